// The search after a registration of few points (few_point_search.hpp),
// on the case that needs every part of it: eight points without ids on a
// full bore (four around the axis at two heights), one of them a blunder.
// Each ring of four has its centre free, so a blunder on one point can be
// moved onto the opposite point by shifting the centre: the data cannot
// tell the two apart. Oracle: a least-squares cylinder fit written here
// (analytic axis and radius, Gauss-Newton) of every single-outlier
// hypothesis, judged by the rule of the header - no registration code.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "inspection/comparison_file.hpp"
#include "inspection/few_point_search.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/registration.hpp"
#include "inspection/registration_run.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;

namespace {

constexpr double kBoreRadius = 15;  // weak_shapes.hpp: axis the y axis
constexpr double kProbeRadius = 1;  // ball of 2 mm

// The corpus's misplacement (the quarter turn), 2 um noise, one blunder,
// no ids.
const Misalignment kQuarterTurn{{1.5, -2, -97}, {-14, 20, -9}};

SimulatedMeasurement corpus_measurement(const InspectionPlan& plan, std::uint32_t seed) {
  SimulationOptions sim;
  sim.misalignment = kQuarterTurn;
  sim.noise_sigma = 0.002;
  sim.blunders = 1;
  sim.seed = seed;
  sim.anonymous = true;
  return simulate_measurement(plan, sim);
}

// The measurement of the corpus case (test_registration_corpus.cpp: 4 x 2
// points, the quarter turn, seed 402).
struct BoreCase {
  test::WeakShape shape = test::weak_shapes(test::source_path("examples/parts/mould.json"))[3];
  InspectionPlan plan;
  SimulatedMeasurement m;
  BoreCase() {
    REQUIRE(std::string(shape.name) == "bore");
    plan = grid_plan(shape.part, 4, 2, {"ball", 2 * kProbeRadius});
    m = corpus_measurement(plan, 402);
  }
};

RegistrationOptions corpus_options() {
  RegistrationOptions o;
  o.loss_scale = 0.025;
  o.outlier_floor = 0.025;
  return o;
}

// Least-squares cylinder of radius `radius` through `q`: axis through
// (a, 0, b) along (c, 1, d) normalised, from the y axis; residuals are the
// distances from the axis less the radius. Returns the sum of squares and
// (in `residual`) every point's residual, `left_out` included.
double fit_cylinder(const std::vector<Eigen::Vector3d>& q, std::size_t left_out, double radius,
                    std::vector<double>& residual) {
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  const auto residuals = [&](const Eigen::Vector4d& p) {
    const Eigen::Vector3d point(p(0), 0, p(1));
    const Eigen::Vector3d axis = Eigen::Vector3d(p(2), 1, p(3)).normalized();
    std::vector<double> r(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) r[i] = (q[i] - point).cross(axis).norm() - radius;
    return r;
  };
  for (int iteration = 0; iteration < 100; ++iteration) {
    const std::vector<double> r0 = residuals(x);
    Eigen::MatrixXd j(q.size() - 1, 4);
    Eigen::VectorXd r(q.size() - 1);
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector4d h = x;
      h(k) += 1e-7;
      const std::vector<double> r1 = residuals(h);
      for (std::size_t i = 0, row = 0; i < q.size(); ++i)
        if (i != left_out) j(static_cast<Eigen::Index>(row++), k) = (r1[i] - r0[i]) / 1e-7;
    }
    for (std::size_t i = 0, row = 0; i < q.size(); ++i)
      if (i != left_out) r(static_cast<Eigen::Index>(row++)) = r0[i];
    const Eigen::Vector4d step = j.colPivHouseholderQr().solve(-r);
    x += step;
    if (step.norm() < 1e-13) break;
  }
  residual = residuals(x);
  double sum = 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    if (i != left_out) sum += residual[i] * residual[i];
  return sum;
}

}  // namespace

TEST_CASE("few points: a blunder on a bore of four points per ring is ambiguous, as every single-outlier fit says") {
  const BoreCase bore;
  const ClosestPointFinder finder(bore.shape.part);
  const RegistrationResult r = register_measurements(finder, bore.m.set, nullptr, corpus_options());
  REQUIRE(r.converged);

  // The probe centres in the part frame of the result: a cylinder of radius
  // 14 about an axis near the y axis (inside the bore).
  std::vector<Eigen::Vector3d> q;
  for (const MeasuredPoint& p : bore.m.set.points) q.push_back(r.transform * p.xyz);
  const std::size_t n = q.size();
  std::vector<double> squares(n);
  std::vector<bool> flagged(n);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> residual;
    squares[j] = fit_cylinder(q, j, kBoreRadius - kProbeRadius, residual);
    // The left-out point must be one the outlier rule flags: beyond the
    // floor (0.025 mm; the robust sigma of micrometre noise is far below).
    flagged[j] = std::abs(residual[j]) > 0.025;
  }
  const std::size_t best = static_cast<std::size_t>(std::min_element(squares.begin(), squares.end()) - squares.begin());
  const double nu = static_cast<double>(n) - 1 - 4;  // 7 points, 4 motions (slide and turn along the axis free)
  const double bound = squares[best] / nu * chi_square_quantile(nu, 3.09);
  std::vector<std::size_t> expected;
  for (std::size_t j = 0; j < n; ++j)
    if (flagged[j] && squares[j] <= bound) expected.push_back(j);
  CAPTURE(squares[best]);
  CAPTURE(bound);

  // The oracle finds the blunder and one more point (the ring's opposite).
  REQUIRE(expected.size() == 2);
  std::size_t blunder = n;
  for (std::size_t i = 0; i < n; ++i)
    if (bore.m.blunder[i]) blunder = i;
  CHECK(std::count(expected.begin(), expected.end(), blunder) == 1);
  CHECK(r.ambiguous_outliers == expected);
  // The result keeps one of them out and the fit is the oracle's.
  std::size_t out = n;
  for (std::size_t i = 0; i < n; ++i)
    if (!r.points[i].in_fit) out = i;
  REQUIRE(out < n);
  CHECK(std::count(expected.begin(), expected.end(), out) == 1);
  double sum = 0;
  for (const RegisteredPoint& p : r.points)
    if (p.in_fit) sum += p.deviation * p.deviation;
  CHECK(sum == doctest::Approx(squares[out]).epsilon(1e-4).scale(0));
}

TEST_CASE("few points: ambiguous outliers make compare exit 3 and name the points, never a verdict") {
  const BoreCase bore;
  const std::string dir = test::scratch_dir("few-point-ambiguous");
  write_part_json(bore.shape.part, dir + "/bore.json");
  InspectionPlan plan = bore.plan;
  plan.part = dir + "/bore.json";
  write_plan(plan, dir + "/plan.json");
  const test::CliResult sim = test::run_furrow(
      {"simulate-measurement", dir + "/bore.json", "--plan", dir + "/plan.json", "--out", dir + "/m.csv",
       "--misalign", "1.5,-2,-97,-14,20,-9", "--noise", "0.002", "--blunders", "1", "--seed", "402", "--anonymous"});
  REQUIRE(sim.status == 0);
  const test::CliResult r = test::run_furrow({"compare", dir + "/bore.json", "--measurements", dir + "/m.csv",
                                              "--probe-diameter", "2", "--tolerance", "0.05", "--out", dir + "/comparison.json"});
  INFO(r.out << r.err);
  CHECK(r.status == 3);
  CHECK(r.out.find("PASS") == std::string::npos);
  const ComparisonDocument doc = read_comparison(dir + "/comparison.json");
  CHECK(doc.summary.verdict == Verdict::inconclusive);
  CHECK(doc.summary.alignment == "ambiguous_outliers");
  REQUIRE(doc.registration.ambiguous_outliers.size() == 2);
  REQUIRE(doc.summary.inconclusive.size() == 1);
  const std::string& text = doc.summary.inconclusive[0].text;
  CHECK(text.find(doc.registration.ambiguous_outliers[0]) != std::string::npos);
  CHECK(text.find(doc.registration.ambiguous_outliers[1]) != std::string::npos);
}

// Found with ten seeds: eight points on the bore, one a 0.73 mm blunder,
// misaligned like the corpus: every placement the global search refined
// absorbed the blunder (four good points 0.13 to 0.49 mm off, none
// flagged: a FAIL of a good part). Run without each point in turn, the
// search finds the placement. Oracle: the planted deviations.
TEST_CASE("few points: a blunder that moves the whole coarse search is found by searching without each point") {
  const test::WeakShape shape = test::weak_shapes(test::source_path("examples/parts/mould.json"))[3];
  const InspectionPlan plan = grid_plan(shape.part, 4, 2, {"ball", 2 * kProbeRadius});
  const SimulatedMeasurement m = corpus_measurement(plan, 602);
  const ClosestPointFinder finder(shape.part);
  const RegistrationResult r = register_measurements(finder, m.set, nullptr, corpus_options());
  REQUIRE(r.converged);
  CHECK(r.ambiguous_outliers.empty());
  for (std::size_t i = 0; i < m.set.points.size(); ++i) {
    CAPTURE(i);
    CHECK(r.points[i].in_fit == !m.blunder[i]);
    // Seven points, four motions: the fit takes at most the noise's size
    // out of each (2 um, 99.9 %: under 7 um).
    if (!m.blunder[i]) CHECK(std::abs(r.points[i].deviation - m.true_deviation[i]) < 0.007);
  }
}

// Found with ten seeds: eight points on the bore, one a 0.73 mm blunder;
// from the placement the first fit ended at, with the blunder left out,
// the tangent planes let each outer step run 3 to 5 mm along a motion the
// six points left barely see and the next run back: the outer loop
// alternated between two placements until its limit. A step that raises
// the true cost is now halved (registration.cpp backtrack()).
TEST_CASE("few points: an outer step that raises the true cost is halved, so the fit converges instead of alternating") {
  const test::WeakShape shape = test::weak_shapes(test::source_path("examples/parts/mould.json"))[3];
  const InspectionPlan plan = grid_plan(shape.part, 4, 2, {"ball", 2 * kProbeRadius});
  const SimulatedMeasurement m = corpus_measurement(plan, 602);
  const ClosestPointFinder finder(shape.part);
  RegistrationOptions o = corpus_options();
  const RegistrationResult first = run_registration(finder, m.set, nullptr, o);
  REQUIRE(first.converged);
  std::size_t blunder = m.set.points.size();
  for (std::size_t i = 0; i < m.set.points.size(); ++i)
    if (m.blunder[i]) blunder = i;
  REQUIRE(blunder < m.set.points.size());
  o.start = first.transform;
  const RegistrationResult r = run_registration(finder, m.set, nullptr, o, blunder);
  INFO(r.status);
  CHECK(r.converged);
  CHECK(r.status == "converged");
}

// Found with ten seeds: eight points on the nearly flat ruled patch, one a
// blunder, turned a quarter turn: a search without one point found the
// other side of the patch (the probe centres of a flat part are the same
// cloud turned over, docs/registration.md "Coarse start") and the fit
// from it won, upside down, without the result saying that another
// orientation fits as well. Oracle: the planted placement.
TEST_CASE("few points: a fit upside down on a flat part, found by a search without one point, is ambiguous") {
  const test::WeakShape shape = test::weak_shapes(test::source_path("examples/parts/mould.json"))[1];
  REQUIRE(std::string(shape.name) == "ruled");
  const InspectionPlan plan = grid_plan(shape.part, 4, 2, {"ball", 2 * kProbeRadius});
  for (const std::uint32_t seed : {462u, 482u}) {
    CAPTURE(seed);
    const SimulatedMeasurement m = corpus_measurement(plan, seed);
    const ClosestPointFinder finder(shape.part);
    const RegistrationResult r = register_measurements(finder, m.set, nullptr, corpus_options());
    REQUIRE(r.converged);
    // The error of the result after the planted placement: turned over
    // (its z axis pointing down) means upside down.
    const Eigen::Isometry3d error = r.transform * kQuarterTurn.part_to_cmm();
    const bool upside_down = error.linear()(2, 2) < 0;
    CHECK((!upside_down || r.coarse.ambiguous));
  }
}
