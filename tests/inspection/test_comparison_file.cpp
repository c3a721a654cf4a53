// comparison.json: write -> read gives back every number of the comparison
// exactly, and a broken file is refused naming the file and the field.
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "support/run_cli.hpp"
#include "verification_fixture.hpp"

using namespace furrow;

namespace {

// A comparison with every kind of point: blunders, a real gouge (large
// deviations), a point beyond the edge, regions from a partition.
struct Fixture {
  Part part = read_part(test::source_path("examples/parts/mould.json"));
  ClosestPointFinder finder{part};
  InspectionPlan plan = grid_plan(part, 16, 12, {"ruby 2 mm", 2});
  SimulatedMeasurement sim;
  CompareOptions options;
  Comparison comparison;
  ComparisonSources sources{"mould.json", "m.csv", "plan.json", "regions.json", "", "mm"};

  Fixture() {
    SimulationOptions o;
    o.misalignment = {{2, -1, 30}, {10, 20, -5}};
    o.blunders = 4;
    o.seed = 7;
    o.surface_offset = [](const PlannedPoint& p) {
      return std::hypot(p.xyz.x() - 62, p.xyz.y() - 30) < 9 ? -0.1 : 0.0;
    };
    sim = simulate_measurement(plan, o);
    MeasuredPoint fixture = sim.set.points[0];
    fixture.id = "FIX";
    fixture.xyz = o.misalignment.part_to_cmm() * Eigen::Vector3d(-15, 40, 25);
    sim.set.points.push_back(fixture);
    options.tolerance = ToleranceZone::make(0.05, 0.02, "t");
    options.registration.loss_scale = 0.025;
    comparison = compare_measurements(finder, sim.set, &plan, options);
    PartitionOptions po;
    po.grid = GridSize{40, 32};
    assign_regions(comparison, partition_part(part, po).map);
    summarize(comparison);
  }
  std::string text() const {
    return comparison_to_json_text(comparison, sim.set, part, options, sources);
  }
};

// `text` with the first `from` replaced by `to` must be refused with `message`.
void expect_refused(const std::string& text, const std::string& from, const std::string& to,
                    const std::string& message) {
  std::string broken = text;
  const std::size_t at = broken.find(from);
  REQUIRE(at != std::string::npos);
  broken.replace(at, from.size(), to);
  CHECK_THROWS_WITH_AS(parse_comparison(broken, "c.json"), message.c_str(), InputError);
}

void check_statistics(const DeviationStatistics& a, const DeviationStatistics& b) {
  CHECK(a.count == b.count);
  CHECK(a.mean == b.mean);
  CHECK(a.sigma == b.sigma);
  CHECK(a.min == b.min);
  CHECK(a.max == b.max);
}

}  // namespace

TEST_CASE("comparison.json round trip: every number read back is the one computed") {
  const Fixture f;
  const Comparison& c = f.comparison;
  const ComparisonDocument d = parse_comparison(f.text(), "c.json");
  CHECK(d.version == kComparisonFormatVersion);
  CHECK(d.sources.part == "mould.json");
  CHECK(d.sources.measurements == "m.csv");
  CHECK(d.sources.plan == "plan.json");
  CHECK(d.sources.regions == "regions.json");
  CHECK(d.sources.prediction.empty());
  CHECK(d.options.tolerance.width == 0.05);
  CHECK(d.options.tolerance.outside == 0.02);
  CHECK(d.options.disposition == "unequal");
  CHECK(d.options.dof == "all");
  CHECK(d.options.loss == "cauchy");
  CHECK(d.options.points == "centre");
  CHECK(d.options.probe_diameter == 2);
  CHECK(d.options.units == "mm");
  CHECK(d.options.outlier_rejection);
  CHECK(d.options.max_outer_iterations == f.options.registration.max_outer_iterations);

  const RegistrationResult& r = c.registration;
  CHECK(d.registration.transform == r.transform.matrix());
  CHECK(d.registration.rms_before == r.rms_before);
  CHECK(d.registration.rms_after == r.rms_after);
  CHECK(d.registration.sigma == r.sigma);
  CHECK(d.registration.outer_iterations == r.outer_iterations);
  CHECK(d.registration.converged == r.converged);
  CHECK(d.registration.status == r.status);
  CHECK(d.registration.coarse_method == "plan ids");
  REQUIRE(r.covariance.has_value());
  REQUIRE(d.registration.covariance.has_value());
  CHECK(*d.registration.covariance == *r.covariance);
  CHECK(d.registration.placement_rotation_deg.z() == doctest::Approx(30).epsilon(1e-3));
  // Outlier counts by reason, against the registration's own flags.
  std::map<std::string, std::size_t> reasons;
  for (const RegisteredPoint& p : r.points)
    if (p.outlier != OutlierReason::none) ++reasons[to_string(p.outlier)];
  CHECK(reasons["blunder"] == 4);
  CHECK(reasons["beyond_edge"] == 1);
  CHECK(reasons["large_deviation"] > 3);
  for (const auto& [reason, n] : d.registration.outliers) CHECK(n == reasons[reason]);
  CHECK(d.registration.outliers.size() == 4);

  REQUIRE(d.points.size() == r.points.size());
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const ComparisonDocument::Point& p = d.points[i];
    const RegisteredPoint& q = r.points[i];
    CAPTURE(i);
    CHECK(p.id == f.sim.set.points[i].id);
    CHECK(d.points_by_id.at(p.id) == i);
    CHECK(p.measured == f.sim.set.points[i].xyz);
    CHECK(p.registered == q.registered);
    CHECK(p.face_index == static_cast<int>(q.foot.face));
    CHECK(p.face == "mould");
    CHECK(p.uv == q.foot.uv);
    CHECK(p.foot == q.foot.point);
    CHECK(p.normal == q.foot.normal);
    CHECK(p.deviation == q.deviation);
    REQUIRE(p.uncertainty.has_value());
    CHECK(*p.uncertainty == q.uncertainty);
    REQUIRE(p.redundancy.has_value());
    CHECK(*p.redundancy == q.redundancy);
    CHECK(p.evaluated == q.evaluated);
    CHECK(p.in_fit == q.in_fit);
    CHECK(p.in_tolerance.has_value() == q.evaluated);
    if (q.evaluated) CHECK(*p.in_tolerance == bool(c.in_tolerance[i]));
    CHECK(p.outlier == (q.outlier == OutlierReason::none ? "" : to_string(q.outlier)));
    CHECK(p.outlier_detail == q.outlier_detail);
    CHECK(p.region == c.region[i]);
  }

  const ComparisonSummary& s = c.summary;
  CHECK(d.summary.points == s.points);
  CHECK(d.summary.in_fit == s.in_fit);
  CHECK(d.summary.evaluated == s.evaluated);
  CHECK(d.summary.outliers == s.outliers);
  CHECK(d.summary.in_tolerance == s.in_tolerance);
  CHECK(d.summary.out_of_tolerance == s.out_of_tolerance);
  CHECK(d.summary.profile == s.profile);
  CHECK(d.summary.pass == s.pass);
  CHECK_FALSE(d.summary.pass);  // the gouge is out of tolerance
  check_statistics(d.summary.deviations, s.deviations);
  REQUIRE(s.regions.size() > 1);
  REQUIRE(d.summary.regions.size() == s.regions.size());
  for (std::size_t k = 0; k < s.regions.size(); ++k) {
    CHECK(d.summary.regions[k].region == s.regions[k].region);
    CHECK(d.summary.regions[k].out_of_tolerance == s.regions[k].out_of_tolerance);
    check_statistics(d.summary.regions[k].deviations, s.regions[k].deviations);
  }
}

TEST_CASE("comparison.json reader: errors name the file and the field") {
  const Fixture f;
  const std::string text = f.text();
  auto refused = [&](const std::string& from, const std::string& to, const std::string& message) {
    expect_refused(text, from, to, message);
  };
  refused("\"version\": 1", "\"version\": 7", "c.json: version: version 7 is not supported (this furrow reads version 1)");
  refused("\"rms_after\": ", "\"rms_after\": \"x\", \"old\": ", "c.json: registration.rms_after: expected a number, found a string");
  refused("],\"deviation\":", "],\"deviation\":null,\"old\":", "c.json: points[0].deviation: expected a number, found null");
  refused("\"evaluated\":true", "\"evaluated\":false", "c.json: points[0].in_tolerance: must be null for a point not evaluated");
  refused("\"id\":\"P00002\"", "\"id\":\"P00001\"", "c.json: points[1].id: duplicate id \"P00001\"");
  refused("\"probe_diameter\"", "\"probe_diameter_mm\"", "c.json: options.probe_diameter: missing");
  refused("\"ambiguous_outliers\": []", "\"ambiguous_outliers\": [7]",
          "c.json: registration.ambiguous_outliers[0]: expected a point id (a string)");
  refused("\"redundancy\":", "\"redundancy\":1.5,\"old\":", "c.json: points[0].redundancy: must lie between 0 and 1");
  CHECK_THROWS_WITH_AS(read_comparison("/nonexistent/c.json"), doctest::Contains("/nonexistent/c.json"), InputError);
}

namespace {

void check_residual_statistics(const ResidualStatistics& a, const ResidualStatistics& b) {
  CHECK(a.count == b.count);
  CHECK(a.mean_predicted == b.mean_predicted);
  CHECK(a.mean_measured == b.mean_measured);
  CHECK(a.mean == b.mean);
  CHECK(a.sigma == b.sigma);
  CHECK(a.rms == b.rms);
  CHECK(a.max_abs == b.max_abs);
  CHECK(a.correlation == b.correlation);
  CHECK(a.normalised_rms == b.normalised_rms);
  CHECK(a.within_share == b.within_share);
  CHECK(a.verdict == b.verdict);
}

// The comparison of a part with a cut gouge, one not cut, and a dent that
// nothing predicted.
struct PredictedFixture {
  Part part = test::mould_part();
  ClosestPointFinder finder{part};
  InspectionPlan plan = grid_plan(part, 24, 20, {"ruby 2 mm", 2});
  Prediction prediction;
  SimulatedMeasurement sim;
  CompareOptions options = test::compare_options(0.05);
  Comparison comparison;
  ComparisonSources sources{"mould.json", "m.csv", "plan.json", "", "prediction.json", "mm"};

  PredictedFixture() {
    const Eigen::Vector2d cut(0.3, 0.6), uncut(0.7, 0.3);
    auto field = [=](const Eigen::Vector2d& uv) {
      return 0.003 * uv.x() + test::dent(uv, cut, 0.06, 0.02) + test::dent(uv, uncut, 0.06, 0.02);
    };
    prediction = test::field_prediction(part, field, 0.001, [](const Eigen::Vector2d& uv) { return uv.y() > 0.1; });
    test::add_zmap_site(prediction, part, cut, {0.03, 0.03}, 0.02);
    test::add_zmap_site(prediction, part, uncut, {0.03, 0.03}, 0.02);
    test::add_zmap_site(prediction, part, {0.5, 0.95}, {0.001, 0.001}, 0.01);
    for (int k = 0; k < 4; ++k) test::add_local_gouge(prediction, part, {0.6 + 0.01 * k, 0.7});
    SimulationOptions o;
    o.seed = 3;
    o.blunders = 2;
    o.surface_offset = [=](const PlannedPoint& p) {
      return field(p.uv) - test::dent(p.uv, uncut, 0.06, 0.02) + test::dent(p.uv, {0.15, 0.3}, 0.06, 0.03);
    };
    sim = simulate_measurement(plan, o);
    options.prediction.probe_sigma = 0.0025;
    options.gouges.site_margin = 1.5;
    comparison = compare_measurements(finder, sim.set, &plan, options);
    verify_prediction(comparison, part, sim.set.probe_radius, prediction, options);
  }
  std::string text() const {
    return comparison_to_json_text(comparison, sim.set, part, options, sources);
  }
};

}  // namespace

TEST_CASE("comparison.json round trip with a prediction: verification read back exactly") {
  const PredictedFixture f;
  const Comparison& c = f.comparison;
  const ComparisonDocument d = parse_comparison(f.text(), "c.json");
  CHECK(d.sources.prediction == "prediction.json");
  CHECK(d.options.prediction.probe_sigma == 0.0025);
  CHECK(d.options.prediction.align);
  CHECK(d.options.gouges.site_margin == 1.5);
  CHECK(d.options.gouges.overcut_sigmas == f.options.gouges.overcut_sigmas);
  CHECK(d.summary.confirmed_gouges == c.summary.confirmed_gouges);
  CHECK(d.summary.unexplained_overcuts == c.summary.unexplained_overcuts);
  CHECK(c.summary.confirmed_gouges == 1);  // G1 (G2 was not cut, G3 between points, L1 not cut)
  CHECK(c.summary.unexplained_overcuts == 1);

  REQUIRE(d.prediction.has_value());
  const PredictionComparison& a = *c.prediction;
  const PredictionComparison& b = *d.prediction;
  CHECK(b.alignment.applied == a.alignment.applied);
  CHECK(b.alignment.status == a.alignment.status);
  CHECK(b.alignment.parameters == a.alignment.parameters);
  CHECK(b.alignment.points == a.alignment.points);
  CHECK(b.alignment.iterations == a.alignment.iterations);
  CHECK(b.alignment.rms_before == a.alignment.rms_before);
  CHECK(b.alignment.rms_after == a.alignment.rms_after);
  check_residual_statistics(b.overall, a.overall);
  CHECK(b.regions.size() == a.regions.size());
  CHECK(b.uncompared.not_reached == a.uncompared.not_reached);
  CHECK(a.uncompared.not_reached > 0);
  REQUIRE(b.points.size() == a.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const PointPrediction &p = a.points[i], &q = *d.points[i].prediction;
    CAPTURE(i);
    CHECK(q.face_predicted == p.face_predicted);
    CHECK(q.status == p.status);
    CHECK(q.compared == p.compared);
    if (!p.reached()) continue;
    CHECK(q.predicted == p.predicted);
    CHECK(q.band_low == p.band_low);
    CHECK(q.band_high == p.band_high);
    CHECK(q.measured == p.measured);
    CHECK(q.residual == p.residual);
    CHECK(q.sigma == p.sigma);
    CHECK(b.points[i].residual == p.residual);
  }

  REQUIRE(d.gouges.has_value());
  REQUIRE(d.gouges->sites.size() == c.gouges->sites.size());
  CHECK(c.gouges->sites.size() == 4);
  for (std::size_t k = 0; k < c.gouges->sites.size(); ++k) {
    const GougeSiteCheck &s = c.gouges->sites[k], &t = d.gouges->sites[k];
    CAPTURE(s.id);
    CHECK(t.id == s.id);
    CHECK(t.source == s.source);
    CHECK(t.face == s.face);
    CHECK(t.face_index == s.face_index);
    CHECK(t.uv_box.min() == s.uv_box.min());
    CHECK(t.uv_box.max() == s.uv_box.max());
    CHECK(t.search_box.min() == s.search_box.min());
    CHECK(t.search_box.max() == s.search_box.max());
    CHECK(t.centroid == s.centroid);
    CHECK(t.predicted_depth == s.predicted_depth);
    CHECK(t.contacts == s.contacts);
    CHECK(t.status == s.status);
    CHECK(t.points == s.points);
    CHECK(t.deepest == s.deepest);
    CHECK(t.measured_depth == s.measured_depth);
    CHECK(t.uncertainty == s.uncertainty);
    CHECK(t.threshold == s.threshold);
    CHECK(t.predicted_error == s.predicted_error);
    CHECK(t.depth_consistent == s.depth_consistent);
  }
  CHECK(d.gouges->sites[2].status == GougeSiteStatus::not_measured);
  REQUIRE(d.gouges->unexplained.size() == c.gouges->unexplained.size());
  for (std::size_t k = 0; k < c.gouges->unexplained.size(); ++k) {
    const OvercutCluster &u = c.gouges->unexplained[k], &v = d.gouges->unexplained[k];
    CHECK(v.id == u.id);
    CHECK(v.points == u.points);
    CHECK(v.deepest == u.deepest);
    CHECK(v.face == u.face);
    CHECK(v.face_index == u.face_index);
    CHECK(v.uv == u.uv);
    CHECK(v.xyz == u.xyz);
    CHECK(v.depth == u.depth);
    CHECK(v.uncertainty == u.uncertainty);
    CHECK(v.threshold == u.threshold);
    CHECK(v.centroid == u.centroid);
  }

  // Broken verification parts name the field.
  const std::string text = f.text();
  auto refused = [&](const std::string& from, const std::string& to, const std::string& message) {
    expect_refused(text, from, to, message);
  };
  const std::string first = f.sim.set.points[*c.gouges->sites[0].deepest].id;
  refused("\"deepest\": \"" + first + "\"", "\"deepest\": \"NOPE\"",
          "c.json: gouge_sites[0].deepest: \"NOPE\" is not a point id of this file");
  refused("\"status\": \"CONFIRMED\"", "\"status\": \"MAYBE\"",
          "c.json: gouge_sites[0].status: \"MAYBE\" is not a gouge site status (CONFIRMED, NOT CONFIRMED, NOT MEASURED)");
  refused("\"prediction_file\": \"prediction.json\"", "\"prediction_file\": null",
          "c.json: prediction_comparison: present without a prediction_file");
  refused("\"verdict\": \"", "\"verdict\": \"probably ", "c.json: prediction_comparison.overall.verdict: \"probably explained\" is not a verdict (explained, not explained, too few points)");
}
