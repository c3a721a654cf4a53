#pragma once
// A tiny measuring program on a plane at z = 5 (three points, one with a
// tilted normal, one move over the clearance plane at z = 12), written by
// hand so the golden files check the writers, not the planner.
#include "io/cmm/probe_program.hpp"

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

}  // namespace furrow::test
