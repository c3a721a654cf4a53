// Registration on weakly constrained shapes (docs/registration.md "Weakly
// constrained directions"): plane, nearly flat ruled patch, cylinder
// segment, full bore, sphere cap, surface of revolution and the mould, each
// misaligned by up to 183 degrees about z plus 20 mm, 2 um noise. The oracles:
// the number and kind of free motions each shape has analytically, the
// deviations put into the simulated data, and a fit with the weak
// directions locked by hand. Then the fits that cannot succeed: exit 3 with
// the state in comparison.json, never exit 2 and never PASS.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/registration.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;

namespace {

RegistrationOptions options() {
  RegistrationOptions o;
  o.loss_scale = 0.025;
  o.outlier_floor = 0.025;
  return o;
}

}  // namespace

TEST_CASE("weakly constrained shapes: converge, lose no point, name their free motions, recover the rest") {
  for (const test::WeakShape& shape : test::weak_shapes(test::source_path("examples/parts/mould.json"))) {
    for (const bool anonymous : {false, true}) {
      const std::string name = shape.name;
      CAPTURE(name);
      CAPTURE(anonymous);
      const ClosestPointFinder finder(shape.part);
      const InspectionPlan plan = grid_plan(shape.part, 20, 20, {"ball", 2});
      SimulationOptions sim;
      sim.misalignment = {{0, 0, 183}, {20, -12, 5}};
      sim.noise_sigma = 0.002;
      sim.seed = 11;
      sim.anonymous = anonymous;
      const SimulatedMeasurement m = simulate_measurement(plan, sim);
      const RegistrationResult r = register_measurements(finder, m.set, anonymous ? nullptr : &plan, options());
      INFO(r.status);
      CHECK(r.converged);
      CHECK(r.outcome == FitOutcome::converged);
      // No point lost: every point in the fit, also without ids, where the
      // global search may leave points beyond a face edge until the held
      // motions are settled on the face (docs/registration.md).
      CHECK(r.in_fit_count() == m.set.points.size());
      // The residuals are the noise: RMS within 10 % of it, and each
      // deviation the one put into the data (the fitted motions absorb a
      // little of the noise: well below 1.5 um).
      CHECK(r.rms_after == doctest::Approx(0.002).epsilon(0.10).scale(0));
      double worst = 0;
      for (std::size_t i = 0; i < m.set.points.size(); ++i)
        if (r.points[i].in_fit) worst = std::max(worst, std::abs(r.points[i].deviation - m.true_deviation[i]));
      CHECK(worst < 1.5e-3);
      // The free motions, as the shape has them.
      int translations = 0, rotations = 0, from_points = 0;
      for (const WeakDirection& d : r.observability.weak) {
        (d.translation ? translations : rotations)++;
        from_points += d.from_points;
        if (shape.exact) CHECK(d.held);
      }
      CHECK(translations == shape.translations);
      CHECK(rotations == shape.rotations);
      CHECK(from_points == 0);
      if (shape.exact) CHECK(r.fitted_dof == 6 - shape.translations - shape.rotations);
    }
  }
}

TEST_CASE("weakly constrained shapes with 5 % blunders, and with only 9 points") {
  for (const test::WeakShape& shape : test::weak_shapes(test::source_path("examples/parts/mould.json"))) {
    const std::string name = shape.name;
    CAPTURE(name);
    const ClosestPointFinder finder(shape.part);
    {  // 400 points, 20 blunders of 0.1 to 1 mm: each flagged, no good point lost
      const InspectionPlan plan = grid_plan(shape.part, 20, 20, {"ball", 2});
      SimulationOptions sim;
      sim.misalignment = {{0, 0, 183}, {20, -12, 5}};
      sim.noise_sigma = 0.002;
      sim.blunders = 20;
      sim.seed = 4;
      const SimulatedMeasurement m = simulate_measurement(plan, sim);
      const RegistrationResult r = register_measurements(finder, m.set, &plan, options());
      CHECK(r.converged);
      for (std::size_t i = 0; i < m.set.points.size(); ++i) {
        CAPTURE(i);
        if (m.blunder[i])
          CHECK(r.points[i].outlier == OutlierReason::blunder);
        else
          CHECK(r.points[i].in_fit);
      }
      CHECK(r.rms_after == doctest::Approx(0.002).epsilon(0.10).scale(0));
      CHECK(r.observability.weak.size() == static_cast<std::size_t>(shape.translations + shape.rotations));
    }
    {  // 9 points: the exact symmetries are still found; the points leave
       // nothing free that the surface fixes, or the alignment says so
      const InspectionPlan plan = grid_plan(shape.part, 3, 3, {"ball", 2});
      SimulationOptions sim;
      sim.misalignment = {{0, 0, 183}, {20, -12, 5}};
      sim.noise_sigma = 0.002;
      sim.seed = 6;
      const SimulatedMeasurement m = simulate_measurement(plan, sim);
      const RegistrationResult r = register_measurements(finder, m.set, &plan, options());
      CHECK(r.converged);
      CHECK(r.in_fit_count() == 9);
      std::size_t from_surface = 0;
      for (const WeakDirection& d : r.observability.weak) from_surface += !d.from_points;
      if (shape.exact) CHECK(from_surface == static_cast<std::size_t>(shape.translations + shape.rotations));
      for (std::size_t i = 0; i < m.set.points.size(); ++i)
        CHECK(std::abs(r.points[i].deviation - m.true_deviation[i]) < 4e-3);
    }
  }
}

TEST_CASE("weakly constrained: held directions give the fit of the same directions locked by hand") {
  // A plane tilted and lifted on the CMM, in-plane placement as designed:
  // locking tx, ty, rz by hand (--dof rx,ry,tz) is then the right fit, and
  // holding them automatically must give the same deviations.
  const Part part = test::one_face("plane", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0}));
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 12, 9, {"ball", 2});
  SimulationOptions sim;
  sim.misalignment = {{0.4, -0.3, 0}, {0, 0, 0.2}};
  sim.noise_sigma = 0.002;
  sim.seed = 5;
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  const RegistrationResult held = register_measurements(finder, m.set, &plan, options());
  RegistrationOptions by_hand = options();
  by_hand.dof = DegreesOfFreedom::parse("rx,ry,tz", "test");
  const RegistrationResult locked = register_measurements(finder, m.set, &plan, by_hand);
  REQUIRE(held.converged);
  REQUIRE(locked.converged);
  CHECK(held.fitted_dof == 3);
  CHECK(locked.fitted_dof == 3);
  CHECK(locked.observability.weak.empty());  // nothing left free among rx, ry, tz
  for (std::size_t i = 0; i < m.set.points.size(); ++i)
    CHECK(std::abs(held.points[i].deviation - locked.points[i].deviation) < 1e-9);
  CHECK(held.sigma == doctest::Approx(locked.sigma).epsilon(1e-9));
}

TEST_CASE("fits that cannot succeed: too few points, exit 3 with the state written, never exit 2, never PASS") {
  const std::string dir = test::scratch_dir("registration-too-few");
  const Part plane = test::one_face("plane", make_plane({0, 0, 0}, {100, 0, 0}, {0, 60, 0}));
  write_part_json(plane, dir + "/plane.json");
  // Three points on the plane, every motion free: the plane leaves three
  // motions, the points fix the other three exactly - nothing is verified.
  test::write_text(dir + "/three.csv", "id,x,y,z\nA,10,10,0\nB,80,15,0\nC,40,50,0\n");
  // Two points: fewer than the six free parameters.
  test::write_text(dir + "/two.csv", "id,x,y,z\nA,10,10,0\nB,80,15,0\n");
  for (const char* name : {"three", "two"}) {
    CAPTURE(name);
    const std::string out = dir + "/" + name + ".json";
    const test::CliResult r = test::run_furrow({"compare", dir + "/plane.json", "--measurements",
                                                dir + "/" + name + ".csv", "--points", "contact", "--out", out});
    INFO(r.out << r.err);
    CHECK(r.status == 3);
    CHECK(r.out.find("PASS") == std::string::npos);
    const ComparisonDocument doc = read_comparison(out);
    CHECK(doc.summary.alignment == "too_few_points");
    CHECK(doc.registration.outcome == "too_few_points");
    CHECK(doc.summary.verdict == Verdict::inconclusive);
    REQUIRE(doc.summary.inconclusive.size() == 1);
    CHECK(doc.summary.inconclusive[0].text.find("did not succeed") != std::string::npos);
  }
  // A file that cannot be read is still bad input.
  test::write_text(dir + "/bad.csv", "id,x,y,z\nA,10,ten,0\n");
  const test::CliResult bad = test::run_furrow({"compare", dir + "/plane.json", "--measurements", dir + "/bad.csv",
                                                "--points", "contact", "--out", dir + "/bad.json"});
  CHECK(bad.status == 2);
}

TEST_CASE("a real-world case: 31 contact points in inches on a nearly flat ruled panel, turned 180 degrees, no ids") {
  // A panel ruled between a straight edge and a shallow, lopsided curve
  // 120 mm away (at most 1.6 mm high): 120 x 80 mm, slopes below 0.02.
  // 31 points at random (u, v), the part turned 181 degrees on the table and
  // moved 30 mm, 2 um noise, written in inches as a CMM writes them,
  // compared without a plan. (A bilinear, hyperbolic-paraboloid panel would
  // not do: upside down it is the same surface up to a tilt, so contact
  // points cannot tell which side was measured.)
  const std::string dir = test::scratch_dir("registration-ruled-inch");
  const Part part = test::one_face(
      "panel", NurbsSurface(1, 2, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1},
                            {{{0, 0, 0}, {0, 40, 0}, {0, 80, 0}}, {{120, 0, 0}, {120, 30, 3}, {120, 80, 0.4}}}));
  write_part_json(part, dir + "/panel.json");
  InspectionPlan plan;
  plan.probe = {"ball", 2};
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return 0.04 + 0.92 * (state >> 8) / 16777216.0;
  };
  for (int k = 0; k < 31; ++k) {
    const double u = next(), v = next();
    const DifferentialGeometry g = part.faces[0].geometry(u, v);
    PlannedPoint p;
    p.id = "P" + std::to_string(k + 1);
    p.order = k + 1;
    p.face = "panel";
    p.uv = {u, v};
    p.xyz = g.point;
    p.ijk = g.normal;
    plan.points.push_back(p);
  }
  SimulationOptions sim;
  sim.misalignment = {{0, 0, 181}, {30, -10, 2}};
  sim.noise_sigma = 0.002;
  sim.seed = 3;
  sim.kind = ProbePointKind::contact;
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  std::string csv = "id,x,y,z\r\n";
  for (const MeasuredPoint& p : m.set.points) {
    char line[160];
    std::snprintf(line, sizeof line, "%s,%.6f,%.6f,%.6f\r\n", p.id.c_str(), p.xyz.x() / 25.4, p.xyz.y() / 25.4,
                  p.xyz.z() / 25.4);
    csv += line;
  }
  test::write_text(dir + "/m.csv", csv);
  const test::CliResult r = test::run_furrow({"compare", dir + "/panel.json", "--measurements", dir + "/m.csv",
                                              "--units", "inch", "--points", "contact", "--out", dir + "/c.json"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  const ComparisonDocument doc = read_comparison(dir + "/c.json");
  CHECK(doc.summary.in_fit == 31);
  CHECK(doc.summary.evaluated == 31);
  CHECK(doc.summary.alignment == "ok");
  // Each deviation is the noise put in (the fit absorbs a little of it;
  // inches written to 1e-6 add 0.0254 um).
  for (std::size_t i = 0; i < doc.points.size(); ++i)
    CHECK(std::abs(doc.points[i].deviation - m.true_deviation[i]) < 2.5e-3);
  CHECK(doc.registration.weak.size() == 3);  // the two slides and the turn about the normal
  CHECK(r.out.find("weakly constrained: translation along") != std::string::npos);
}
