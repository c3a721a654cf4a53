// Setups (docs/cmm.md "Setups") on a part built with OpenCASCADE, written as
// STEP and imported through the CAD module: a block 40 x 30 x 15 mm with a
// pocket 20 x 10 x 5 mm cut into its underside (open at z = 0), planned
// with the vertical stylus and --setups 2. Known answers:
//   - as imported the probe reaches only the top (1200 mm^2); the underside
//     (the bottom ring, 1200 - 200 mm^2, and the pocket floor, 200 mm^2,
//     both facing down) is reachable only with the part turned over, so
//     setup 2 rests on the top and plans both underside faces, and nothing
//     else (the walls and sides are 90 degrees off the vertical stylus);
//   - the combined covered area is the analytic sum 1200 + 1000 + 200;
//   - every planned point of both setups, taken back to the part frame,
//     lies on the face the analytic block says, and the stylus swept along
//     every move stays clear of the block sampled every 0.25 mm and above
//     the fixture plane (the brute-force sweep of support/setup_clearance.hpp,
//     independent of the planner's sphere tracing).
// And stability on an L-shaped part (analytic centre of mass): its centre
// of mass by the divergence theorem against the analytic value and
// OpenCASCADE's GProp; the end of its foot and the top of its leg are on
// its convex hull but would let it tip over, so they are not candidates and
// are refused by name when named with --setup-faces.
#include <doctest/doctest.h>

#include <BRepBuilderAPI_MakePolygon.hxx>

#include <cmath>
#include <set>

#include "base/error.hpp"
#include "cad_reference.hpp"
#include "geometry/solid_mass.hpp"
#include "io/cad/cad_import.hpp"
#include "partition/partition.hpp"
#include "planning/part_setup.hpp"
#include "planning/plan_coverage.hpp"
#include "stage/plan_stage.hpp"
#include "support/run_cli.hpp"
#include "support/setup_clearance.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kX = 40, kY = 30, kZ = 15;                            // the block
constexpr double kPx0 = 10, kPx1 = 30, kPy0 = 10, kPy1 = 20, kDepth = 5;  // the pocket, from z = 0 up

TopoDS_Shape block_with_underside_pocket() {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(kX, kY, kZ)).Shape();
  // The cutter reaches 1 mm below the block so the pocket opens on the underside.
  const TopoDS_Shape pocket = BRepPrimAPI_MakeBox(gp_Pnt(kPx0, kPy0, -1), gp_Pnt(kPx1, kPy1, kDepth)).Shape();
  return BRepAlgoAPI_Cut(block, pocket).Shape();
}

bool in_pocket(double x, double y) { return x > kPx0 && x < kPx1 && y > kPy0 && y < kPy1; }

// The block's surface every about h mm, from its analytic shape: the outer
// box less the pocket's opening, the pocket's walls and floor.
std::vector<Eigen::Vector3d> block_samples(double h) {
  std::vector<Eigen::Vector3d> s;
  auto n = [h](double length) { return std::max(1, static_cast<int>(std::ceil(length / h))); };
  // A rectangle from a along e1 (length l1) and e2 (length l2).
  auto rect = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& e1, double l1, const Eigen::Vector3d& e2, double l2,
                  bool skip_pocket) {
    const int n1 = n(l1), n2 = n(l2);
    for (int i = 0; i <= n1; ++i)
      for (int j = 0; j <= n2; ++j) {
        const Eigen::Vector3d p = a + e1 * (l1 * i / n1) + e2 * (l2 * j / n2);
        if (skip_pocket && in_pocket(p.x(), p.y())) continue;
        s.push_back(p);
      }
  };
  const Eigen::Vector3d ex = Eigen::Vector3d::UnitX(), ey = Eigen::Vector3d::UnitY(), ez = Eigen::Vector3d::UnitZ();
  rect({0, 0, kZ}, ex, kX, ey, kY, false);  // top
  rect({0, 0, 0}, ex, kX, ey, kY, true);    // bottom ring
  rect({0, 0, 0}, ex, kX, ez, kZ, false);   // front, back
  rect({0, kY, 0}, ex, kX, ez, kZ, false);
  rect({0, 0, 0}, ey, kY, ez, kZ, false);   // left, right
  rect({kX, 0, 0}, ey, kY, ez, kZ, false);
  rect({kPx0, kPy0, kDepth}, ex, kPx1 - kPx0, ey, kPy1 - kPy0, false);  // pocket floor
  rect({kPx0, kPy0, 0}, ex, kPx1 - kPx0, ez, kDepth, false);            // pocket walls
  rect({kPx0, kPy1, 0}, ex, kPx1 - kPx0, ez, kDepth, false);
  rect({kPx0, kPy0, 0}, ey, kPy1 - kPy0, ez, kDepth, false);
  rect({kPx1, kPy0, 0}, ey, kPy1 - kPy0, ez, kDepth, false);
  return s;
}

enum class Where { top, bottom_ring, pocket_floor, elsewhere };
Where where(const Eigen::Vector3d& p) {
  constexpr double tol = 1e-6;
  const bool inside = p.x() > -tol && p.x() < kX + tol && p.y() > -tol && p.y() < kY + tol;
  if (!inside) return Where::elsewhere;
  if (std::abs(p.z() - kZ) < tol) return Where::top;
  if (std::abs(p.z()) < tol && !in_pocket(p.x(), p.y())) return Where::bottom_ring;
  if (std::abs(p.z() - kDepth) < tol && p.x() > kPx0 - tol && p.x() < kPx1 + tol && p.y() > kPy0 - tol &&
      p.y() < kPy1 + tol)
    return Where::pocket_floor;
  return Where::elsewhere;
}

}  // namespace

TEST_CASE("setups on an OpenCASCADE block: the underside with its pocket is planned in setup 2, the stylus clear") {
  silence_occt();
  const std::string path = scratch_dir("cad-setups") + "/pocket_block.step";
  write_step(block_with_underside_pocket(), path);
  const Part part = import_cad(path).part;
  // Cells of 1 mm: every edge of the block and the pocket runs along cell
  // edges, so the partition's region areas (integrated over whole cells) are
  // the faces' exact areas and the covered area can be checked against the
  // analytic sum.
  PartitionOptions po;
  po.spacing = 1.0;
  const RegionMap map = partition_part(part, po).map;
  PlannerOptions o;
  o.points = 60;
  o.min_per_region = 4;
  o.setups = 2;
  const PlanStage stage = plan_stage(part, map, o, nullptr, "pocket_block", "regions.json", "");
  REQUIRE(stage.setups.size() == 2);

  // Setup 2 rests on the top: the face whose outward normal is +z at z = 15.
  REQUIRE(stage.setups[1].setup.resting_face);
  const std::optional<RestingFace> rest = planar_face(part, map, *stage.setups[1].setup.resting_face);
  REQUIRE(rest);
  CHECK((rest->normal - Eigen::Vector3d::UnitZ()).norm() < 1e-9);
  CHECK(std::abs(rest->point.z() - kZ) < 1e-6);

  // Every point on the face the analytic block says: setup 1 the top, setup
  // 2 the bottom ring and the pocket floor, each of those at its minimum.
  int count[2][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}};
  for (int k = 0; k < 2; ++k) {
    const SetupPlan& s = stage.setups[static_cast<std::size_t>(k)];
    REQUIRE(s.result.plan.setup);
    for (const PlannedPoint& p : s.result.plan.points) {
      const Eigen::Vector3d x = s.result.plan.setup->to_part(p.xyz);
      CAPTURE(p.id);
      CAPTURE(x);
      ++count[k][static_cast<int>(where(x))];
    }
  }
  CHECK(count[0][static_cast<int>(Where::top)] >= o.min_per_region);
  CHECK(count[0][static_cast<int>(Where::top)] == static_cast<int>(stage.setups[0].result.plan.points.size()));
  CHECK(count[1][static_cast<int>(Where::bottom_ring)] >= o.min_per_region);
  CHECK(count[1][static_cast<int>(Where::pocket_floor)] >= o.min_per_region);
  CHECK(count[1][static_cast<int>(Where::top)] == 0);
  CHECK(count[1][static_cast<int>(Where::elsewhere)] == 0);

  // Combined: top + bottom ring + pocket floor, each counted once.
  const double want = kX * kY + (kX * kY - (kPx1 - kPx0) * (kPy1 - kPy0)) + (kPx1 - kPx0) * (kPy1 - kPy0);
  MESSAGE("covered " << stage.coverage.area.covered << " mm^2 of " << stage.coverage.area.total << ", analytic "
                     << want);
  CHECK(std::abs(stage.coverage.area.covered - want) < 1e-6 * want);
  const double total = 2 * (kX * kY + kX * kZ + kY * kZ) + 2 * kDepth * ((kPx1 - kPx0) + (kPy1 - kPy0));
  CHECK(std::abs(stage.coverage.area.total - total) < 1e-6 * total);
  for (const RegionCoverage& r : stage.coverage.regions) {
    if (!r.covered) continue;
    const std::optional<RestingFace> f = planar_face(part, map, r.face);
    REQUIRE(f);
    CAPTURE(r.face);
    // Covered in setup 1 exactly when the face looks up as imported.
    CHECK(r.setup == (f->normal.z() > 0.5 ? 1 : 2));
  }

  // Brute force in each setup's frame: clear of the block, above the fixture plane.
  const std::vector<Eigen::Vector3d> samples = block_samples(0.25);
  for (const SetupPlan& s : stage.setups) {
    CAPTURE(s.setup.index);
    const SetupClearance c = vertical_stylus_clearance(s, o, samples);
    CHECK(c.part >= -(0.25 * 0.25 / 2 + 1e-6));  // a sample grid of 0.25 mm misses at most its half-diagonal's sag
    CHECK(c.lowest >= -1e-9);
    MESSAGE("setup " << s.setup.index << ": " << s.result.plan.points.size() << " points, smallest sampled clearance "
                     << c.part << " mm, lowest ball point z = " << c.lowest << " mm");
  }
}

namespace {

// An L-shaped part: the profile in (x, z) - a foot 60 x 10 along x and a leg
// 10 x 50 standing on its left end - extruded 20 mm along y. Its centre of
// mass, from the two rectangles (areas 600 and 500, centres (30, 5) and
// (5, 35)): x = z = (600 * 30 + 500 * 5) / 1100 = 18.6364, y = 10; volume
// 1100 x 20 mm^3.
constexpr double kLFoot = 60, kLThick = 10, kLHeight = 60, kLWidth = 20;
const double kLCentre = (600.0 * 30 + 500.0 * 5) / 1100;

TopoDS_Shape l_part() {
  BRepBuilderAPI_MakePolygon profile;
  for (const auto& [x, z] : std::vector<std::pair<double, double>>{
           {0, 0}, {kLFoot, 0}, {kLFoot, kLThick}, {kLThick, kLThick}, {kLThick, kLHeight}, {0, kLHeight}})
    profile.Add(gp_Pnt(x, 0, z));
  profile.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire(), true).Face();
  return BRepPrimAPI_MakePrism(face, gp_Vec(0, kLWidth, 0)).Shape();
}

// The planar face of the imported part with that outward normal through that point.
int face_at(const Part& part, const RegionMap& map, const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const std::optional<RestingFace> r = planar_face(part, map, static_cast<int>(f));
    if (r && (r->normal - normal).norm() < 1e-9 && std::abs(normal.dot(r->point - point)) < 1e-6)
      return static_cast<int>(f);
  }
  return -1;
}

}  // namespace

TEST_CASE("stability: the L part's centre of mass by the divergence theorem, analytic and as OpenCASCADE's GProp") {
  silence_occt();
  const std::string path = scratch_dir("cad-l-part") + "/l_part.step";
  const TopoDS_Shape shape = l_part();
  write_step(shape, path);
  const Part part = import_cad(path).part;
  const SolidMass m = solid_mass(part);
  CHECK(m.closed);
  const double volume = 1100 * kLWidth;
  CHECK(std::abs(m.volume - volume) < 1e-6 * volume);
  CHECK((m.centroid - Eigen::Vector3d(kLCentre, kLWidth / 2, kLCentre)).norm() < 1e-6);
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  CHECK((m.centroid - eig(props.CentreOfMass())).norm() < 1e-6);
  // A face missing: an open shell has no centre of mass.
  Part open = part;
  open.faces.pop_back();
  CHECK(!solid_mass(open).closed);
}

TEST_CASE("stability: the L part's small foot end and leg top cannot carry it, refused by name with the overhang") {
  silence_occt();
  const std::string path = scratch_dir("cad-l-part-rest") + "/l_part.step";
  write_step(l_part(), path);
  const Part part = import_cad(path).part;
  PartitionOptions po;
  po.grid = GridSize{30, 30};
  const RegionMap map = partition_part(part, po).map;
  const int bottom = face_at(part, map, -Eigen::Vector3d::UnitZ(), {0, 0, 0});
  const int left = face_at(part, map, -Eigen::Vector3d::UnitX(), {0, 0, 0});
  const int front = face_at(part, map, -Eigen::Vector3d::UnitY(), {0, 0, 0});
  const int foot_end = face_at(part, map, Eigen::Vector3d::UnitX(), {kLFoot, 0, 0});
  const int leg_top = face_at(part, map, Eigen::Vector3d::UnitZ(), {0, 0, kLHeight});
  const int inner = face_at(part, map, Eigen::Vector3d::UnitZ(), {0, 0, kLThick});
  for (int f : {bottom, left, front, foot_end, leg_top, inner}) REQUIRE(f >= 0);
  // The margin is the distance from the centre's projection to the nearest
  // edge of the support rectangle (or the L's hull), analytic.
  struct Want {
    int face;
    bool on_hull;
    double margin;
  };
  const Want wants[] = {
      {bottom, true, kLWidth / 2},          // [0, 60] x [0, 20]: the y edges are nearest
      {left, true, kLWidth / 2},            // [0, 20] x [0, 60] in (y, z)
      {front, true, kLCentre},              // the L's hull: x = 0 and z = 0 at 18.64 (the slant at 23.1)
      {foot_end, true, kLThick - kLCentre}, // z in [0, 10]: the centre 8.64 mm above it
      {leg_top, true, kLThick - kLCentre},  // x in [0, 10]
  };
  for (const Want& w : wants) {
    CAPTURE(w.face);
    const std::optional<RestingFace> r = planar_face(part, map, w.face);
    REQUIRE(r);
    CHECK(r->on_hull == w.on_hull);
    CHECK(std::abs(r->balance_margin - w.margin) < 1e-4);
    CHECK(r->stable == (w.margin >= 0));
  }
  const std::optional<RestingFace> in = planar_face(part, map, inner);
  REQUIRE(in);
  CHECK(!in->on_hull);
  CHECK(!in->stable);
  // The candidates for a setup: neither the foot's end nor the leg's top.
  for (const RestingFace& c : resting_candidates(part, map)) {
    CHECK(c.face != foot_end);
    CHECK(c.face != leg_top);
    CHECK(c.stable);
  }
  const std::string refused = "cannot rest on face " + std::to_string(foot_end);
  const std::string refused_by_stage = "--setup-faces: the part " + refused;
  CHECK_THROWS_WITH_AS(named_resting_face(part, map, foot_end, "--setup-faces"),
                       doctest::Contains(refused.c_str()), InputError);
  CHECK_THROWS_WITH_AS(named_resting_face(part, map, foot_end, "--setup-faces"),
                       doctest::Contains("it would tip over, its centre of mass lies 8.636 mm outside"), InputError);
  CHECK_NOTHROW(named_resting_face(part, map, bottom, "--setup-faces"));
  // Through the plan stage: a named unstable face is refused before anything is planned.
  PlannerOptions o;
  o.points = 30;
  o.setup_faces = {foot_end};
  CHECK_THROWS_WITH_AS(plan_stage(part, map, o, nullptr, "l_part", "regions.json", ""),
                       doctest::Contains(refused_by_stage.c_str()), InputError);
}
