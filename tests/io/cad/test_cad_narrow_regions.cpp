// Narrow regions under the ball-contact rule (docs/cmm.md "Narrow regions"),
// on parts built with OpenCASCADE and imported from STEP:
// - a stepped block with fillets of 1, 2 (concave) and 3 mm along x, all
//   narrower than twice the default border clearance: every fillet gets its
//   points, and every contact is checked against the block's analytic cross
//   section (independent of the planner's closest-point search): the closest
//   point of the section from the ball centre is the planned point, on its
//   fillet's arc, nothing else within the ball's radius, and it stays on the
//   arc with the centre 0.25 mm off either way;
// - a slot 1.6 mm wide: its floor is too narrow for a 2 mm ball and is
//   reported with the largest ball that measures it, w - 2·shift.
#include <doctest/doctest.h>

#include <BRepFilletAPI_MakeFillet.hxx>
#include <TopExp_Explorer.hxx>
#include <BRepAdaptor_Curve.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "cad_reference.hpp"
#include "io/cad/cad_import.hpp"
#include "partition/partition.hpp"
#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kLength = 60;  // along x
constexpr double kHalfPi = 1.57079632679489661923;

// The stepped block's cross section in (y, z): upper level z = 20 for
// y in [0, 20], lower level z = 10 for y in [20, 40]. Fillets: convex 1 mm
// on the edge (y 0, z 20), convex 3 mm on (20, 20), concave 2 mm on (20, 10).
struct Arc {
  Eigen::Vector2d centre;
  double radius;
  double from, to;  // polar angle range around the centre [rad], from < to
  const char* name;
};
struct Segment {
  Eigen::Vector2d a, b;
};
const Arc kArcs[] = {{{1, 19}, 1, kHalfPi, 2 * kHalfPi, "fillet R1"},
                     {{17, 17}, 3, 0, kHalfPi, "fillet R3"},
                     {{22, 12}, 2, 2 * kHalfPi, 3 * kHalfPi, "fillet R2 (concave)"}};
const Segment kSegments[] = {{{0, 0}, {40, 0}},   {{40, 0}, {40, 10}},  {{40, 10}, {22, 10}}, {{20, 12}, {20, 17}},
                             {{17, 20}, {1, 20}}, {{0, 19}, {0, 0}}};

TopoDS_Shape filleted_step_block() {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(kLength, 40, 20)).Shape();
  block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeBox(gp_Pnt(-1, 20, 10), gp_Pnt(kLength + 1, 41, 21)).Shape()).Shape();
  BRepFilletAPI_MakeFillet fillet(block);
  for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    const BRepAdaptor_Curve c(edge);
    const gp_Pnt a = c.Value(c.FirstParameter()), b = c.Value(c.LastParameter());
    if (std::abs(a.Y() - b.Y()) > 1e-9 || std::abs(a.Z() - b.Z()) > 1e-9) continue;  // not along x
    const Eigen::Vector2d yz(a.Y(), a.Z());
    if ((yz - Eigen::Vector2d(0, 20)).norm() < 1e-9) fillet.Add(1.0, edge);
    if ((yz - Eigen::Vector2d(20, 20)).norm() < 1e-9) fillet.Add(3.0, edge);
    if ((yz - Eigen::Vector2d(20, 10)).norm() < 1e-9) fillet.Add(2.0, edge);
  }
  return fillet.Shape();
}

// Closest point of the cross section's boundary from q: which element
// (arcs 0..2, segments 3..) and the point.
struct SectionFoot {
  int element = -1;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double distance = std::numeric_limits<double>::infinity();
  double angle = 0;  // on an arc
};
SectionFoot section_foot(const Eigen::Vector2d& q) {
  SectionFoot best;
  for (int k = 0; k < 3; ++k) {
    const Arc& arc = kArcs[k];
    const Eigen::Vector2d d = q - arc.centre;
    double t = std::atan2(d.y(), d.x());
    while (t < arc.from) t += 4 * kHalfPi;  // now in [from, from + 2 pi)
    const Eigen::Vector2d at_from = arc.centre + arc.radius * Eigen::Vector2d(std::cos(arc.from), std::sin(arc.from));
    const Eigen::Vector2d at_to = arc.centre + arc.radius * Eigen::Vector2d(std::cos(arc.to), std::sin(arc.to));
    const double clamped = t <= arc.to ? t : ((q - at_from).norm() < (q - at_to).norm() ? arc.from : arc.to);
    const Eigen::Vector2d p = arc.centre + arc.radius * Eigen::Vector2d(std::cos(clamped), std::sin(clamped));
    if ((q - p).norm() < best.distance) best = {k, p, (q - p).norm(), clamped};
  }
  for (int k = 0; k < 6; ++k) {
    const Segment& s = kSegments[k];
    const double t = std::clamp((q - s.a).dot(s.b - s.a) / (s.b - s.a).squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d p = s.a + t * (s.b - s.a);
    if ((q - p).norm() < best.distance) best = {3 + k, p, (q - p).norm(), 0};
  }
  return best;
}

// Distance from q to every element but `skip`.
double distance_to_others(const Eigen::Vector2d& q, int skip) {
  double d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (k == skip) continue;
    const Arc& arc = kArcs[k];
    for (int s = 0; s <= 2000; ++s) {
      const double t = arc.from + (arc.to - arc.from) * s / 2000;
      d = std::min(d, (q - arc.centre - arc.radius * Eigen::Vector2d(std::cos(t), std::sin(t))).norm());
    }
  }
  for (int k = 0; k < 6; ++k) {
    const Segment& s = kSegments[k];
    const double t = std::clamp((q - s.a).dot(s.b - s.a) / (s.b - s.a).squaredNorm(), 0.0, 1.0);
    d = std::min(d, (q - s.a - t * (s.b - s.a)).norm());
  }
  return d;
}

TopoDS_Shape slot_block(double w) {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(40, 30, 10)).Shape();
  return BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeBox(gp_Pnt(-1, 15 - w / 2, 5), gp_Pnt(41, 15 + w / 2, 11)).Shape())
      .Shape();
}

RegionMap partition(const Part& part) {
  PartitionOptions po;
  po.grid = GridSize{60, 60};
  return partition_part(part, po).map;
}

}  // namespace

TEST_CASE("fillets of 1 to 3 mm get their points, each contact on its fillet by the analytic cross section") {
  silence_occt();
  const std::string path = scratch_dir("narrow-fillets") + "/block.step";
  write_step(filleted_step_block(), path);
  const Part part = import_cad(path).part;
  const RegionMap map = partition(part);
  PlannerOptions o;
  o.points = 150;
  o.min_per_region = 4;
  const PlanResult r = plan_probe_points(part, map, o);
  const double radius = o.probe_diameter / 2, shift = o.contact.shift;
  REQUIRE(border_clearance(o) == doctest::Approx(2.0));

  int on_arc[3] = {0, 0, 0};
  for (const PlannedPoint& p : r.plan.points) {
    CAPTURE(p.id);
    CAPTURE(p.xyz);
    const Eigen::Vector2d c(p.xyz.y() + radius * p.ijk.y(), p.xyz.z() + radius * p.ijk.z());
    const SectionFoot foot = section_foot(c);
    // The oracle's contact is the planned point ...
    CHECK((foot.point - Eigen::Vector2d(p.xyz.y(), p.xyz.z())).norm() < 1e-3);
    CHECK(foot.distance == doctest::Approx(radius).epsilon(1e-6));
    if (foot.element >= 3) continue;
    // ... and on a fillet: the ball touches nothing else, and with its
    // centre off by the shift along the section's tangent the contact stays
    // strictly inside the same arc.
    const int k = foot.element;
    CAPTURE(kArcs[k].name);
    ++on_arc[k];
    CHECK(foot.angle > kArcs[k].from + 1e-9);
    CHECK(foot.angle < kArcs[k].to - 1e-9);
    CHECK(distance_to_others(c, k) > radius);
    const Eigen::Vector2d t(-std::sin(foot.angle), std::cos(foot.angle));
    for (double sign : {-1.0, 1.0}) {
      const SectionFoot moved = section_foot(c + sign * shift * t);
      CHECK(moved.element == k);
      CHECK(moved.angle > kArcs[k].from);
      CHECK(moved.angle < kArcs[k].to);
    }
  }
  // Every fillet gets the minimum of its region (each fillet face is one
  // region: a cylinder has one curvature class).
  for (int k = 0; k < 3; ++k) {
    CAPTURE(kArcs[k].name);
    CHECK(on_arc[k] >= o.min_per_region);
  }
  // The 1 and 2 mm fillets hold no point 2 mm from their edges: they are
  // planned by the contact rule (the 3 mm one keeps a band at 2 mm).
  for (const PlannedPoint& p : r.plan.points) {
    const Eigen::Vector2d c(p.xyz.y() + radius * p.ijk.y(), p.xyz.z() + radius * p.ijk.z());
    const int k = section_foot(c).element;
    REQUIRE(p.region);
    if (k == 0 || k == 2) CHECK(r.regions[static_cast<std::size_t>(*p.region)].contact_rule);
  }
  for (const PlanIssue& i : r.issues) CHECK(i.kind != PlanIssue::Kind::region_skipped);
}

TEST_CASE("a slot floor too narrow for the ball is reported with the largest ball that fits, w - 2 shift") {
  silence_occt();
  // A block with a slot 1.6 mm wide and 5 mm deep along x. With the ball's
  // centre r' above the middle of the floor and off by the shift s
  // sideways, the floor stays the closest part while r' < w/2 - s: the
  // largest ball that measures the floor is w - 2s across.
  constexpr double w = 1.6;
  const std::string path = scratch_dir("narrow-slot") + "/slot.step";
  write_step(slot_block(w), path);
  const Part part = import_cad(path).part;
  const RegionMap map = partition(part);
  PlannerOptions o;
  o.points = 60;
  o.min_per_region = 3;
  const PlanResult r = plan_probe_points(part, map, o);
  const double expected = w - 2 * o.contact.shift;
  int reported = 0;
  for (const PlanIssue& i : r.issues) {
    if (i.kind != PlanIssue::Kind::region_skipped) continue;
    const Region& region = map.regions[static_cast<std::size_t>(i.region)];
    const Face& face = part.faces[static_cast<std::size_t>(region.face)];
    const ParameterDomain& d = face.domain();
    const DifferentialGeometry g = face.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2);
    if (!(g.normal.z() > 0.99 && std::abs(g.point.z() - 5) < 1e-9)) continue;  // the slot's floor
    ++reported;
    CAPTURE(i.reason);
    CHECK(i.largest_ball_diameter <= expected + 1e-6);
    CHECK(i.largest_ball_diameter >= expected - 0.02);
    CHECK(i.reason.find("largest ball that would") != std::string::npos);
  }
  CHECK(reported == 1);
  // A ball that small does measure it.
  PlannerOptions small = o;
  small.probe_diameter = expected - 0.05;
  small.stylus_diameter = 0.5;
  const PlanResult s = plan_probe_points(part, map, small);
  int on_floor = 0;
  for (const PlannedPoint& p : s.plan.points) on_floor += std::abs(p.xyz.z() - 5) < 1e-9 && std::abs(p.xyz.y() - 15) < w / 2;
  CHECK(on_floor >= small.min_per_region);
}

TEST_CASE("furrow plan --contact-shift sets the margin: the slot floor's largest ball in report.json is w - 2 shift") {
  silence_occt();
  constexpr double w = 1.6, shift = 0.1;
  const std::string dir = scratch_dir("narrow-slot-cli");
  write_step(slot_block(w), dir + "/slot.step");
  REQUIRE(run_furrow({"partition", dir + "/slot.step", "--out", dir + "/regions.json"}).status == 0);
  const CliResult r = run_furrow({"plan", dir + "/slot.step", "--regions", dir + "/regions.json", "--out", dir + "/plan",
                                  "--contact-shift", "0.1", "--allow-uncovered"});
  REQUIRE(r.status == 0);
  const auto report = nlohmann::json::parse(slurp(dir + "/plan/report.json"));
  CHECK(report["options"]["contact_shift_mm"].get<double>() == shift);
  int reported = 0;
  for (const auto& issue : report["issues"])
    if (issue["kind"] == "region_skipped" && issue.contains("largest_ball_diameter_mm")) {
      ++reported;
      const double d = issue["largest_ball_diameter_mm"].get<double>();
      CHECK(d <= w - 2 * shift + 1e-6);
      CHECK(d >= w - 2 * shift - 0.02);
    }
  CHECK(reported == 1);
  const CliResult bad = run_furrow({"plan", dir + "/slot.step", "--regions", dir + "/regions.json", "--out",
                                    dir + "/bad", "--contact-shift", "-1"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--contact-shift") != std::string::npos);
}
