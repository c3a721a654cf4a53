// Registration: recovery of a known misalignment (with and without ids),
// blunders, robust versus plain least squares, probe compensation, locked
// DOF and the covariance's 1/sqrt(N) law. The oracle is always the simulated
// truth: the part-to-CMM motion and the deviations put into the data.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/registration.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

Part mould() { return read_part(test::source_path("examples/parts/mould.json")); }

// Worst displacement error of the registered transform over the plan's
// points, and its rotation error, against the simulated truth.
struct TransformError {
  double displacement;  // [mm]
  double angle;         // [rad]
};
TransformError error_of(const RegistrationResult& r, const Misalignment& truth,
                        const InspectionPlan& plan) {
  const Eigen::Isometry3d e = r.transform * truth.part_to_cmm();  // identity when exact
  TransformError out{0, Eigen::AngleAxisd(e.linear()).angle()};
  for (const PlannedPoint& p : plan.points)
    out.displacement = std::max(out.displacement, (e * p.xyz - p.xyz).norm());
  return out;
}

// Plan points at random (u,v) of one face (seeded).
InspectionPlan random_plan(const Part& part, int count, std::uint32_t seed, double probe_diameter) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  InspectionPlan plan;
  plan.probe = {"ball", probe_diameter};
  const Face& face = part.faces[0];
  for (int k = 0; k < count; ++k) {
    const ParameterDomain& d = face.domain();
    const double u = d.u0 + unit(rng) * d.width_u(), v = d.v0 + unit(rng) * d.width_v();
    const DifferentialGeometry g = face.geometry(u, v);
    PlannedPoint p;
    p.id = "R" + std::to_string(k);
    p.order = k + 1;
    p.face = face.name();
    p.uv = {u, v};
    p.xyz = g.point;
    p.ijk = g.normal;
    plan.points.push_back(p);
  }
  return plan;
}

RegistrationOptions options_for(double tolerance) {
  RegistrationOptions o;
  o.loss_scale = tolerance / 2;
  o.outlier_floor = tolerance / 2;
  return o;
}

// Largest displacement between two transforms over the plan's points [mm].
double difference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                  const InspectionPlan& plan) {
  double out = 0;
  for (const PlannedPoint& p : plan.points) out = std::max(out, (a * p.xyz - b * p.xyz).norm());
  return out;
}

SimulationOptions misaligned_with_blunders(const InspectionPlan& plan, double noise,
                                           std::uint32_t seed) {
  SimulationOptions sim;
  sim.misalignment = {{4, -6, 10}, {20, -12, 15}};  // up to 10 degrees and 20 mm
  sim.noise_sigma = noise;
  sim.blunders = static_cast<int>(plan.points.size() / 20);  // 5 %
  sim.seed = seed;
  return sim;
}

void check_blunders_flagged(const RegistrationResult& r, const SimulatedMeasurement& m) {
  int missed = 0, false_alarms = 0;
  for (std::size_t i = 0; i < m.set.points.size(); ++i) {
    missed += m.blunder[i] && r.points[i].outlier != OutlierReason::blunder;
    false_alarms += !m.blunder[i] && r.points[i].outlier != OutlierReason::none;
  }
  CHECK(missed == 0);
  CHECK(false_alarms == 0);
}

}  // namespace

TEST_CASE("noise-free recovery on the mould is exact, blunders flagged") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 45, 36, {"ball", 2});
  const SimulationOptions sim = misaligned_with_blunders(plan, 0, 3);
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  const RegistrationResult r = register_measurements(finder, m.set, &plan, options_for(0.05));
  CHECK(r.converged);
  CHECK(r.coarse.method == CoarseMethod::plan_ids);
  const TransformError e = error_of(r, sim.misalignment, plan);
  CHECK(e.displacement < 1e-9);
  CHECK(e.angle < 1e-12);
  check_blunders_flagged(r, m);
  for (std::size_t i = 0; i < m.set.points.size(); ++i)
    if (!m.blunder[i]) CHECK(std::abs(r.points[i].deviation) < 1e-9);
}

TEST_CASE("recovery on the mould: < 1 um / 1e-5 rad with 2 um noise and 5% blunders") {
  // 150 000 points: the mould is shallow, so rotation about z and the
  // in-plane shifts are seen only through its slopes; fewer points leave
  // them statistically uncertain beyond 1e-5 rad (the covariance says so).
  const Part part = mould();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 400, 375, {"ball", 2});
  const SimulationOptions sim = misaligned_with_blunders(plan, 0.002, 42);
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  const RegistrationResult r = register_measurements(finder, m.set, &plan, options_for(0.05));
  CHECK(r.converged);
  const TransformError e = error_of(r, sim.misalignment, plan);
  CHECK(e.displacement < 1e-3);
  CHECK(e.angle < 1e-5);
  check_blunders_flagged(r, m);
  CHECK(r.sigma == doctest::Approx(0.002).epsilon(0.02).scale(0));
  // The actual error is a plausible draw from the reported covariance:
  // chi-square with 6 degrees of freedom, below 30 with probability 1 - 4e-5.
  REQUIRE(r.covariance.has_value());
  const Eigen::Isometry3d fix = sim.misalignment.part_to_cmm().inverse() * r.transform.inverse();
  Eigen::Matrix<double, 6, 1> delta;
  const Eigen::AngleAxisd aa(fix.linear());
  delta << aa.angle() * aa.axis(), fix.translation();
  const double chi2 = delta.dot(r.covariance->ldlt().solve(delta));
  CHECK(chi2 < 30);
}

TEST_CASE("robust fit with blunders = plain least squares without them") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 45, 36, {"ball", 2});
  const SimulatedMeasurement m =
      simulate_measurement(plan, misaligned_with_blunders(plan, 0.002, 9));
  const RegistrationResult robust = register_measurements(finder, m.set, &plan, options_for(0.05));
  MeasurementSet clean = m.set;
  clean.points.clear();
  for (std::size_t i = 0; i < m.set.points.size(); ++i)
    if (!m.blunder[i]) clean.points.push_back(m.set.points[i]);
  RegistrationOptions ls = options_for(0.05);
  ls.loss = RobustLoss::none;
  ls.flag_outliers = false;
  const RegistrationResult plain = register_measurements(finder, clean, &plan, ls);
  CHECK(plain.converged);
  CHECK(difference(plain.transform, robust.transform, plan) < 1e-9);
  CHECK(plain.sigma == doctest::Approx(robust.sigma).epsilon(1e-9));
}

TEST_CASE("without ids, a part turned 90 or 180 degrees on the table gives the id answer") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 45, 36, {"ball", 3});
  for (double turn : {90.0, 180.0, -90.0}) {
    SimulationOptions sim = misaligned_with_blunders(plan, 0.002, 7);
    sim.misalignment = {{1.5, -2, turn + 3}, {250, 140, -35}};
    const SimulatedMeasurement with_ids = simulate_measurement(plan, sim);
    sim.anonymous = true;
    const SimulatedMeasurement anonymous = simulate_measurement(plan, sim);
    CAPTURE(turn);
    const RegistrationResult by_ids =
        register_measurements(finder, with_ids.set, &plan, options_for(0.05));
    const RegistrationResult global =
        register_measurements(finder, anonymous.set, &plan, options_for(0.05));
    CHECK(by_ids.coarse.method == CoarseMethod::plan_ids);
    CHECK(global.coarse.method == CoarseMethod::global_search);
    CHECK_FALSE(global.coarse.ambiguous);
    CHECK(global.converged);
    CHECK(difference(global.transform, by_ids.transform, plan) < 1e-9);
    // And both are near the truth (statistically: 1620 points, 2 um noise).
    CHECK(error_of(global, sim.misalignment, plan).displacement < 0.01);
  }
}

TEST_CASE("probe compensation: 4 mm ball centres on a sphere of radius 50") {
  Part part;
  part.faces.emplace_back("sphere", make_sphere(50, 0.1, 2.5, -0.7, 1.2));
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 12, 10, {"ball", 4});
  SimulationOptions sim;
  sim.noise_sigma = 0;
  sim.misalignment = {{0, 0, 0}, {0.4, -0.3, 0.25}};
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  CHECK((m.set.points[0].xyz - sim.misalignment.translation).norm() == doctest::Approx(52));
  RegistrationOptions o = options_for(0.05);
  o.dof = DegreesOfFreedom::parse("translation", "test");
  const RegistrationResult r = register_measurements(finder, m.set, nullptr, o);
  CHECK(r.converged);
  for (const RegisteredPoint& p : r.points) CHECK(std::abs(p.deviation) < 1e-9);
  CHECK((r.transform.translation() + sim.misalignment.translation).norm() < 1e-9);

  SUBCASE("all six DOF: rotations about the centre are not observable, held, and the report says so") {
    const RegistrationResult full = register_measurements(finder, m.set, &plan, options_for(0.05));
    for (const RegisteredPoint& p : full.points) CHECK(std::abs(p.deviation) < 1e-9);
    CHECK(full.fitted_dof == 3);
    REQUIRE(full.observability.weak.size() == 3);
    for (const WeakDirection& d : full.observability.weak) {
      CHECK_FALSE(d.translation);
      CHECK(d.held);
      CHECK_FALSE(d.from_points);
      CHECK(d.axis_point.cross(d.direction).norm() < 1e-6);  // the axis passes through the centre
    }
    // The three translations that are fitted have a covariance.
    CHECK(full.covariance.has_value());
  }
}

TEST_CASE("a locked z translation stays exactly where it started") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 20, 16, {"ball", 2});
  SimulationOptions sim;
  sim.misalignment = {{0.2, -0.1, 0.5}, {0.3, -0.2, 0.15}};
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  RegistrationOptions o = options_for(0.05);
  o.dof = DegreesOfFreedom::parse("rx,ry,rz,tx,ty", "test");
  const RegistrationResult locked = register_measurements(finder, m.set, &plan, o);
  CHECK(locked.coarse.method == CoarseMethod::identity);
  CHECK(locked.transform.translation().z() == 0.0);
  CHECK(locked.parameters(5) == 0.0);
  REQUIRE(locked.covariance.has_value());
  CHECK((*locked.covariance).row(5).isZero());
  // Free, the same data wants a z shift: the lock did something.
  const RegistrationResult free = register_measurements(finder, m.set, &plan, options_for(0.05));
  CHECK(std::abs(free.transform.translation().z()) > 0.01);
  CHECK(locked.rms_after > free.rms_after);
}

TEST_CASE("covariance: standard deviations halve when the points quadruple") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  Eigen::Matrix<double, 6, 1> sd[2];
  const int counts[2] = {400, 1600};
  for (int k = 0; k < 2; ++k) {
    const InspectionPlan plan = random_plan(part, counts[k], 100 + k, 2);
    SimulationOptions sim;
    sim.misalignment = {{2, 1, -3}, {5, 4, -2}};
    sim.seed = 200 + k;
    const SimulatedMeasurement m = simulate_measurement(plan, sim);
    const RegistrationResult r = register_measurements(finder, m.set, &plan, options_for(0.05));
    REQUIRE(r.covariance.has_value());
    sd[k] = r.covariance->diagonal().cwiseSqrt();
    for (const RegisteredPoint& p : r.points) CHECK(p.uncertainty > 0);
  }
  for (int j = 0; j < 6; ++j) {
    CAPTURE(j);
    CHECK(sd[1](j) / sd[0](j) == doctest::Approx(0.5).epsilon(0.2).scale(0));
  }
}

TEST_CASE(
    "a real gouge is a large deviation, evaluated, isolated blunders are not, edges are refused") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  InspectionPlan plan = grid_plan(part, 40, 32, {"ball", 2});
  const Eigen::Vector3d gouge_centre(62, 30, 0);
  SimulationOptions sim;
  sim.misalignment = {{1, 2, 3}, {4, 5, 6}};
  sim.blunders = 10;
  sim.seed = 5;
  sim.surface_offset = [&](const PlannedPoint& p) {
    const double r = std::hypot(p.xyz.x() - gouge_centre.x(), p.xyz.y() - gouge_centre.y());
    return r < 7 ? -0.12 : 0.0;
  };
  SimulatedMeasurement m = simulate_measurement(plan, sim);
  // A point probed on the fixture, 15 mm beyond the face edge.
  MeasuredPoint fixture = m.set.points[0];
  fixture.id = "FIX";
  fixture.xyz = sim.misalignment.part_to_cmm() * Eigen::Vector3d(-15, 40, 25);
  m.set.points.push_back(fixture);

  CompareOptions co;
  co.registration = options_for(0.05);
  co.tolerance = ToleranceZone::make(0.05, 0.025, "test");
  const Comparison c = compare_measurements(finder, m.set, &plan, co);
  int gouge_points = 0;
  for (std::size_t i = 0; i + 1 < m.set.points.size(); ++i) {
    const RegisteredPoint& p = c.registration.points[i];
    const bool in_gouge = std::abs(m.true_deviation[i] + 0.12) < 0.02 && !m.blunder[i];
    if (in_gouge) {
      ++gouge_points;
      CHECK(p.outlier == OutlierReason::large_deviation);
      CHECK(p.evaluated);
      CHECK_FALSE(p.in_fit);
      CHECK_FALSE(c.in_tolerance[i]);
      CHECK(p.deviation == doctest::Approx(-0.12).epsilon(0.05).scale(0));  // 6 um: 3 sigma of the noise
    }
    if (m.blunder[i]) CHECK(p.outlier == OutlierReason::blunder);
  }
  CHECK(gouge_points >= 5);
  CHECK(c.registration.points.back().outlier == OutlierReason::beyond_edge);
  CHECK_FALSE(c.summary.pass);
  CHECK(c.summary.out_of_tolerance == static_cast<std::size_t>(gouge_points));
  CHECK(c.summary.profile == doctest::Approx(2 * 0.12).epsilon(0.05).scale(0));  // 2 x (120 um + the noise)
}
