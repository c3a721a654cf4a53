// Ambiguous orientation decided on fine fits (docs/registration.md
// "Ambiguous orientation"): a part with no symmetry that the coarse search
// calls ambiguous is not, once fitted - the oracle is the planted
// transform, recovered - and a plane, whose probe centres are the same
// cloud turned over, stays ambiguous whichever side is kept, both fits
// leaving only the noise.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "base/numbers.hpp"
#include "inspection/coarse_alignment.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/orientation_check.hpp"
#include "inspection/registration.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
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

TEST_CASE("orientation: an ambiguous fit whose other orientation moves a point across the zone is not a verdict") {
  const std::string dir = test::scratch_dir("orientation-verdict");
  const Part plane = test::one_face("plane", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0}));
  write_part_json(plane, dir + "/plane.json");
  InspectionPlan plan = grid_plan(plane, 20, 20, {"ruby 2 mm", 2});
  plan.part = dir + "/plane.json";
  write_plan(plan, dir + "/plan.json");
  // A bump 30 um high and 16 mm across: +30 um the right way up, -30 um
  // turned over.
  const auto simulate = [&](const std::string& out, bool anonymous) {
    std::vector<std::string> args = {"simulate-measurement", dir + "/plane.json", "--plan", dir + "/plan.json",
                                     "--misalign", "0,0,180,20,-12,5", "--seed", "3", "--outliers", "0",
                                     "--bump", "10,5,0,8,0.03", "--out", out};
    if (anonymous) args.push_back("--anonymous");
    REQUIRE(test::run_furrow(args).status == 0);
  };
  simulate(dir + "/anonymous.csv", true);
  simulate(dir + "/ids.csv", false);
  const auto compare = [&](const std::string& measurements, const std::vector<std::string>& zone,
                           const std::string& out, bool with_plan) {
    std::vector<std::string> args = {"compare", dir + "/plane.json", "--measurements", measurements,
                                     "--probe-diameter", "2", "--out", out};
    if (with_plan) args.insert(args.end(), {"--plan", dir + "/plan.json"});
    args.insert(args.end(), zone.begin(), zone.end());
    return test::run_furrow(args);
  };
  // Zone -10 / +40 um: the bump is inside read one way, outside the other.
  const std::vector<std::string> unequal = {"--tolerance", "0.05", "--outside", "0.04"};
  const test::CliResult guessed = compare(dir + "/anonymous.csv", unequal, dir + "/guessed.json", false);
  INFO(guessed.out << guessed.err);
  CHECK(guessed.status == 3);
  const ComparisonDocument g = read_comparison(dir + "/guessed.json");
  CHECK(g.summary.verdict == Verdict::inconclusive);
  CHECK(g.summary.alignment == "ambiguous_orientation");
  REQUIRE(g.summary.inconclusive.size() == 1);
  CHECK(g.summary.inconclusive[0].text.find("cannot tell the part's orientation") != std::string::npos);
  CHECK(guessed.out.find("cannot tell the part's orientation") != std::string::npos);
  // The points named are the bump's: the ones whose reading, +h or -h
  // with h the planted height there, leaves the zone one way.
  // (Points within three noise sigmas of the zone's -10 um either way
  // are not judged here.)
  const std::string& text = g.summary.inconclusive[0].text;
  const std::size_t from = text.find("puts point"), to = text.find(" on the other side");
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  std::string list = text.substr(text.find(' ', from + 5) + 1, to - text.find(' ', from + 5) - 1);
  for (std::size_t at; (at = list.find(" and ")) != std::string::npos;) list.replace(at, 5, ", ");
  std::set<std::string> named;
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t end = std::min(list.find(", ", start), list.size());
    named.insert(list.substr(start, end - start));
    start = end + 2;
  }
  std::size_t expected = 0;
  for (const ComparisonDocument::Point& p : g.points) {
    if (!p.evaluated) continue;
    CAPTURE(p.id);
    CAPTURE(p.deviation);
    const double h = std::abs(p.deviation);
    if (h > 0.01 + 3 * 0.002) {
      CHECK(named.count(p.id) == 1);
      ++expected;
    } else if (h < 0.01 - 3 * 0.002) {
      CHECK(named.count(p.id) == 0);
    }
  }
  CHECK(expected >= 3);
  // Zone +-35 um: inside either way, the verdict stands.
  const test::CliResult both = compare(dir + "/anonymous.csv", {"--tolerance", "0.07"}, dir + "/both.json", false);
  INFO(both.out << both.err);
  CHECK(both.status == 0);
  CHECK(read_comparison(dir + "/both.json").registration.coarse_ambiguous);
  // With the plan's ids there is one orientation: the bump reads +30 um.
  const test::CliResult ids = compare(dir + "/ids.csv", unequal, dir + "/ids.json", true);
  INFO(ids.out << ids.err);
  CHECK(ids.status == 0);
}
