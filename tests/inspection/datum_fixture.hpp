#pragma once
// A part with three datum planes under a free-form face, its plan with a
// 3-2-1 datum alignment, and its measurement on the CMM at a known
// placement: the fixture of the datum-frame tests (test_datum_frame.cpp,
// test_datum_bore.cpp).
#include <cmath>
#include <string>

#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/plan_file.hpp"
#include "stage/compare_stage.hpp"

namespace furrow::test {


// Three datum planes and a free-form (twisted bilinear) face above them:
// A the top z = 0 (+z), B the wall y = 0 (-y), C the wall x = 0 (-x).
inline Part datum_part() {
  Part part;
  part.faces.emplace_back("A", make_plane({0, 0, 0}, {100, 0, 0}, {0, 60, 0}));
  part.faces.emplace_back("B", make_plane({0, 0, -30}, {100, 0, 0}, {0, 0, 30}));
  part.faces.emplace_back("C", make_plane({0, 0, -30}, {0, 0, 30}, {0, 60, 0}));
  part.faces.emplace_back("F", make_bilinear({10, 10, 20}, {90, 10, 26}, {10, 50, 29}, {90, 50, 17}));
  return part;
}

// A datum point on plane face A, B or C with its (u, v) on that face (the
// make_plane parameters above) and its index, as plan.json holds it.
inline PlannedPoint planned(const std::string& id, const Eigen::Vector3d& xyz, const Eigen::Vector3d& ijk,
                     const std::string& face) {
  PlannedPoint p;
  p.id = id;
  p.xyz = xyz;
  p.ijk = ijk;
  p.face = face;
  p.face_index = face == "A" ? 0 : face == "B" ? 1 : face == "C" ? 2 : 3;
  if (face == "A") p.uv = {xyz.x() / 100, xyz.y() / 60};
  if (face == "B") p.uv = {xyz.x() / 100, (xyz.z() + 30) / 30};
  if (face == "C") p.uv = {(xyz.z() + 30) / 30, xyz.y() / 60};
  p.approach = p.retract = xyz + 5 * ijk;
  return p;
}

// A plan: 7 x 5 points on F and the 3-2-1 alignment A (4 points), B (2), C (1).
inline InspectionPlan datum_plan(const Part& part) {
  InspectionPlan plan;
  plan.probe = {"ball", 2};
  const Face& f = part.faces[3];
  const ParameterDomain& d = f.domain();
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = d.u0 + (i + 0.5) / 7 * d.width_u(), v = d.v0 + (j + 0.5) / 5 * d.width_v();
      const DifferentialGeometry g = f.geometry(u, v);
      PlannedPoint p = planned("F" + std::to_string(i * 5 + j), g.point, g.normal, "F");
      p.uv = {u, v};
      p.order = i * 5 + j + 1;
      plan.points.push_back(p);
    }
  PartAlignment a;
  a.method = PartAlignment::Method::datums;
  DatumFeature da;
  da.label = "A";
  da.kind = DatumFeature::Kind::plane;
  da.origin = {0, 0, 0};
  da.normal = {0, 0, 1};
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(5, 5, 0), Eigen::Vector3d(95, 5, 0), Eigen::Vector3d(95, 55, 0),
                                   Eigen::Vector3d(5, 55, 0)})
    da.points.push_back(planned("A" + std::to_string(da.points.size() + 1), x, da.normal, "A"));
  DatumFeature db;
  db.label = "B";
  db.kind = DatumFeature::Kind::line;
  db.origin = {20, 0, -15};
  db.direction = {1, 0, 0};
  db.normal = {0, -1, 0};
  db.points = {planned("B1", {20, 0, -15}, db.normal, "B"), planned("B2", {80, 0, -15}, db.normal, "B")};
  DatumFeature dc;
  dc.label = "C";
  dc.kind = DatumFeature::Kind::point;
  dc.origin = {0, 30, -15};
  dc.normal = {-1, 0, 0};
  dc.points = {planned("C1", dc.origin, dc.normal, "C")};
  da.face = "A", db.face = "B", dc.face = "C";
  da.face_index = 0, db.face_index = 1, dc.face_index = 2;
  da.axis = 'Z', da.origin_axis = 'Z', db.axis = 'X', db.origin_axis = 'Y', dc.axis = 0, dc.origin_axis = 'X';
  a.datums = {da, db, dc};
  int order = 0;
  for (DatumFeature& f : a.datums)
    for (PlannedPoint& p : f.points) p.order = ++order;
  plan.alignment = a;
  return plan;
}

// Probe-ball centres of every plan and datum point on the CMM: part_to_cmm
// (xyz + (offset + r) n), offset(id, point, normal) along the normal.
template <class Offset>
inline MeasurementSet measure(const InspectionPlan& plan, const Eigen::Isometry3d& part_to_cmm, double r, Offset offset) {
  MeasurementSet set;
  set.source = "simulated";
  set.kind = ProbePointKind::probe_centre;
  set.probe_radius = r;
  set.ids_from_file = true;
  auto add = [&](const PlannedPoint& p) {
    MeasuredPoint m;
    m.id = p.id;
    m.xyz = part_to_cmm * (p.xyz + (offset(p) + r) * p.ijk);
    set.points.push_back(m);
  };
  for (const DatumFeature& f : plan.alignment->datums)
    for (const PlannedPoint& p : f.points) add(p);
  for (const PlannedPoint& p : plan.points) add(p);
  return set;
}

inline Eigen::Isometry3d placement() {
  Misalignment m;
  m.rotation_deg = {2.5, -1.5, 17};
  m.translation = {312.5, -48.25, 101.75};
  return m.part_to_cmm();
}

// Form error of a smooth surface deviation, in mm (+ material left).
inline double form(const PlannedPoint& p) { return 0.01 * std::sin(p.xyz.x() / 13) * std::cos(p.xyz.y() / 7); }

inline Comparison run(const Part& part, const InspectionPlan& plan, const MeasurementSet& measured, AlignMethod align,
               MeasurementSet* compared_out = nullptr) {
  CompareOptions options;
  options.align = align;
  options.tolerance = ToleranceZone::make(0.05, 0.025, "test");
  scale_registration_to_tolerance(options);
  const MeasurementSet compared = prepare_alignment(options, measured, &plan, "plan.json");
  if (compared_out) *compared_out = compared;
  return compare_stage(part, compared, &plan, nullptr, nullptr, options);
}


}  // namespace furrow::test
