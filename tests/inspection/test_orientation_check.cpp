// Ambiguous orientation decided on fine fits (docs/registration.md
// "Ambiguous orientation"): a part with no symmetry that the coarse search
// calls ambiguous is not, once fitted - the oracle is the planted
// transform, recovered - and a plane, whose probe centres are the same
// cloud turned over, stays ambiguous whichever side is kept, both fits
// leaving only the noise.
#include <doctest/doctest.h>

#include <cmath>

#include "base/numbers.hpp"
#include "inspection/coarse_alignment.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/orientation_check.hpp"
#include "inspection/registration.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;

namespace {

constexpr double kNoise = 0.002;

SimulatedMeasurement anonymous(const InspectionPlan& plan, const Misalignment& misalignment, std::uint32_t seed) {
  SimulationOptions sim;
  sim.misalignment = misalignment;
  sim.noise_sigma = kNoise;
  sim.seed = seed;
  sim.anonymous = true;
  return simulate_measurement(plan, sim);
}

// The search's runner-up: its best other placement turned more than the
// ambiguity angle.
Eigen::Isometry3d runner_up(const CoarseResult& coarse, const CoarseOptions& options) {
  for (const Eigen::Isometry3d& t : coarse.alternatives)
    if (Eigen::AngleAxisd(coarse.transform.linear().transpose() * t.linear()).angle() >
        radians(options.ambiguity_angle_deg))
      return t;
  FAIL("no runner-up turned more than the ambiguity angle");
  return Eigen::Isometry3d::Identity();
}

}  // namespace

TEST_CASE("orientation: the mould the coarse search calls ambiguous is fitted the one right way, and not ambiguous") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 12, 10, {"ball", 2});
  const Misalignment misalignment{{1, -2, 30}, {15, -4, 2}};
  const SimulatedMeasurement m = anonymous(plan, misalignment, 5);
  const RegistrationOptions options;
  // The search's own call: ambiguous (its scores are a point-to-point ICP
  // against a surface sampling, about 0.5 mm off here).
  const CoarseResult coarse = coarse_alignment(finder, m.set, nullptr, options.coarse);
  REQUIRE(coarse.method == CoarseMethod::global_search);
  REQUIRE(coarse.ambiguous);
  const RegistrationResult r = register_measurements(finder, m.set, nullptr, options);
  INFO(r.status);
  REQUIRE(r.converged);
  CHECK_FALSE(r.coarse.ambiguous);
  // The planted transform comes back: the orientation kept is the true one.
  const Eigen::Isometry3d error = r.transform * misalignment.part_to_cmm();
  CHECK(Eigen::AngleAxisd(error.linear()).angle() < 1e-3);
  CHECK(error.translation().norm() < 0.05);
  CHECK(r.rms_after < 1.2 * kNoise);
  // And the runner-up's own fit, run here: it comes back to the same
  // placement (or would explain the points worse) - it was no other
  // orientation of the part.
  RegistrationOptions from_runner_up = options;
  from_runner_up.start = runner_up(coarse, options.coarse);
  CHECK(Eigen::AngleAxisd(from_runner_up.start->linear().transpose() * r.transform.linear()).angle() > 0.5);
  const RegistrationResult other = register_measurements(finder, m.set, nullptr, from_runner_up);
  const double turn = Eigen::AngleAxisd(other.transform.linear().transpose() * r.transform.linear()).angle();
  CAPTURE(turn);
  CHECK((turn < 1e-3 || fit_cost(other, options) > options.coarse.ambiguity_ratio * fit_cost(r, options)));
}

TEST_CASE("orientation: a plane stays ambiguous, both sides fitted to the noise") {
  const Part plane = test::one_face("plane", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0}));
  const ClosestPointFinder finder(plane);
  const InspectionPlan plan = grid_plan(plane, 20, 20, {"ball", 2});
  const RegistrationOptions options;
  for (const Misalignment& misalignment :
       {Misalignment{{0, 0, 180}, {20, -12, 5}}, Misalignment{{1.5, -2, -97}, {-14, 20, -9}}}) {
    CAPTURE(misalignment.rotation_deg.z());
    const SimulatedMeasurement m = anonymous(plan, misalignment, 3);
    const RegistrationResult r = register_measurements(finder, m.set, nullptr, options);
    INFO(r.status);
    REQUIRE(r.converged);
    CHECK(r.coarse.ambiguous);
    CHECK(r.rms_after < 1.2 * kNoise);
    // The plane turned over about a line in it: the fit from there leaves
    // the noise as well.
    RegistrationOptions turned = options;
    turned.start = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitX()) * r.transform;
    const RegistrationResult other = register_measurements(finder, m.set, nullptr, turned);
    REQUIRE(other.converged);
    CHECK(other.rms_after < 1.2 * kNoise);
    CHECK(another_orientation(r.transform, fit_cost(r, options), other.transform, fit_cost(other, options),
                              options.coarse));
  }
}
