// Gouge confirmation on synthetic predictions whose answer is known: a
// predicted dent that was cut is CONFIRMED, a predicted dent the part does
// not have is NOT CONFIRMED, a site between all probe points is NOT
// MEASURED, and a dent nothing predicted is UNEXPLAINED where it was put.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>

#include "base/error.hpp"
#include "inspection/comparison.hpp"
#include "inspection/distance_clusters.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const Eigen::Vector2d kCut(0.3, 0.6);        // z-map site G1: predicted and cut
const Eigen::Vector2d kUncut(0.7, 0.3);      // z-map site G2: predicted, not cut
const Eigen::Vector2d kBetween(1.0 / 30, 1.0 / 24);  // G3: between grid points
const Eigen::Vector2d kLocal(0.5, 0.4);      // local gouges L1: predicted and cut
const Eigen::Vector2d kLocalDry(0.85, 0.8);  // local gouges L2: no error predicted, not cut
const Eigen::Vector2d kSurprise(0.15, 0.25); // a dent nothing predicted
constexpr double kRadius = 0.06;             // dents' radius in u (6 mm), v likewise
constexpr double kDepth = 0.02;              // [mm]

double predicted_field(const Eigen::Vector2d& uv) {
  return 0.002 + dent(uv, kCut, kRadius, kDepth) + dent(uv, kUncut, kRadius, kDepth) +
         dent(uv, kLocal, kRadius, kDepth);
}

struct Scenario {
  Part part = mould_part();
  ClosestPointFinder finder{part};
  InspectionPlan plan = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
  Prediction prediction = field_prediction(part, predicted_field);
  SimulatedMeasurement sim;
  Comparison comparison;
  CompareOptions options = compare_options(0.05);

  Scenario() {
    add_zmap_site(prediction, part, kCut, {0.03, 0.03}, kDepth);
    add_zmap_site(prediction, part, kUncut, {0.03, 0.03}, kDepth);
    add_zmap_site(prediction, part, kBetween, {0.001, 0.001}, 0.015);
    for (int k = -2; k <= 2; ++k) add_local_gouge(prediction, part, kLocal + Eigen::Vector2d(0.01 * k, 0.005 * k));
    for (int k = 0; k < 3; ++k) add_local_gouge(prediction, part, kLocalDry + Eigen::Vector2d(0.01 * k, 0));
    // The part as cut: the prediction, except that G2's dent did not
    // happen, plus a dent at kSurprise.
    SimulationOptions o;
    o.noise_sigma = 0.002;
    o.seed = 4;
    o.misalignment = {{-3, 1, 120}, {50, -30, 8}};
    o.surface_offset = [](const PlannedPoint& p) {
      return predicted_field(p.uv) - dent(p.uv, kUncut, kRadius, kDepth) +
             dent(p.uv, kSurprise, kRadius, 0.03);
    };
    sim = simulate_measurement(plan, o);
    comparison = compare_measurements(finder, sim.set, &plan, options);
    verify_prediction(comparison, part, sim.set.probe_radius, prediction, options);
  }
  const GougeSiteCheck& site(const std::string& id) const {
    for (const GougeSiteCheck& s : comparison.gouges->sites)
      if (s.id == id) return s;
    FAIL("no site " << id);
    throw;
  }
};

}  // namespace

TEST_CASE("gouge confirmation: confirmed, not confirmed, not measured, unexplained") {
  const Scenario sc;
  const Comparison& c = sc.comparison;
  REQUIRE(c.gouges.has_value());
  const GougeConfirmation& g = *c.gouges;
  REQUIRE(g.sites.size() == 5);  // G1 G2 G3 L1 L2
  const double lower = c.tolerance.lower();

  SUBCASE("G1: the predicted dent was cut") {
    const GougeSiteCheck& s = sc.site("G1");
    CHECK(s.source == GougeSiteSource::zmap);
    CHECK(s.status == GougeSiteStatus::confirmed);
    REQUIRE(s.deepest.has_value());
    CHECK(*s.measured_depth > *s.threshold);
    CHECK(*s.threshold == doctest::Approx(0.5 * std::abs(lower)));  // 12.5 um beats 3 sigma here
    CHECK(*s.measured_depth == doctest::Approx(-c.registration.points[*s.deepest].deviation));
    CHECK(*s.depth_consistent);
    CHECK(*s.predicted_depth == kDepth);
    // The evidence: exactly the evaluated points whose foot is in the grown box.
    for (std::size_t i = 0; i < c.registration.points.size(); ++i) {
      const RegisteredPoint& p = c.registration.points[i];
      const bool on = p.evaluated && s.search_box.contains(p.foot.uv);
      CHECK(on == std::binary_search(s.points.begin(), s.points.end(), i));
    }
    CHECK(s.points.size() >= 4);
    // The margin: at least 1 mm on the surface (u ~ 100 mm, v ~ 80 mm).
    CHECK(s.search_box.min().x() <= s.uv_box.min().x() - 0.0099);
    CHECK(s.search_box.max().y() >= s.uv_box.max().y() + 0.0124);
  }
  SUBCASE("G2: predicted, measured in tolerance, no overcut") {
    const GougeSiteCheck& s = sc.site("G2");
    CHECK(s.status == GougeSiteStatus::not_confirmed);
    CHECK(s.points.size() >= 4);
    CHECK(*s.measured_depth < *s.threshold);
    CHECK_FALSE(*s.depth_consistent);  // -20 um predicted where the part is nominal
  }
  SUBCASE("G3: no probe point on it") {
    const GougeSiteCheck& s = sc.site("G3");
    CHECK(s.status == GougeSiteStatus::not_measured);
    CHECK(s.points.empty());
    CHECK_FALSE(s.measured_depth.has_value());
    CHECK_FALSE(s.deepest.has_value());
  }
  SUBCASE("L1: five local-gouge contacts 1.1 mm apart are one site, cut") {
    const GougeSiteCheck& s = sc.site("L1");
    CHECK(s.source == GougeSiteSource::local);
    CHECK(s.contacts == 5);
    CHECK(s.status == GougeSiteStatus::confirmed);
    // Its depth comes from the error field: brute force over every cell
    // whose rectangle meets the search box, the lowest band edge.
    double lowest = 0;
    for (int cj = 0; cj < 80; ++cj)
      for (int ci = 0; ci < 100; ++ci) {
        const Eigen::AlignedBox2d cell(Eigen::Vector2d(ci / 100.0, cj / 80.0), Eigen::Vector2d((ci + 1) / 100.0, (cj + 1) / 80.0));
        if (cell.intersects(s.search_box))
          lowest = std::min(lowest, predicted_field(cell.center()) - 0.001);
      }
    REQUIRE(s.predicted_depth.has_value());
    CHECK(*s.predicted_depth == doctest::Approx(-lowest).epsilon(1e-12));
    CHECK(*s.predicted_depth > 0.017);
    CHECK(*s.depth_consistent);
  }
  SUBCASE("L2: local gouges the error field shows no overcut for, part nominal") {
    const GougeSiteCheck& s = sc.site("L2");
    CHECK(s.contacts == 3);
    CHECK_FALSE(s.predicted_depth.has_value());
    CHECK(s.status != GougeSiteStatus::confirmed);
  }
  SUBCASE("the surprise dent is unexplained, where it was put") {
    REQUIRE(g.unexplained.size() == 1);
    const OvercutCluster& u = g.unexplained[0];
    CHECK(u.id == "U1");
    const Eigen::Vector3d centre = sc.part.faces[0].surface().point(kSurprise.x(), kSurprise.y());
    CHECK((u.xyz - centre).norm() < 4);  // the grid is ~3.3 mm
    CHECK(u.depth == doctest::Approx(0.03).epsilon(0.35).scale(0));  // the nearest grid point is off the dent's centre
    // What was put there, less what the fit absorbs (the 20 um dents stay in it).
    CHECK(std::abs(u.depth + sc.sim.true_deviation[u.deepest]) < 2.5e-3);
    CHECK(u.depth > u.threshold);
    // Every point of it overcut beyond its threshold and near the dent.
    for (std::size_t i : u.points) {
      CHECK(c.registration.points[i].deviation < -u.threshold + 1e-9);
      CHECK((c.registration.points[i].foot.point - centre).norm() < 6.5);
    }
  }
  CHECK(c.summary.confirmed_gouges == 2);
  CHECK(c.summary.unexplained_overcuts == 1);
  CHECK_FALSE(c.summary.pass);  // confirmed gouges, and the 30 um surprise is out of tolerance
}

TEST_CASE("gouge confirmation: a confirmed gouge in tolerance still fails the part") {
  const Part part = mould_part();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
  auto field = [](const Eigen::Vector2d& uv) { return 0.002 + dent(uv, kCut, kRadius, kDepth); };
  Prediction p = field_prediction(part, field);
  add_zmap_site(p, part, kCut, {0.03, 0.03}, kDepth);
  SimulationOptions o;
  o.seed = 2;
  o.surface_offset = [&](const PlannedPoint& q) { return field(q.uv); };
  const SimulatedMeasurement m = simulate_measurement(plan, o);
  const CompareOptions options = compare_options(0.05);
  Comparison c = compare_measurements(finder, m.set, &plan, options);
  REQUIRE(c.summary.pass);  // 20 um deep, the zone goes to -25 um
  verify_prediction(c, part, m.set.probe_radius, p, options);
  CHECK(c.summary.out_of_tolerance == 0);
  CHECK(c.summary.confirmed_gouges == 1);
  CHECK_FALSE(c.summary.pass);
  CHECK(c.gouges->unexplained.empty());
  CHECK(c.prediction->overall.explained());
}

TEST_CASE("overcut threshold: the larger of k sigma and a share of the lower limit") {
  GougeConfirmationOptions o;
  const ToleranceZone bilateral = ToleranceZone::make(0.05, 0.025, "t");
  CHECK(overcut_threshold(0, 0.002, bilateral, o) == doctest::Approx(0.0125));
  CHECK(overcut_threshold(0.004, 0.003, bilateral, o) == doctest::Approx(0.015));  // 3 * 5 um
  const ToleranceZone outside_only = ToleranceZone::make(0.05, 0.05, "t");
  CHECK(overcut_threshold(0, 0.002, outside_only, o) == doctest::Approx(0.006));
  o.tolerance_fraction = 1.5;
  const Part part = mould_part();
  const RegistrationResult empty;
  CHECK_THROWS_AS(confirm_gouges(empty, part, bilateral, Prediction{}, PredictionComparison{},
                                 PredictionComparisonOptions{}, o),
                  InputError);
}

TEST_CASE("distance clusters: single linkage, ordered by first member") {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {10, 0, 0}, {1, 0, 0}, {11.5, 0, 0}, {2, 0, 0}, {30, 0, 0}};
  const auto c = distance_clusters(pts, 1.5);
  REQUIRE(c.size() == 3);
  CHECK(c[0] == std::vector<std::size_t>{0, 2, 4});  // a chain 0-2-4, ends 2 mm apart
  CHECK(c[1] == std::vector<std::size_t>{1, 3});
  CHECK(c[2] == std::vector<std::size_t>{5});
  CHECK(distance_clusters(pts, 1.49).size() == 4);  // 10 and 11.5 part
  CHECK(distance_clusters({}, 1).empty());
}

TEST_CASE("distance clusters of dense blobs and chains equal brute-force single linkage") {
  // The oracle: every pair compared, joined by union-find, the same order
  // rule (members increasing, clusters by first member).
  std::mt19937 rng(5);
  std::normal_distribution<double> spread(0.0, 1.0);
  std::uniform_real_distribution<double> where(-20.0, 20.0);
  std::vector<Eigen::Vector3d> pts;
  for (int blob = 0; blob < 6; ++blob) {  // dense blobs, a scan dent's overcuts
    const Eigen::Vector3d c(where(rng), where(rng), 0.1 * where(rng));
    for (int k = 0; k < 150; ++k) pts.push_back(c + 0.8 * Eigen::Vector3d(spread(rng), spread(rng), 0.1 * spread(rng)));
  }
  for (int k = 0; k < 40; ++k) pts.emplace_back(25 + 0.9 * k, -25, 0);  // a chain 0.9 mm apart
  for (int k = 0; k < 60; ++k) pts.emplace_back(where(rng), where(rng), where(rng));  // strays
  auto brute = [&](double d) {
    std::vector<std::size_t> parent(pts.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::function<std::size_t(std::size_t)> root = [&](std::size_t i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j)
        if ((pts[i] - pts[j]).norm() <= d) {
          const std::size_t a = root(i), b = root(j);
          if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::map<std::size_t, std::vector<std::size_t>> by;
    for (std::size_t i = 0; i < pts.size(); ++i) by[root(i)].push_back(i);
    std::vector<std::vector<std::size_t>> out;
    for (auto& [r, m] : by) out.push_back(m);
    return out;
  };
  for (const double d : {0.3, 0.9, 1.5, 5.0}) {
    INFO("distance " << d);
    const auto fast = distance_clusters(pts, d);
    CHECK(fast == brute(d));
    MESSAGE("distance " << d << ": " << fast.size() << " clusters of " << pts.size() << " points");
  }
  CHECK(distance_clusters(pts, 0.9).size() < distance_clusters(pts, 0.3).size());
}

TEST_CASE("one probe point on a narrow predicted gouge: a blunder to the fit, confirmed by the prediction") {
  const Part part = mould_part();
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 30, 24, {"ruby 2 mm", 2});
  // A dent 60 um deep, 2 mm across, centred on one planned point: no
  // neighbour sees it, so the registration cannot tell it from a blunder.
  const Eigen::Vector2d centre = plan.points[300].uv;
  auto field = [&](const Eigen::Vector2d& uv) { return dent(uv, centre, 0.02, 0.06); };
  Prediction p = field_prediction(part, field, 0.0005, {}, 500, 400);
  add_zmap_site(p, part, centre, {0.01, 0.01}, 0.06);
  SimulationOptions o;
  o.seed = 8;
  o.blunders = 4;
  o.surface_offset = [&](const PlannedPoint& q) { return field(q.uv); };
  const SimulatedMeasurement m = simulate_measurement(plan, o);
  REQUIRE_FALSE(m.blunder[300]);
  const CompareOptions options = compare_options(0.05);
  Comparison c = compare_measurements(finder, m.set, &plan, options);
  REQUIRE(c.registration.points[300].outlier == OutlierReason::blunder);
  CHECK_FALSE(c.registration.points[300].evaluated);
  CHECK(c.summary.out_of_tolerance == 0);  // without the prediction the gouge goes unseen
  verify_prediction(c, part, m.set.probe_radius, p, options);
  const RegisteredPoint& q = c.registration.points[300];
  CHECK(q.outlier == OutlierReason::large_deviation);
  CHECK(q.evaluated);
  CHECK_FALSE(q.in_fit);
  CHECK(q.outlier_detail.find("explained by the prediction") != std::string::npos);
  REQUIRE(c.gouges->sites.size() == 1);
  CHECK(c.gouges->sites[0].status == GougeSiteStatus::confirmed);
  CHECK(c.gouges->sites[0].deepest == std::optional<std::size_t>(300));
  CHECK(c.summary.out_of_tolerance == 1);
  CHECK_FALSE(c.summary.pass);
  CHECK(c.prediction->points[300].compared);
  // Blunders the prediction does not explain stay blunders.
  for (std::size_t i = 0; i < c.registration.points.size(); ++i)
    if (i != 300)
      CHECK(c.registration.points[i].outlier == (m.blunder[i] ? OutlierReason::blunder : OutlierReason::none));
}
