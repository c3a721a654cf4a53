#pragma once
// A tiny measuring program on a plane at z = 5 (three points, one with a
// tilted normal, one move over the clearance plane at z = 12), written by
// hand so the golden files check the writers, not the planner.
#include "io/cmm/probe_program.hpp"
#include "io/plan_file.hpp"
#include "planning/alignment_moves.hpp"

namespace furrow::test {

inline ProbeProgram tiny_program() {
  ProbeProgram p;
  p.name = "tiny";
  p.part = "tiny_plane.json";
  p.probe = {"Probe1", 2};
  p.revision = "C";
  p.date = "2026-03-14";
  p.stylus_length = 20;
  p.head_length = 62.5;  // e.g. 20 mm stylus + probe module and body below the head's centre
  p.move_speed = 50;
  p.measure_speed = 4;
  p.tolerance = PointProfileTolerance{-0.02, 0.03};
  p.approach = 3;
  p.retract = 3;
  p.search = 3;
  auto point = [](const char* id, int order, Eigen::Vector3d xyz, Eigen::Vector3d ijk) {
    PlannedPoint q;
    q.id = id;
    q.order = order;
    q.face = "plane";
    q.region = 0;
    q.xyz = xyz;
    q.ijk = ijk;
    q.approach = xyz + 4 * ijk;  // ball radius 1 + approach 3
    q.retract = q.approach;
    return q;
  };
  p.steps.push_back({point("P0001", 1, {5, 5, 5}, {0, 0, 1}), {{5, 5, 9}}});
  p.steps.push_back({point("P0002", 2, {15, 5, 5}, {0, 0, 1}), {{15, 5, 9}}});
  p.steps.push_back({point("P0003", 3, {10, 15, 5}, {0, 0.6, 0.8}), {{15, 5, 12}, {10, 17.4, 12}, {10, 17.4, 8.2}}});
  p.final_moves = {{10, 17.4, 12}};
  return p;
}

// tiny_program() with an indexable head: the middle point with the tip
// turned (A 52.5, B -172.5), the others with the vertical tip A0B0.
inline ProbeProgram tipped_program() {
  ProbeProgram p = tiny_program();
  p.head_length = 60;
  p.steps[0].point.tip = TipAngles{0, 0};
  p.steps[1].point.tip = TipAngles{52.5, -172.5};
  p.steps[2].point.tip = TipAngles{0, 0};
  p.steps[1].moves_before = {{5, 5, 12}, {15, 5, 12}, {15, 5, 9}};
  p.tips = {{0, 0}, {52.5, -172.5}};
  p.start_tip = TipAngles{0, 0};
  return p;
}

// tiny_program() with `alignment`'s datum moves first, from (5, 5) over a
// clearance plane at `clearance_z`.
inline ProbeProgram tiny_program_with_alignment(const PartAlignment& alignment, double clearance_z) {
  ProbeProgram p = tiny_program();
  add_alignment_moves(p, alignment, clearance_z, {5, 5, clearance_z});
  return p;
}

// A plan holding `alignment` and one free-form point (a copy of a point of
// the first datum under its own id): enough for plan.json round trips.
inline InspectionPlan plan_with_alignment(PartAlignment alignment) {
  InspectionPlan plan;
  plan.probe = {"Probe1", 2};
  plan.alignment = std::move(alignment);
  plan.points.push_back(plan.alignment->datums[0].points[1]);
  plan.points[0].id = "P0001";
  plan.points[0].order = 1;
  return plan;
}

// A DMIS program read back (`back`) holds the alignment `a` it was written
// with: every alignment point in order under its id, to the program's
// 1e-6 mm rounding, with its approach as the last move before it; each
// datum's label, kind, axis and origin axis; the frame's origin.
inline void check_alignment_read_back(const ProbeProgram& back, const PartAlignment& a) {
  REQUIRE(back.alignment.has_value());
  const std::vector<PlannedPoint> want = a.points();
  REQUIRE(back.alignment_steps.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    CHECK(back.alignment_steps[k].point.id == want[k].id);
    CHECK((back.alignment_steps[k].point.xyz - want[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((back.alignment_steps[k].moves_before.back() - want[k].approach).cwiseAbs().maxCoeff() <= 5e-7);
  }
  REQUIRE(back.alignment->datums.size() == a.datums.size());
  for (std::size_t k = 0; k < a.datums.size(); ++k) {
    CHECK(back.alignment->datums[k].label == a.datums[k].label);
    CHECK(back.alignment->datums[k].kind == a.datums[k].kind);
    CHECK(back.alignment->datums[k].axis == a.datums[k].axis);
    CHECK(back.alignment->datums[k].origin_axis == a.datums[k].origin_axis);
  }
  CHECK((back.alignment->origin - a.origin).cwiseAbs().maxCoeff() <= 5e-7);
}

}  // namespace furrow::test
