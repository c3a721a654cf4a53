// Points the best fit cannot check (docs/registration.md "Points the fit
// cannot check"): each point's redundancy - the share of a deviation at the
// point that shows in its own reading - against a finite difference of the
// whole registration, their sum against the points less the motions fitted,
// and the verdict that will not pass a point the fit follows, end to end
// with the re-measure that answers it.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "inspection/comparison.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/registration.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

SimulatedMeasurement measure(const InspectionPlan& plan, double noise) {
  SimulationOptions sim;
  sim.misalignment = {{1, -2, 30}, {5, 8, -3}};
  sim.noise_sigma = noise;
  sim.seed = 7;
  return simulate_measurement(plan, sim);
}

// Point i's deviation after the whole registration is run again (from `r`'s
// transform) with its measured point moved `step` mm along its normal.
double deviation_moved(const ClosestPointFinder& finder, const MeasurementSet& set, const InspectionPlan& plan,
                       RegistrationOptions options, const RegistrationResult& r, std::size_t i, double step) {
  MeasurementSet moved = set;
  // The normal at the foot, part frame -> CMM frame.
  moved.points[i].xyz += step * (r.transform.linear().transpose() * r.points[i].foot.normal);
  options.start = r.transform;
  const RegistrationResult again = register_measurements(finder, moved, &plan, options);
  REQUIRE(again.converged);
  return again.points[i].deviation;
}

}  // namespace

TEST_CASE("redundancy: each point's share of a deviation that shows, against a finite difference of the fit") {
  const Part part = read_part(kMould);
  const ClosestPointFinder finder(part);
  // The redundancy is that of the fit linearised at its solution (the
  // Gauss-Newton hat matrix). The fit itself also bends with the residuals
  // times the second derivatives of the distances, which shifts the finite
  // difference in proportion to the noise: about 1e-3 on the 20-point
  // grid's least redundant point at 0.2 um (1.3e-2 at 2 um, where a turn the
  // shallow mould barely sees gets little from the points). At 0.2 um the
  // Cauchy loss weights every point by 1 to 1e-4, so both losses are held
  // to the same bound. The step, 1 um, is far above the 1e-10 mm the fit
  // converges to and far below where the distances curve.
  constexpr double kNoise = 2e-4, kStep = 1e-3, kTolerance = 2e-3;
  for (const auto& [nu, nv] : {std::pair{4, 2}, std::pair{5, 4}}) {
    const InspectionPlan plan = grid_plan(part, nu, nv, {"ball", 2});
    const SimulatedMeasurement m = measure(plan, kNoise);
    for (const RobustLoss loss : {RobustLoss::none, RobustLoss::cauchy}) {
      CAPTURE(nu * nv);
      CAPTURE(static_cast<int>(loss));
      RegistrationOptions options;
      options.loss = loss;
      const RegistrationResult r = register_measurements(finder, m.set, &plan, options);
      INFO(r.status);
      REQUIRE(r.converged);
      REQUIRE(r.covariance);
      double sum = 0;
      double lowest = 1;
      for (std::size_t i = 0; i < r.points.size(); ++i) {
        CAPTURE(i);
        REQUIRE(r.points[i].in_fit);
        const double fd = (deviation_moved(finder, m.set, plan, options, r, i, kStep) -
                           deviation_moved(finder, m.set, plan, options, r, i, -kStep)) /
                          (2 * kStep);
        CHECK(std::abs(r.points[i].redundancy - fd) < kTolerance);
        sum += r.points[i].redundancy;
        lowest = std::min(lowest, r.points[i].redundancy);
      }
      // The trace of the hat matrix is the number of motions fitted.
      CHECK(sum == doctest::Approx(static_cast<double>(r.points.size()) - r.fitted_dof).epsilon(1e-9));
      // Eight points for six motions: some points fix the fit instead of
      // being checked by it; twenty leave every point checked.
      if (nu * nv == 8) CHECK(lowest < kCheckedRedundancy);
      if (nu * nv == 20) CHECK(lowest > kCheckedRedundancy);
    }
  }
}

TEST_CASE("redundancy: the verdict does not pass the points the fit follows, and the re-measure ring answers it") {
  const std::string dir = test::scratch_dir("redundancy-remeasure");
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, 4, 2, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, dir + "/plan.json");
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--noise", "0.002",
                            "--outliers", "0", "--out", dir + "/first.csv"})
              .status == 0);
  const test::CliResult first = test::run_furrow(
      {"compare", kMould, "--measurements", dir + "/first.csv", "--plan", dir + "/plan.json", "--out",
       dir + "/first.json"});
  INFO(first.out << first.err);
  // Nothing is out of tolerance: INCONCLUSIVE, exit 4, naming exactly the
  // points whose redundancy is below the bound.
  CHECK(first.status == 4);
  const ComparisonDocument doc = read_comparison(dir + "/first.json");
  CHECK(doc.summary.verdict == Verdict::inconclusive);
  std::set<std::string> unchecked, named;
  for (const ComparisonDocument::Point& p : doc.points) {
    REQUIRE(p.redundancy);
    CHECK(*p.redundancy >= 0);
    CHECK(*p.redundancy <= 1);
    if (*p.redundancy < kCheckedRedundancy) unchecked.insert(p.id);
  }
  for (const InconclusiveReason& reason : doc.summary.inconclusive) {
    CHECK(reason.kind == "point_not_checked");
    named.insert(reason.subject);
    CHECK(first.out.find("point " + reason.subject + " is not checked by the best fit") != std::string::npos);
  }
  CHECK_FALSE(unchecked.empty());
  CHECK(named == unchecked);

  // The re-measure plan: the ring around each such point, not the point.
  REQUIRE(test::run_furrow({"remeasure", dir + "/first.json", "--out", dir + "/again"}).status == 0);
  const InspectionPlan again = read_plan(dir + "/again/plan.json");
  REQUIRE_FALSE(again.points.empty());
  for (const PlannedPoint& p : again.points) {
    const std::string centre = p.id.substr(0, p.id.find("_R"));
    CHECK(p.id != centre);
    CHECK(unchecked.count(centre) == 1);
  }
  // Measured and compared with the first points: the neighbours check them.
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", dir + "/again/plan.json", "--noise", "0.002",
                            "--outliers", "0", "--seed", "7", "--out", dir + "/again.csv"})
              .status == 0);
  const test::CliResult both = test::run_furrow({"compare", kMould, "--measurements", dir + "/first.csv",
                                                 "--measurements", dir + "/again.csv", "--plan", dir + "/plan.json",
                                                 "--out", dir + "/both.json"});
  INFO(both.out << both.err);
  CHECK(both.status == 0);
  for (const ComparisonDocument::Point& p : read_comparison(dir + "/both.json").points)
    CHECK(*p.redundancy >= kCheckedRedundancy);
}
