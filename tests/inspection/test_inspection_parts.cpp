// The smaller pieces of inspection: degrees of freedom, tolerance zones,
// statistics and per-region summaries, the simulator's geometry, outlier
// classification, surface sampling and the DMIS-nominal coarse start.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/outlier_detection.hpp"
#include "inspection/surface_sampling.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

TEST_CASE("degrees of freedom: names, lists, refusals") {
  CHECK(DegreesOfFreedom::parse("all", "--dof").all_free());
  CHECK(DegreesOfFreedom::parse("translation", "--dof").free ==
        std::array<bool, 6>{false, false, false, true, true, true});
  CHECK(DegreesOfFreedom::parse("rotation", "--dof").to_string() == "rotation");
  const DegreesOfFreedom d = DegreesOfFreedom::parse("tz,rx", "--dof");
  CHECK(d.count() == 2);
  CHECK(d.to_string() == "rx,tz");
  CHECK(DegreesOfFreedom::parse("rx,ry,rz,tx,ty,tz", "--dof").to_string() == "all");
  CHECK_THROWS_WITH_AS(DegreesOfFreedom::parse("tx,tx", "--dof"), "--dof: \"tx\" is listed twice",
                       InputError);
  CHECK_THROWS_WITH_AS(DegreesOfFreedom::parse("", "--dof"),
                       "--dof: no degree of freedom left to fit", InputError);
}

TEST_CASE("tolerance zones: bilateral, unilateral, unequal, limits are in") {
  const ToleranceZone b = ToleranceZone::make(0.1, 0.05, "t");
  CHECK(b.disposition() == "bilateral");
  CHECK(b.contains(0.05));
  CHECK(b.contains(-0.05));
  CHECK_FALSE(b.contains(-0.0500001));
  const ToleranceZone out = ToleranceZone::make(0.1, 0.1, "t");
  CHECK(out.disposition() == "unilateral outside");
  CHECK(out.lower() == 0);
  CHECK_FALSE(out.contains(-0.001));
  CHECK(ToleranceZone::make(0.1, 0, "t").disposition() == "unilateral inside");
  const ToleranceZone u = ToleranceZone::make(0.1, 0.03, "t");
  CHECK(u.disposition() == "unequal");
  CHECK(u.lower() == doctest::Approx(-0.07));
  CHECK_THROWS_AS(ToleranceZone::make(0, 0, "t"), InputError);
  CHECK_THROWS_AS(ToleranceZone::make(0.1, 0.2, "t"), InputError);
}

TEST_CASE("statistics and the summary: evaluated points only, per region, profile 2 max|d|") {
  const DeviationStatistics s = deviation_statistics({1, 2, 3, 4});
  CHECK(s.mean == 2.5);
  CHECK(s.sigma == doctest::Approx(std::sqrt(5.0 / 3)));
  CHECK(s.min == 1);
  CHECK(s.max == 4);
  CHECK(deviation_statistics({}).count == 0);

  Comparison c;
  c.tolerance = ToleranceZone::make(0.05, 0.025, "t");
  const double d[6] = {0.01, -0.02, 0.03, -0.2, 0.5, 0.0};
  const OutlierReason why[6] = {OutlierReason::none,    OutlierReason::none,
                                OutlierReason::none,    OutlierReason::large_deviation,
                                OutlierReason::blunder, OutlierReason::none};
  for (int k = 0; k < 6; ++k) {
    RegisteredPoint p;
    p.deviation = d[k];
    p.outlier = why[k];
    p.in_fit = why[k] == OutlierReason::none;
    p.evaluated = why[k] != OutlierReason::blunder;
    c.registration.points.push_back(p);
    c.region.push_back(k < 3 ? std::optional<int>(7) : std::optional<int>(2));
  }
  summarize(c);
  const ComparisonSummary& s2 = c.summary;
  CHECK(s2.points == 6);
  CHECK(s2.in_fit == 4);
  CHECK(s2.evaluated == 5);
  CHECK(s2.outliers == 2);
  CHECK(s2.out_of_tolerance ==
        2);  // 0.03 and the large deviation -0.2; the blunder is not evaluated
  CHECK_FALSE(s2.pass);
  CHECK(s2.profile == doctest::Approx(0.4));
  REQUIRE(s2.regions.size() == 2);
  CHECK(s2.regions[0].region == 2);
  CHECK(s2.regions[0].deviations.count == 2);  // -0.2 and 0.0
  CHECK(s2.regions[0].out_of_tolerance == 1);
  CHECK(s2.regions[1].deviations.mean == doctest::Approx(0.02 / 3));
  CHECK_FALSE(c.in_tolerance[4]);
}

TEST_CASE("simulation: centres one probe radius out along the normal, then placed on the table") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const InspectionPlan plan = grid_plan(part, 5, 4, {"ball", 3});
  CHECK(plan.points.size() == 20);
  SimulationOptions o;
  o.noise_sigma = 0;
  o.misalignment = {{0, 0, 90}, {10, 0, 0}};
  const SimulatedMeasurement m = simulate_measurement(plan, o);
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const Eigen::Vector3d c = plan.points[k].xyz + 1.5 * plan.points[k].ijk;
    const Eigen::Vector3d expected(10 - c.y(), c.x(), c.z());  // Rz(90) then +10 in x
    CHECK((m.set.points[k].xyz - expected).norm() < 1e-12);
    CHECK(m.set.points[k].id == plan.points[k].id);
  }
  o.blunders = 3;
  o.seed = 9;
  o.noise_sigma = 0.01;
  const SimulatedMeasurement a = simulate_measurement(plan, o), b = simulate_measurement(plan, o);
  CHECK(a.true_deviation == b.true_deviation);  // seeded
  int blunders = 0;
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    blunders += a.blunder[k];
    if (a.blunder[k]) CHECK(std::abs(a.true_deviation[k]) > 0.05);
  }
  CHECK(blunders == 3);
  o.blunders = 21;
  CHECK_THROWS_AS(simulate_measurement(plan, o), InputError);
}

TEST_CASE(
    "outliers: an isolated spike is a blunder, a patch of agreeing points a large deviation") {
  std::vector<Eigen::Vector3d> pos;
  std::vector<double> d;
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0, 0.002);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) {
      pos.emplace_back(2.0 * i, 2.0 * j, 0);
      const bool patch = std::hypot(i - 20, j - 20) < 2.5;
      d.push_back(noise(rng) + (patch ? -0.1 : 0.0));
    }
  d[5 * 30 + 5] += 0.4;   // spike
  d[5 * 30 + 7] += -0.3;  // another spike nearby, other sign
  std::vector<OutlierReason> why(d.size(), OutlierReason::none);
  const OutlierVerdict v =
      classify_deviations(pos, d, std::vector<bool>(d.size(), true), OutlierRule{}, why);
  CHECK(v.robust_sigma == doctest::Approx(0.002).epsilon(0.25).scale(0));
  CHECK(v.limit == doctest::Approx(0.025));  // the floor, 5 sigma being less
  CHECK(why[5 * 30 + 5] == OutlierReason::blunder);
  CHECK(why[5 * 30 + 7] == OutlierReason::blunder);
  int patch = 0;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j)
      if (std::hypot(i - 20, j - 20) < 2.5) {
        ++patch;
        CHECK(why[i * 30 + j] == OutlierReason::large_deviation);
      }
  CHECK(patch >= 13);
  CHECK(std::count(why.begin(), why.end(), OutlierReason::none) ==
        static_cast<long>(d.size()) - patch - 2);
}

TEST_CASE("surface sampling: about the requested count, even spacing, trims respected") {
  Part plate;
  plate.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 25, 0}));
  const std::vector<SurfaceSample> s = sample_part_surface(plate, 10000);
  CHECK(s.size() == doctest::Approx(10000).epsilon(0.05));
  // Spacing along x and y about equal although u and v are scaled 4:1.
  CHECK(std::abs(s[1].point.y() - s[0].point.y()) == doctest::Approx(0.5).epsilon(0.05).scale(0));
  Part holed;
  holed.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 100, 0}),
                           Trim({{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                 {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}}}));
  const std::vector<SurfaceSample> h = sample_part_surface(holed, 10000);
  CHECK(h.size() == doctest::Approx(7500).epsilon(0.05));
  for (const SurfaceSample& p : h) CHECK(holed.faces[0].trim().contains(p.uv));
}

TEST_CASE("DMIS nominals give the coarse start when there is no plan") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 8, 6, {"ball", 2});
  SimulationOptions o;
  o.kind = ProbePointKind::contact;
  o.misalignment = {{10, 20, 150}, {300, 200, 100}};
  SimulatedMeasurement m = simulate_measurement(plan, o);
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    m.set.points[k].nominal = plan.points[k].xyz;
    m.set.points[k].nominal_ijk = plan.points[k].ijk;
  }
  const CoarseResult c = coarse_alignment(finder, m.set, nullptr, CoarseOptions{});
  CHECK(c.method == CoarseMethod::dmis_nominals);
  CHECK(c.matched == plan.points.size());
  const Eigen::Isometry3d e = c.transform * o.misalignment.part_to_cmm();
  CHECK(Eigen::AngleAxisd(e.linear()).angle() < 1e-4);
  CHECK(c.median_distance < 0.01);
}

TEST_CASE("outliers: a deep graded gouge is one large deviation, not blunders point by point") {
  // A spherical-cap dent 0.5 mm deep: neighbouring points differ by up to
  // 0.15 mm, far more than the 25 um limit.
  std::vector<Eigen::Vector3d> pos;
  std::vector<double> d;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) {
      pos.emplace_back(2.0 * i, 2.0 * j, 0);
      const double r = std::hypot(i - 15, j - 15);
      d.push_back(r < 4 ? -0.5 * (1 - r * r / 16) : 0.0);
    }
  d[3 * 30 + 3] = 0.7;    // a blunder far away
  d[15 * 30 + 16] = -1.6; // a blunder in the dent: 4x its neighbours' excess
  std::vector<OutlierReason> why(d.size(), OutlierReason::none);
  classify_deviations(pos, d, std::vector<bool>(d.size(), true), OutlierRule{}, why);
  int dent = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (k == 3 * 30 + 3 || k == 15 * 30 + 16) continue;
    if (d[k] < -0.025) {
      ++dent;
      CAPTURE(k);
      CHECK(why[k] == OutlierReason::large_deviation);
    }
  }
  CHECK(dent >= 40);
  CHECK(why[3 * 30 + 3] == OutlierReason::blunder);
  CHECK(why[15 * 30 + 16] == OutlierReason::blunder);
}
