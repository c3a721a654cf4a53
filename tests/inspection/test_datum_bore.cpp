// A datum frame from a plane, a bore perpendicular to it and a point (furrow
// compare --align datums with a cylinder secondary). Oracles: the placement
// planted into the simulated points (recovered exactly without noise, to
// 1 um / 1e-5 rad with 1 um noise), a bore machined off position whose
// shift reappears, with the sign and size the geometry says, in every
// free-form deviation, and the plan file read back.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "datum_fixture.hpp"
#include "inspection/datum_frame.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const Eigen::Vector3d kBoreCentre(70, 30, 0);  // where the bore's axis meets datum A (z = 0)
constexpr double kBoreRadius = 6;

// datum_plan() with B replaced by a bore of radius 6 along z under A, 70 mm
// from C: 16 points on two rings 10 mm apart, each with the wall's normal
// out of the material (towards the axis); A gets 8 more points.
InspectionPlan bore_plan(const Part& part) {
  InspectionPlan plan = datum_plan(part);
  DatumFeature b;
  b.label = "B";
  b.kind = DatumFeature::Kind::cylinder;
  b.face = "Bore";
  b.face_index = 3;
  b.origin = kBoreCentre + Eigen::Vector3d(0, 0, -10);
  b.direction = {0, 0, 1};
  b.normal = {0, 0, 1};
  b.radius = kBoreRadius;
  b.axis = 0;
  b.origin_axis = 'X';
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < 8; ++k) {
      const double angle = k * kPi / 4 + ring * kPi / 8 + 0.1;
      const Eigen::Vector3d out(std::cos(angle), std::sin(angle), 0);
      const Eigen::Vector3d at = kBoreCentre + kBoreRadius * out + Eigen::Vector3d(0, 0, ring ? -15 : -5);
      PlannedPoint p = planned("B" + std::to_string(ring * 8 + k + 1), at, -out, "F");
      p.face = "Bore";
      b.points.push_back(p);
    }
  plan.alignment->datums[1] = b;
  // Twelve points on A: a datum plane is probed widely.
  DatumFeature& a = plan.alignment->datums[0];
  for (const double x : {15.0, 35.0, 55.0, 85.0})
    for (const double y : {15.0, 45.0})
      a.points.push_back(planned("A" + std::to_string(a.points.size() + 1), {x, y, 0}, {0, 0, 1}, "A"));
  int order = 0;
  for (DatumFeature& f : plan.alignment->datums)
    for (PlannedPoint& p : f.points) p.order = ++order;
  return plan;
}

// The measured set with every bore point taken `shift` (part frame) away
// from its nominal: the bore machined off position.
MeasurementSet measure_shifted_bore(const InspectionPlan& plan, const Eigen::Vector3d& shift, double r) {
  MeasurementSet set = measure(plan, placement(), r, [](const PlannedPoint&) { return 0.0; });
  for (const PlannedPoint& p : plan.alignment->datums[1].points)
    for (MeasuredPoint& m : set.points)
      if (m.id == p.id) m.xyz = placement() * (p.xyz + shift + r * p.ijk);
  return set;
}

double angle_of(const Eigen::Matrix3d& r) { return Eigen::AngleAxisd(r).angle(); }

}  // namespace

// Exact measurements of `plan`'s points at the planted placement, centres
// (r = 1) and contacts (r = 0): the frame undoes the placement to rounding,
// B's circle is exactly round and its axis meets A where the plan says.
static void check_recovers_placement(const InspectionPlan& plan) {
  for (const double r : {0.0, 1.0}) {
    CAPTURE(r);
    const MeasurementSet set = measure(plan, placement(), r, [](const PlannedPoint&) { return 0.0; });
    const DatumFrame f = fit_datum_frame(*plan.alignment, set, "plan.json");
    const Eigen::Isometry3d error = f.transform * placement();
    CHECK(angle_of(error.linear()) < 1e-12);
    CHECK(error.translation().norm() < 1e-9);
    REQUIRE(f.datums.size() == 3);
    CHECK(f.datums[1].kind == DatumFeature::Kind::cylinder);
    CHECK(f.datums[1].form_error < 1e-9);  // roundness of an exact circle
    CHECK(f.datums[2].form_error < 1e-9);  // a point has none, an exact line's straightness is 0
    CHECK((f.datums[1].origin - placement() * kBoreCentre).norm() < 1e-9);
  }
}

TEST_CASE("bore datum: plane, bore and point recover a known placement exactly") {
  check_recovers_placement(bore_plan(datum_part()));
}

// bore_plan() with C the line of datum_plan()'s wall B (y = 0, along +x):
// the bore sets both in-plane origins, the wall only the direction, as
// furrow plan proposes without two perpendicular walls.
InspectionPlan bore_and_wall_plan(const Part& part) {
  InspectionPlan plan = bore_plan(part);
  DatumFeature c = datum_plan(part).alignment->datums[1];
  c.label = "C";
  c.axis = 'X';
  c.origin_axis = 0;
  for (PlannedPoint& p : c.points) p.id = "C" + p.id.substr(1);
  plan.alignment->datums[2] = c;
  int order = 0;
  for (DatumFeature& f : plan.alignment->datums)
    for (PlannedPoint& p : f.points) p.order = ++order;
  return plan;
}

TEST_CASE("bore datum with a wall for the direction: plane, bore and line recover a known placement exactly") {
  const Part part = datum_part();
  const InspectionPlan plan = bore_and_wall_plan(part);
  check_recovers_placement(plan);
  // The wall machined 0.02 mm off (moved along its normal) moves nothing:
  // it sets only the direction. Turned by 1 mrad about z instead, it turns
  // the frame by exactly that.
  MeasurementSet moved = measure(plan, placement(), 1.0, [](const PlannedPoint& p) { return p.id[0] == 'C' ? 0.02 : 0.0; });
  CHECK((fit_datum_frame(*plan.alignment, moved, "plan.json").transform * placement()).translation().norm() < 1e-9);
  const double turn = 1e-3;
  MeasurementSet turned = measure(plan, placement(), 0.0, [](const PlannedPoint&) { return 0.0; });
  for (const PlannedPoint& p : plan.alignment->datums[2].points)
    for (MeasuredPoint& m : turned.points)
      if (m.id == p.id) {
        // Turned about the bore's axis: the wall's points keep their height.
        const Eigen::Vector3d about = p.xyz - kBoreCentre;
        m.xyz = placement() * (kBoreCentre + Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * about);
      }
  const Eigen::Isometry3d error = fit_datum_frame(*plan.alignment, turned, "plan.json").transform * placement();
  CHECK(angle_of(error.linear()) == doctest::Approx(turn).epsilon(1e-9));
  // A wall line whose points coincide in plan view fixes no direction.
  MeasurementSet stacked = measure(plan, placement(), 0.0, [](const PlannedPoint&) { return 0.0; });
  const std::string c1 = plan.alignment->datums[2].points[0].id, c2 = plan.alignment->datums[2].points[1].id;
  for (MeasuredPoint& m : stacked.points)
    if (m.id == c2)
      for (const MeasuredPoint& n : stacked.points)
        if (n.id == c1) m.xyz = n.xyz + placement().linear() * Eigen::Vector3d(0, 0, 3);
  CHECK_THROWS_WITH_AS(fit_datum_frame(*plan.alignment, stacked, "plan.json"), doctest::Contains("fixes no direction"),
                       DatumFrameError);
}

TEST_CASE("bore datum: with 0.1 um probing noise the frame is within 1 um and 1e-5 rad") {
  const Part part = datum_part();
  const InspectionPlan plan = bore_plan(part);
  std::mt19937 rng(3);
  // The frame's error is the noise propagated, linear in it: on this
  // 100 x 60 mm part mostly datum A's tilt, about 2e-5 rad per um of noise
  // (eight seeds at 0.5 um gave 0.5e-5 to 1.7e-5 rad). At 0.1 um it must
  // stay well inside 1 um / 1e-5 rad.
  std::normal_distribution<double> noise(0, 0.0001);
  const MeasurementSet set = measure(plan, placement(), 1.0, [&](const PlannedPoint& p) {
    return p.face == "F" ? 0.0 : noise(rng);
  });
  const DatumFrame f = fit_datum_frame(*plan.alignment, set, "plan.json");
  const Eigen::Isometry3d error = f.transform * placement();
  CHECK(angle_of(error.linear()) < 1e-5);
  // Over the part (its corners), no point moves by 1 um.
  double worst = 0;
  for (double x : {0.0, 100.0})
    for (double y : {0.0, 60.0})
      for (double z : {-30.0, 40.0}) worst = std::max(worst, (error * Eigen::Vector3d(x, y, z) - Eigen::Vector3d(x, y, z)).norm());
  CHECK(worst < 1e-3);
  CHECK(f.datums[1].form_error > 0);
  CHECK(f.datums[1].form_error < 0.01);
}

TEST_CASE("bore datum: a bore machined 0.05 mm off position moves the frame, and the free-form face with it") {
  const Part part = datum_part();
  const InspectionPlan plan = bore_plan(part);
  const Eigen::Vector3d shift(0.05, 0, 0);  // towards C: the turn about the axis stays
  const MeasurementSet measured = measure_shifted_bore(plan, shift, 1.0);
  const Comparison c = run(part, plan, measured, AlignMethod::datums);
  REQUIRE(c.datum_frame);
  // The frame's origin is the bore's axis: the part seen from it sits
  // -shift away, so a free-form point's deviation is -shift . n (the face is
  // smooth and the shift small: to second order in 0.05 mm).
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    CAPTURE(i);
    CHECK(std::abs(c.registration.points[i].deviation - (-shift.dot(plan.points[i].ijk))) < 2e-5);
  }
  REQUIRE(c.bestfit_profile);
  CHECK(*c.bestfit_profile < 0.002);  // the best fit takes the location away
  CHECK(c.summary.profile > 0.005);
}

TEST_CASE("bore datum: degenerate bore data and a tilted or misplaced definition are refused with the reason") {
  const Part part = datum_part();
  const InspectionPlan plan = bore_plan(part);
  const auto none = [](const PlannedPoint&) { return 0.0; };
  SUBCASE("bore points on a line seen along the axis: no circle") {
    InspectionPlan bad = plan;
    for (PlannedPoint& p : bad.alignment->datums[1].points) {
      p.xyz = {40 + 0.1 * p.order, 36, p.xyz.z()};
      p.ijk = {0, -1, 0};
    }
    CHECK_THROWS_AS(fit_datum_frame(*bad.alignment, measure(bad, placement(), 1.0, none), "plan.json"),
                    DatumFrameError);
  }
  SUBCASE("an axis 5 degrees off the primary's normal") {
    InspectionPlan bad = plan;
    bad.alignment->datums[1].direction = {std::sin(kPi / 36), 0, std::cos(kPi / 36)};
    try {
      fit_datum_frame(*bad.alignment, measure(bad, placement(), 1.0, none), "plan.json");
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("not perpendicular") != std::string::npos);
    }
  }
  SUBCASE("the tertiary point on the bore's axis") {
    InspectionPlan bad = plan;
    bad.alignment->datums[2].origin = kBoreCentre + Eigen::Vector3d(0, 0, -20);
    CHECK_THROWS_AS(fit_datum_frame(*bad.alignment, measure(bad, placement(), 1.0, none), "plan.json"), InputError);
  }
}

TEST_CASE("bore datum: plan.json keeps the cylinder and its radius, and a cylinder without one is refused") {
  const Part part = datum_part();
  const InspectionPlan plan = bore_plan(part);
  const std::string text = plan_to_json_text(plan);
  const InspectionPlan back = parse_plan(text, "plan.json");
  REQUIRE(back.alignment);
  const DatumFeature& b = back.alignment->datums[1];
  CHECK(b.kind == DatumFeature::Kind::cylinder);
  CHECK(b.radius == kBoreRadius);
  CHECK(b.points.size() == 16);
  std::string no_radius = text;
  const std::size_t at = no_radius.find("\"radius\"");
  REQUIRE(at != std::string::npos);
  no_radius.replace(at, 8, "\"radios\"");
  try {
    parse_plan(no_radius, "plan.json");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("radius") != std::string::npos);
  }
}
