// Setups (docs/cmm.md "Setups") on a box whose six faces are planes with
// outward normals, 40 x 30 x 10 mm, planned with the vertical stylus
// (--max-tilt 75): as imported only the top (40 x 30) faces the stylus; the
// bottom faces only down and the four sides are 90 degrees off vertical.
// Known answers:
//   --setups 2: setup 2 rests on the top (the turn that brings most short
//     area up is the one that brings the bottom up: 1200 mm^2 against 400
//     or 300 for a side), plans only the bottom, and the combined covered
//     area is top + bottom = 2400 mm^2;
//   --setups 3: setup 3 rests on the front (y = 0, the first of the two
//     400 mm^2 sides) and measures the back: 2800 mm^2;
//   every planned point of every setup is clear of the part and of the
//     fixture plane by a brute-force sweep of the ball and shaft along the
//     touch and both vertical legs against dense samples of the box taken
//     to the setup frame with plan.json's own transform (independent of
//     the planner's sphere tracing); each point taken back to the part
//     frame lies on its face (check_plan_against_part);
//   a face that is not planar or cannot carry the part is refused by name.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "base/error.hpp"
#include "io/cmm/nist_checker.hpp"
#include "io/cmm/probe_head.hpp"
#include "io/plan_file.hpp"
#include "plan_fixtures.hpp"
#include "planning/part_setup.hpp"
#include "planning/plan_coverage.hpp"
#include "stage/plan_stage.hpp"
#include "support/capsule_oracle.hpp"
#include "support/setup_clearance.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kX = 40, kY = 30, kZ = 10;

Part box_part() { return test::box_part(kX, kY, kZ); }

// Every face of the box every h mm, in the part frame.
std::vector<Eigen::Vector3d> box_samples(double h) {
  std::vector<Eigen::Vector3d> s;
  const int nx = static_cast<int>(std::ceil(kX / h)), ny = static_cast<int>(std::ceil(kY / h)),
            nz = static_cast<int>(std::ceil(kZ / h));
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      s.emplace_back(kX * i / nx, kY * j / ny, 0);
      s.emplace_back(kX * i / nx, kY * j / ny, kZ);
    }
  for (int k = 0; k <= nz; ++k) {
    for (int i = 0; i <= nx; ++i) {
      s.emplace_back(kX * i / nx, 0, kZ * k / nz);
      s.emplace_back(kX * i / nx, kY, kZ * k / nz);
    }
    for (int j = 0; j <= ny; ++j) {
      s.emplace_back(0, kY * j / ny, kZ * k / nz);
      s.emplace_back(kX, kY * j / ny, kZ * k / nz);
    }
  }
  return s;
}

struct Fixture {
  Part part = box_part();
  RegionMap map = partition_of(part, 24, 24);
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

PlannerOptions box_options(int setups) {
  PlannerOptions o;
  o.points = 60;
  o.min_per_region = 4;
  o.setups = setups;
  return o;
}

double face_area(int face) {
  const double areas[] = {kX * kY, kX * kY, kX * kZ, kX * kZ, kY * kZ, kY * kZ};
  return areas[face];
}

// The vertical stylus's clearance over every point of a setup, against the
// box sampled every 0.25 mm (support/setup_clearance.hpp).
SetupClearance brute_clearance(const SetupPlan& s, const PlannerOptions& o) {
  return vertical_stylus_clearance(s, o, box_samples(0.25));
}

// The indexable head of test_auto_tips.cpp, nothing qualified, and the
// same numbers for the oracle.
const char* kHead = R"({
  "head": {"type": "test", "a": {"min": 0, "max": 90, "step": 45}, "b": {"min": -90, "max": 180, "step": 90},
           "length": 30, "diameter": 24},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": []
})";
const OracleHead kOracleHead{1, 0.5, 20, 25, 6.6, 30, 12};

// With the head: the assembly of each point's tip (the oracle's capsules)
// along the touch and both vertical legs, against the box samples in the
// setup frame; and the lowest point any capsule reaches over those moves.
SetupClearance brute_head_clearance(const SetupPlan& s) {
  REQUIRE(s.result.plan.setup);
  const PlanSetupRecord& rec = *s.result.plan.setup;
  std::vector<Eigen::Vector3d> samples = box_samples(0.25);
  for (Eigen::Vector3d& q : samples) q = rec.rotation * q + rec.translation;
  SetupClearance c;
  for (const PlannedPoint& p : s.result.plan.points) {
    REQUIRE(p.tip);
    const std::vector<OracleCapsule> all = oracle_capsules(kOracleHead, p.tip->a, p.tip->b);
    const std::vector<OracleCapsule> rest(all.begin() + 1, all.end());
    const Eigen::Vector3d centre = p.xyz + p.ijk;
    const Eigen::Vector3d out = p.xyz + (1 + std::max(s.result.approach, s.result.retract)) * p.ijk;
    c.part = std::min(c.part, swept_clearance(samples, rest, centre, out));
    for (const Eigen::Vector3d& q : {p.approach, p.retract}) {
      const Eigen::Vector3d top(q.x(), q.y(), std::max(q.z(), s.result.clearance_z));
      c.part = std::min(c.part, swept_clearance(samples, all, q, top));
    }
    // The motions are straight and the legs rise: the lowest points are at
    // the contact, approach and retract positions.
    for (const Eigen::Vector3d& at : {centre, p.approach, p.retract})
      for (const OracleCapsule& k : all) c.lowest = std::min({c.lowest, (at + k.a).z() - k.radius, (at + k.b).z() - k.radius});
  }
  return c;
}

}  // namespace

TEST_CASE("setups with an indexable head: every point of both setups clear of the part and above the fixture plane") {
  const Fixture& f = fixture();
  PlannerOptions o;
  use_head(o, parse_probe_head(kHead, "head.json"));
  o.tips = TipChoice::automatic;
  // Sides only within 20 degrees of a tip's axis: A90, whose probe body
  // (radius 6.6 mm) lies level with the ball, so a side point below 6.6 mm
  // above the fixture plane is out of reach (the fixture check bites).
  o.max_tilt_degrees = 20;
  o.points = 60;
  o.min_per_region = 4;
  o.setups = 2;
  const PlanStage stage = plan_stage(f.part, f.map, o, nullptr, "box", "regions.json", "");
  REQUIRE(stage.setups.size() == 2);
  // Setup 1 measures the top only: a side point needs A90 and 6.6 mm above
  // the table, and the 2 mm border leaves a band of 1.4 mm below the top.
  for (const PlannedPoint& p : stage.setups[0].result.plan.points) CHECK(p.face_index == 0);
  // The estimate per resting face, by the sides' interior points at
  // mid-height: on the top only the bottom comes up (1200; the sides are
  // 10 mm high, their middle 5 mm < 6.6 mm up); on the front (or back) the
  // back (400) faces up and the bottom and both ends stand 30 mm high
  // (1200 + 2 x 300): 2200; on the left (or right) the right (300) faces up
  // and bottom, front and back stand 40 mm high (1200 + 2 x 400): 2300,
  // the most; the left comes first of the two.
  REQUIRE(stage.setups[1].setup.resting_face);
  CHECK(*stage.setups[1].setup.resting_face == 4);
  CHECK(std::abs(stage.setups[1].estimated_area - 2300) < 1e-6 * 2300);
  double covered_faces = 0;
  for (const RegionCoverage& r : stage.coverage.regions) {
    CAPTURE(r.region);
    CAPTURE(r.reason);
    if (r.face == 0) CHECK(r.setup == 1);
    if (r.face == 1 || r.face == 5) {
      CHECK(r.covered);
      CHECK(r.setup == 2);
    }
    if (r.face == 4) CHECK(!r.covered);  // it carries the part in setup 2
    if (r.covered) covered_faces += face_area(r.face);
  }
  // One planar region per face: the covered area is the sum of the covered faces' areas.
  CHECK(stage.coverage.regions.size() == 6);
  CHECK(std::abs(stage.coverage.area.covered - covered_faces) < 1e-6 * covered_faces);
  CHECK(covered_faces >= face_area(0) + face_area(1));
  for (const SetupPlan& s : stage.setups) {
    CAPTURE(s.setup.index);
    const SetupClearance c = brute_head_clearance(s);
    const double h = 0.25;
    CHECK(c.part >= -(h * h / 2 + 1e-6));
    // Setup 1 stands on the box's lowest point (z = 0), setup 2 on its top, moved to z = 0.
    CHECK(c.lowest >= -1e-9);
    // Its program, with a tool per tip, passes NIST's I++ DME checker.
    const std::string prg = s.folder + "/box_S" + std::to_string(s.setup.index) + ".prg";
    const auto file = std::find_if(stage.files.begin(), stage.files.end(), [&](const FolderFile& x) { return x.path == prg; });
    REQUIRE(file != stage.files.end());
    CHECK(nist_checker_findings(file->bytes, "setups_head_" + std::to_string(s.setup.index) + ".prg").empty());
    MESSAGE("head, setup " << s.setup.index << ": " << s.result.plan.points.size() << " points, "
                           << s.result.plan.tips.size() << " tips, smallest sampled clearance " << c.part
                           << " mm, lowest point of the assembly z = " << c.lowest << " mm");
  }
}

TEST_CASE("setups: the bottom, reachable only from below, is planned in setup 2 resting on the top") {
  const Fixture& f = fixture();
  const PlannerOptions o = box_options(2);
  const PlanStage stage = plan_stage(f.part, f.map, o, nullptr, "box", "regions.json", "");
  REQUIRE(stage.setups.size() == 2);
  const SetupPlan& s1 = stage.setups[0];
  const SetupPlan& s2 = stage.setups[1];
  CHECK(!s1.setup.resting_face);
  REQUIRE(s2.setup.resting_face);
  CHECK(*s2.setup.resting_face == 0);
  CHECK(s2.folder == "setup2");
  // Setup 1 covers the top only; setup 2 plans and covers only the bottom.
  std::set<std::size_t> faces1, faces2;
  for (const PlannedPoint& p : s1.result.plan.points) faces1.insert(p.face_index);
  for (const PlannedPoint& p : s2.result.plan.points) {
    faces2.insert(p.face_index);
    CHECK(p.id.rfind("S2_", 0) == 0);
    // In the setup frame the bottom faces up.
    CHECK(p.ijk.z() > 1 - 1e-9);
  }
  CHECK(faces1 == std::set<std::size_t>{0});
  CHECK(faces2 == std::set<std::size_t>{1});
  for (const RegionCoverage& r : s2.coverage.regions) CHECK(r.face != 0);  // the top was covered in setup 1
  // Combined: top + bottom, each counted once; the sides are short for the tilt.
  const double want = face_area(0) + face_area(1);
  CHECK(std::abs(stage.coverage.area.covered - want) < 1e-6 * want);
  const double total = 2 * (kX * kY + kX * kZ + kY * kZ);
  CHECK(std::abs(stage.coverage.area.total - total) < 1e-6 * total);
  for (const RegionCoverage& r : stage.coverage.regions) {
    CAPTURE(r.region);
    if (r.face <= 1) {
      CHECK(r.covered);
      CHECK(r.setup == r.face + 1);
    } else {
      CHECK(!r.covered);
      CHECK(r.state == CoverageState::unreachable_access);
    }
  }
  // The greedy estimate of setup 2 is the bottom's area (its interior point reachable).
  CHECK(std::abs(s2.estimated_area - face_area(1)) < 1e-6 * face_area(1));

  // Brute force in each setup's frame: clear of the part, above the fixture plane.
  for (const SetupPlan& s : stage.setups) {
    CAPTURE(s.setup.index);
    const SetupClearance c = brute_clearance(s, o);
    CHECK(c.part >= -(0.25 * 0.25 / 2 + 1e-6));
    // Both setups stand on z = 0: setup 1 on the box's lowest point, setup 2 on the top.
    CHECK(c.lowest >= -1e-9);
    MESSAGE("setup " << s.setup.index << ": " << s.result.plan.points.size() << " points, smallest sampled clearance "
                     << c.part << " mm, lowest ball point z = " << c.lowest << " mm");
  }
  // plan.json records the setup; its points map back onto the part.
  const InspectionPlan read = parse_plan(s2.plan_json, "setup2/plan.json");
  REQUIRE(read.setup);
  CHECK(read.setup->index == 2);
  REQUIRE(read.setup->resting_face);
  CHECK(*read.setup->resting_face == 0);
  CHECK((read.setup->rotation - s2.setup.to_setup.linear()).norm() < 1e-15);
  CHECK_NOTHROW(check_plan_against_part(read, f.part, "setup2/plan.json", 1e-6));
  // Files: one folder per setup and the top-level report and figure.
  std::set<std::string> names;
  for (const FolderFile& file : stage.files) names.insert(file.path);
  for (const char* n : {"report.json", "coverage.png", "setup1/plan.json", "setup1/box_S1.dmi", "setup1/box_S1.prg",
                        "setup1/plan.png", "setup1/coverage.png", "setup1/report.json", "setup2/plan.json",
                        "setup2/box_S2.dmi", "setup2/box_S2.prg", "setup2/report.json"}) {
    CAPTURE(n);
    CHECK(names.count(n) == 1);
  }
}

TEST_CASE("setups: a third setup rests on the front and measures the back") {
  const Fixture& f = fixture();
  const PlanStage stage = plan_stage(f.part, f.map, box_options(3), nullptr, "box", "regions.json", "");
  REQUIRE(stage.setups.size() == 3);
  REQUIRE(stage.setups[2].setup.resting_face);
  CHECK(*stage.setups[2].setup.resting_face == 2);
  const double want = face_area(0) + face_area(1) + face_area(3);
  CHECK(std::abs(stage.coverage.area.covered - want) < 1e-6 * want);
  for (const PlannedPoint& p : stage.setups[2].result.plan.points) CHECK(p.face_index == 3);
}

TEST_CASE("setups: named faces are used in order, and a face that cannot carry the part is refused by name") {
  const Fixture& f = fixture();
  PlannerOptions o = box_options(1);
  o.setup_faces = {3};  // rest on the back: the front comes up
  const PlanStage stage = plan_stage(f.part, f.map, o, nullptr, "box", "regions.json", "");
  REQUIRE(stage.setups.size() == 2);
  CHECK(*stage.setups[1].setup.resting_face == 3);
  CHECK(stage.setups[1].setup.named);
  for (const PlannedPoint& p : stage.setups[1].result.plan.points) CHECK(p.face_index == 2);
  CHECK(std::abs(stage.coverage.area.covered - (face_area(0) + face_area(2))) < 1e-6 * face_area(0));

  o.setup_faces = {9};
  CHECK_THROWS_WITH_AS(plan_stage(f.part, f.map, o, nullptr, "box", "regions.json", ""),
                       doctest::Contains("--setup-faces: face 9 is not a face of the part"), InputError);
  // A cylinder is not a plane; a floor with a wall standing on it cannot carry it.
  const Part groove = groove_part(3);
  const RegionMap groove_map = partition_of(groove, 30, 30);
  CHECK_THROWS_WITH_AS(named_resting_face(groove, groove_map, 1, "--setup-faces"),
                       doctest::Contains("face 1 (\"groove\") is not planar"), InputError);
  const Part wall = floor_and_wall(-10, 10, 8);
  const RegionMap wall_map = partition_of(wall, 30, 30);
  CHECK_THROWS_WITH_AS(named_resting_face(wall, wall_map, 0, "--setup-faces"),
                       doctest::Contains("cannot rest on face 0 (\"floor\")"), InputError);
}

TEST_CASE("setups: resting on a face turns its outward normal to -z and puts it in z = 0") {
  const Fixture& f = fixture();
  for (int face = 0; face < 6; ++face) {
    CAPTURE(face);
    const std::optional<RestingFace> r = planar_face(f.part, f.map, face);
    REQUIRE(r);
    CHECK(r->stable);
    CHECK(std::abs(r->area - face_area(face)) < 1e-6 * face_area(face));
    const PartSetup s = resting_setup(*r, 2, false);
    CHECK((s.to_setup.linear() * r->normal - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12);
    CHECK(std::abs(s.to_setup.linear().determinant() - 1) < 1e-12);
    // Every box corner lands at z >= 0, the face's own corners at z = 0.
    double lowest = 1e300;
    for (double x : {0.0, kX})
      for (double y : {0.0, kY})
        for (double z : {0.0, kZ}) lowest = std::min(lowest, (s.to_setup * Eigen::Vector3d(x, y, z)).z());
    CHECK(std::abs(lowest) < 1e-12);
  }
}

TEST_CASE("plan.json setup: written and read back bit for bit, a matrix that is not a rotation refused by field") {
  InspectionPlan plan;
  plan.probe = {"Probe1", 2};
  PlannedPoint p;
  p.id = "S2_P0001";
  p.order = 1;
  p.face = "bottom";
  p.face_index = 1;
  p.xyz = {1, 2, 10};
  p.ijk = {0, 0, 1};
  p.approach = p.retract = {1, 2, 14};
  plan.points.push_back(p);
  PlanSetupRecord rec;
  rec.index = 2;
  rec.resting_face = 0;
  rec.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  rec.translation = {0.1, -2, 10};
  plan.setup = rec;
  const InspectionPlan back = parse_plan(plan_to_json_text(plan), "plan.json");
  REQUIRE(back.setup);
  CHECK(back.setup->index == 2);
  CHECK(back.setup->resting_face == std::optional<std::size_t>(0));
  CHECK(back.setup->rotation == rec.rotation);
  CHECK(back.setup->translation == rec.translation);
  // to_part inverts x_setup = R x_part + t.
  const Eigen::Vector3d x(3, -4, 5);
  CHECK((back.setup->to_part(rec.rotation * x + rec.translation) - x).norm() < 1e-12);

  std::string text = plan_to_json_text(plan);
  nlohmann::json doc = nlohmann::json::parse(text);
  doc["setup"]["part_to_setup"]["rotation"][0] = {2, 0, 0};
  CHECK_THROWS_WITH_AS(parse_plan(doc.dump(), "plan.json"), doctest::Contains("setup.part_to_setup.rotation: not a rotation"),
                       InputError);
  doc = nlohmann::json::parse(text);
  doc["setup"]["part_to_setup"]["rotation"] = {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // a mirror
  CHECK_THROWS_WITH_AS(parse_plan(doc.dump(), "plan.json"), doctest::Contains("not a rotation"), InputError);
  doc = nlohmann::json::parse(text);
  doc["setup"]["index"] = 0;
  CHECK_THROWS_AS(parse_plan(doc.dump(), "plan.json"), InputError);
}
