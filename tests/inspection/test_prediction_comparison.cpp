// Predicted versus measured: the machined surface a prediction describes
// is what simulate-measurement probes; the statistics against a second
// computation from the points; the prediction alignment against a direct
// linear least-squares solution; the verdict on cases whose answer is known.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>

#include "base/error.hpp"
#include "inspection/comparison.hpp"
#include "partition/partition.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A smooth field with a non-zero mean: what a best fit to the nominal
// partly absorbs.
double wavy(const Eigen::Vector2d& uv) {
  return 0.004 + 0.006 * std::sin(2 * M_PI * uv.x()) * std::cos(M_PI * uv.y());
}

struct Run {
  Part part = mould_part();
  ClosestPointFinder finder{part};
  InspectionPlan plan = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
  Prediction prediction;
  SimulatedMeasurement sim;
  Comparison comparison;
  CompareOptions options = compare_options(0.05);

  // Measurements of the predicted surface plus `extra` (at the planned
  // point), noise `noise`, placed on the table with a misalignment.
  Run(const ErrorField& field, double noise, const std::function<double(const PlannedPoint&)>& extra = {},
      bool align = true)
      : prediction(field_prediction(part, field)) {
    SimulationOptions o;
    o.noise_sigma = noise;
    o.seed = 11;
    o.misalignment = {{1, -2, 30}, {10, 20, 5}};
    const SurfaceOffset predicted = predicted_surface_offsets(plan, prediction).lookup(plan);
    o.surface_offset = [&](const PlannedPoint& p) { return predicted(p) + (extra ? extra(p) : 0.0); };
    sim = simulate_measurement(plan, o);
    options.prediction.align = align;
    comparison = compare_measurements(finder, sim.set, &plan, options);
    verify_prediction(comparison, part, sim.set.probe_radius, prediction, options);
  }
};

}  // namespace

TEST_CASE("the predicted machined surface is what simulate-measurement probes, exactly") {
  const Part part = mould_part();
  const InspectionPlan plan = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
  // Not reached where u < 0.2: the surface stays nominal there, counted.
  const Prediction p = field_prediction(part, wavy, 0.001, [](const Eigen::Vector2d& uv) { return uv.x() >= 0.2; });
  const PredictedSurfaceOffsets machined = predicted_surface_offsets(plan, p);
  SimulationOptions o;
  o.noise_sigma = 0;
  o.surface_offset = machined.lookup(plan);
  const SimulatedMeasurement m = simulate_measurement(plan, o);
  std::size_t not_reached = 0;
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const PlannedPoint& q = plan.points[k];
    const PredictedError e = p.predicted_error_at(q.face, q.uv.x(), q.uv.y());
    not_reached += !e.reached();
    const double along_normal = (m.set.points[k].xyz - q.xyz).dot(q.ijk) - 1.0;  // minus the probe radius
    CHECK(std::abs(along_normal - (e.reached() ? e.value : 0.0)) < 1e-12);
    CHECK(std::isfinite(machined.offset[k]));
  }
  CHECK(not_reached == 6 * 24);  // grid columns with u < 0.2
  CHECK(machined.not_reached == not_reached);
  CHECK(machined.reached == plan.points.size() - not_reached);
}

TEST_CASE("bumps: a raised cosine along the normal, summed with the surface offset") {
  const SurfaceBump b{{10, 20, 30}, 4, -0.03};
  CHECK(b.offset_at({10, 20, 30}) == -0.03);
  CHECK(b.offset_at({12, 20, 30}) == doctest::Approx(-0.015));
  CHECK(b.offset_at({10, 24, 30}) == 0);
  CHECK(b.offset_at({10, 30, 30}) == 0);
  const Part part = mould_part();
  const InspectionPlan plan = grid_plan(part, 10, 8, {"ball", 2});
  SimulationOptions o;
  o.noise_sigma = 0;
  o.surface_offset = [](const PlannedPoint&) { return 0.001; };
  o.bumps = {{plan.points[17].xyz, 5, 0.02}};
  const SimulatedMeasurement m = simulate_measurement(plan, o);
  CHECK(m.true_deviation[17] == doctest::Approx(0.021));
  CHECK(m.true_deviation[0] == doctest::Approx(0.001));
  // Plan cell centres 10 x 10 mm apart: only the centre point within 5 mm.
  CHECK(m.bump_points == std::vector<std::size_t>{1});
  o.bumps[0].radius = 0;
  CHECK_THROWS_AS(simulate_measurement(plan, o), InputError);
}

TEST_CASE("prediction comparison statistics equal a second computation from the points") {
  const Run run(wavy, 0.002, {}, false);
  const Comparison& c = run.comparison;
  REQUIRE(c.prediction.has_value());
  const PredictionComparison& pc = *c.prediction;
  CHECK_FALSE(pc.alignment.applied);
  CHECK(pc.alignment.status == "off");
  // Oracle: the prediction queried at each foot as written, the deviation as
  // measured, sigma_total from its three parts; moments with Eigen.
  std::vector<double> pred, meas, sig;
  for (std::size_t i = 0; i < c.registration.points.size(); ++i) {
    const RegisteredPoint& p = c.registration.points[i];
    if (!p.evaluated) {
      CHECK_FALSE(pc.points[i].compared);
      continue;
    }
    const PredictedError e = run.prediction.predicted_error_at("mould", p.foot.uv.x(), p.foot.uv.y());
    REQUIRE(e.reached());
    CHECK(pc.points[i].compared);
    CHECK(pc.points[i].predicted == e.value);
    CHECK(pc.points[i].measured == p.deviation);
    CHECK(pc.points[i].residual == p.deviation - e.value);
    const double s = std::sqrt(p.uncertainty * p.uncertainty + 0.002 * 0.002 + 0.002 * 0.002 / 12);
    CHECK(pc.points[i].sigma == doctest::Approx(s).epsilon(1e-12));
    pred.push_back(e.value);
    meas.push_back(p.deviation);
    sig.push_back(s);
  }
  const Eigen::Map<const Eigen::ArrayXd> P(pred.data(), pred.size()), M(meas.data(), meas.size()),
      S(sig.data(), sig.size());
  const Eigen::ArrayXd R = M - P;
  const double n = static_cast<double>(R.size());
  const ResidualStatistics& o = pc.overall;
  CHECK(o.count == pred.size());
  CHECK(o.mean_predicted == doctest::Approx(P.mean()).epsilon(1e-12));
  CHECK(o.mean_measured == doctest::Approx(M.mean()).epsilon(1e-12));
  CHECK(o.mean == doctest::Approx(R.mean()).epsilon(1e-12));
  CHECK(o.sigma == doctest::Approx(std::sqrt((R - R.mean()).square().sum() / (n - 1))).epsilon(1e-12));
  CHECK(o.rms == doctest::Approx(std::sqrt(R.square().mean())).epsilon(1e-12));
  CHECK(o.max_abs == R.abs().maxCoeff());
  const Eigen::ArrayXd dp = P - P.mean(), dm = M - M.mean();
  REQUIRE(o.correlation.has_value());
  CHECK(*o.correlation == doctest::Approx((dp * dm).sum() / std::sqrt(dp.square().sum() * dm.square().sum())).epsilon(1e-12));
  CHECK(o.normalised_rms == doctest::Approx(std::sqrt((R / S).square().mean())).epsilon(1e-12));
  CHECK(o.within_share == doctest::Approx(((R.abs() <= 3 * S).cast<double>()).mean()).epsilon(1e-12));
  CHECK(pc.uncompared.not_reached == 0);
}

TEST_CASE("the prediction alignment is the least-squares rigid fit to the predicted surface") {
  const Run run(wavy, 0.002);
  const Comparison& c = run.comparison;
  const PredictionComparison& pc = *c.prediction;
  REQUIRE(pc.alignment.applied);
  CHECK(pc.alignment.status == "converged");
  // Oracle: the linearised problem solved directly, min |J delta - (e - d)|
  // with J_i = [(y_i x n_i)^T, n_i^T] over the fitted points.
  std::vector<std::size_t> fitted;
  for (std::size_t i = 0; i < c.registration.points.size(); ++i)
    if (c.registration.points[i].in_fit && pc.points[i].reached()) fitted.push_back(i);
  CHECK(pc.alignment.points == fitted.size());
  Eigen::MatrixXd J(fitted.size(), 6);
  Eigen::VectorXd rhs(fitted.size());
  for (std::size_t k = 0; k < fitted.size(); ++k) {
    const RegisteredPoint& p = c.registration.points[fitted[k]];
    J.row(k) << p.registered.cross(p.foot.normal).transpose(), p.foot.normal.transpose();
    rhs(k) = pc.points[fitted[k]].predicted - p.deviation;
  }
  const Eigen::VectorXd delta = J.colPivHouseholderQr().solve(rhs);
  CHECK((pc.alignment.parameters - delta).head<3>().norm() < 1e-8);  // rad: < 1 nm at 100 mm
  CHECK((pc.alignment.parameters - delta).tail<3>().norm() < 1e-6);  // mm
  for (std::size_t i = 0; i < c.registration.points.size(); ++i) {
    const RegisteredPoint& p = c.registration.points[i];
    if (!pc.points[i].reached()) continue;
    Eigen::Matrix<double, 1, 6> j;
    j << p.registered.cross(p.foot.normal).transpose(), p.foot.normal.transpose();
    CHECK(std::abs(pc.points[i].measured - (p.deviation + j * delta)) < 1e-7);
  }
  CHECK(pc.alignment.rms_after <= pc.alignment.rms_before);
}

TEST_CASE("verdict: explained when the part is the predicted one, not with a systematic error") {
  SUBCASE("measured = predicted + noise: explained, strongly correlated") {
    const Run run(wavy, 0.002);
    const ResidualStatistics& o = run.comparison.prediction->overall;
    CAPTURE(o.normalised_rms);
    CAPTURE(o.within_share);
    CHECK(o.verdict == PredictionVerdict::explained);
    CHECK(o.normalised_rms == doctest::Approx(1).epsilon(0.25).scale(0));
    CHECK(o.within_share >= 0.99);
    // Field sigma ~3 um against 2 um of noise: r ~ 3 / sqrt(3^2 + 2^2).
    CHECK(*o.correlation > 0.7);
    CHECK(std::abs(o.mean) < 0.0005);
  }
  SUBCASE("+15 um on the half x > 50 that the prediction does not know: not explained") {
    const Run run(wavy, 0.002, [](const PlannedPoint& p) { return p.xyz.x() > 50 ? 0.015 : 0.0; });
    const ResidualStatistics& o = run.comparison.prediction->overall;
    CAPTURE(o.normalised_rms);
    CHECK(o.verdict == PredictionVerdict::not_explained);
    CHECK(o.normalised_rms > 1.5);
  }
  SUBCASE("the measured error is twice the predicted one: not explained, yet correlated") {
    const Run run(wavy, 0.002, [](const PlannedPoint& p) { return wavy(p.uv); });
    const ResidualStatistics& o = run.comparison.prediction->overall;
    CHECK(o.verdict == PredictionVerdict::not_explained);
    CHECK(*o.correlation > 0.9);
  }
  SUBCASE("without the prediction alignment the fit's absorption is charged to the prediction") {
    const Run aligned(wavy, 0.002), raw(wavy, 0.002, {}, false);
    CHECK(aligned.comparison.prediction->overall.explained());
    CHECK(raw.comparison.prediction->overall.normalised_rms >
          aligned.comparison.prediction->overall.normalised_rms);
  }
}

TEST_CASE("per-region residual statistics group the compared points by region") {
  Run run(wavy, 0.002);
  Comparison& c = run.comparison;
  PartitionOptions po;
  po.grid = GridSize{40, 32};
  assign_regions(c, partition_part(run.part, po).map);
  verify_prediction(c, run.part, run.sim.set.probe_radius, run.prediction, run.options);
  std::map<int, std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < c.region.size(); ++i)
    if (c.prediction->points[i].compared && c.region[i]) members[*c.region[i]].push_back(i);
  REQUIRE(c.prediction->regions.size() == members.size());
  CHECK(members.size() >= 4);
  std::size_t k = 0;
  for (const auto& [id, idx] : members) {
    const RegionResidualStatistics& r = c.prediction->regions[k++];
    CHECK(r.region == id);
    CHECK(r.statistics.count == idx.size());
    double sum = 0;
    for (std::size_t i : idx) sum += c.prediction->points[i].residual;
    CHECK(r.statistics.mean == doctest::Approx(sum / idx.size()).epsilon(1e-12));
    CHECK(r.statistics.verdict == (idx.size() < 5 ? PredictionVerdict::too_few_points
                                                  : r.statistics.verdict));
  }
}

TEST_CASE("residual statistics: too few points, constant series, bad options") {
  PredictionComparisonOptions o;
  const ResidualStatistics few = residual_statistics({0.01, 0.02}, {0.011, 0.019}, {0.002, 0.002}, o);
  CHECK(few.verdict == PredictionVerdict::too_few_points);
  CHECK(few.rms == doctest::Approx(0.001));
  const ResidualStatistics flat =
      residual_statistics(std::vector<double>(6, 0.0), {0.001, -0.001, 0.002, 0, 0, 0}, std::vector<double>(6, 0.002), o);
  CHECK_FALSE(flat.correlation.has_value());
  CHECK(flat.verdict == PredictionVerdict::explained);
  // One point in six beyond 3 sigma: 83 % within, not explained.
  const ResidualStatistics one_off =
      residual_statistics(std::vector<double>(6, 0.0), {0.001, -0.001, 0.002, 0, 0, 0.0061}, std::vector<double>(6, 0.002), o);
  CHECK(one_off.within_share == doctest::Approx(5.0 / 6));
  CHECK(one_off.verdict == PredictionVerdict::not_explained);
}
