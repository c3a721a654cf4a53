// Coverage of a plan: the per-region counts against a recount of the plan's
// own points, the reasons, and `furrow plan`'s exit status for a region no
// probe reaches.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <utility>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "plan_fixtures.hpp"
#include "planning/coverage_image.hpp"
#include "planning/plan_coverage.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

// A groove of radius 1 mm: a 4 mm ball cannot reach its bottom, a 1 mm ball can.
PlannerOptions groove_options(double ball) {
  PlannerOptions o;
  o.probe_diameter = ball;
  o.stylus_diameter = ball / 2;
  o.border = 0.2;
  o.min_per_region = 5;
  o.points = 60;
  return o;
}

// Plan points per region, counted from the plan itself.
std::map<int, int> recount(const PlanResult& r) {
  std::map<int, int> n;
  for (const PlannedPoint& p : r.plan.points) ++n[*p.region];
  return n;
}

}  // namespace

TEST_CASE("coverage counts every region's plan points and names why the groove is short") {
  const Part part = groove_part(1.0);
  const RegionMap map = partition_of(part, 60, 60);
  const PlanResult r = plan_probe_points(part, map, groove_options(4));
  const PlanCoverage c = plan_coverage(r, 5);
  const std::map<int, int> counted = recount(r);
  REQUIRE(c.regions.size() == map.regions.size());
  int covered = 0, groove_short = 0;
  long planned = 0;
  for (const RegionCoverage& rc : c.regions) {
    const int n = counted.count(rc.region) ? counted.at(rc.region) : 0;
    CHECK(rc.planned == n);
    CHECK(rc.required == 5);
    CHECK(rc.covered == (n >= 5));
    CHECK(rc.face == map.regions[static_cast<std::size_t>(rc.region)].face);
    covered += rc.covered;
    planned += n;
    if (!rc.covered) {
      CHECK(!rc.reason.empty());
      if (rc.face == 1) {
        ++groove_short;
        CHECK(rc.reason.find("cannot reach") != std::string::npos);
        CHECK((rc.reason.find("ball") != std::string::npos || rc.reason.find("tilt") != std::string::npos));
      }
    } else {
      CHECK(rc.reason.empty());
    }
  }
  CHECK(groove_short >= 1);  // the groove's bottom is out of reach
  CHECK(c.regions_covered == covered);
  CHECK(c.planned == planned);
  CHECK(c.planned == static_cast<long>(r.plan.points.size()));
  CHECK(!c.complete());
  // Per face: the sums of its regions.
  for (const FaceCoverage& f : c.faces) {
    int regions = 0, planned_on_face = 0;
    for (const PlannedPoint& p : r.plan.points) planned_on_face += static_cast<int>(p.face_index) == f.face;
    for (const Region& region : map.regions) regions += region.face == f.face;
    CHECK(f.regions == regions);
    CHECK(f.planned == planned_on_face);
  }
  const std::string text = c.describe_uncovered(1);
  CHECK(text.find("region ") == 2);
  if (c.uncovered().size() > 1) CHECK(text.find("more (report.json") != std::string::npos);

  // A ball that fits covers every region; no minimum covers any plan.
  const PlanResult fits = plan_probe_points(part, map, groove_options(1));
  CHECK(plan_coverage(fits, 5).complete());
  CHECK(plan_coverage(r, 0).complete());
  CHECK(plan_coverage(r, 0).describe_uncovered().empty());
}

TEST_CASE("coverage by area: each region whole under one state, the states sum to the part") {
  // Four regions built by hand, one a state, areas 10, 20, 30 and 40 mm^2:
  // 0 holds its minimum of 4; 1 was skipped (no ball position measures it);
  // 2 is short because 3 of its points were dropped (2 for the ball, 1 for
  // the tilt); 3 is short because only 2 admissible points fit, none dropped.
  PlanResult r;
  const int planned[] = {4, 0, 2, 2}, dropped[] = {0, 0, 3, 0}, sampled[] = {6, 0, 5, 2};
  for (int k = 0; k < 4; ++k) {
    RegionPlanSummary s;
    s.region = k;
    s.face = k / 2;
    s.area = 10.0 * (k + 1);
    s.allocated = 5;
    s.sampled = sampled[k];
    s.planned = planned[k];
    s.dropped = dropped[k];
    s.samplable = k != 1;
    r.regions.push_back(s);
  }
  PlanIssue skipped;
  skipped.kind = PlanIssue::Kind::region_skipped;
  skipped.region = 1;
  skipped.reason = "too narrow";
  r.issues.push_back(skipped);
  for (const AccessProblem problem : {AccessProblem::ball, AccessProblem::tilt, AccessProblem::ball}) {
    PlanIssue d;
    d.kind = PlanIssue::Kind::dropped;
    d.region = 2;
    d.problem = problem;
    r.issues.push_back(d);
  }
  const PlanCoverage c = plan_coverage(r, 4);
  REQUIRE(c.regions.size() == 4);
  CHECK(c.regions[0].state == CoverageState::covered);
  CHECK(c.regions[1].state == CoverageState::unreachable_narrow);
  CHECK(c.regions[2].state == CoverageState::unreachable_access);
  CHECK(c.regions[2].access == AccessProblem::ball);
  CHECK(c.regions[3].state == CoverageState::reachable_unplanned);
  CHECK(c.area.total == 100.0);
  CHECK(c.area.covered == 10.0);
  CHECK(c.area.unreachable_narrow == 20.0);
  CHECK(c.area.unreachable_access == 30.0);
  CHECK(c.area.reachable_unplanned == 40.0);
  REQUIRE(c.area.by_access_problem.size() == 1);
  CHECK(c.area.by_access_problem[0] == std::pair<AccessProblem, double>(AccessProblem::ball, 30.0));
  CHECK(c.area.share_covered() == 0.1);
  // A region with every point dropped is out of reach however few it needed.
  r.regions[3].dropped = 1;
  r.regions[3].planned = 0;
  r.issues[1].region = 3;
  const PlanCoverage none = plan_coverage(r, 4);
  CHECK(none.regions[3].state == CoverageState::unreachable_access);
  CHECK(none.regions[3].access == AccessProblem::ball);

  // The groove: the states add up to the part's area as the region map
  // measures it, and the groove's bottom is out of the 4 mm ball's reach.
  const Part part = groove_part(1.0);
  const RegionMap map = partition_of(part, 60, 60);
  const PlanCoverage g = plan_coverage(plan_probe_points(part, map, groove_options(4)), 5);
  double map_area = 0;
  for (const Region& region : map.regions) map_area += region.area;
  const CoverageArea& a = g.area;
  CHECK(std::abs(a.total - map_area) <= 1e-9 * map_area);
  CHECK(std::abs(a.covered + a.reachable_unplanned + a.unreachable_narrow + a.unreachable_access - a.total) <=
        1e-9 * a.total);
  CHECK(a.unreachable_access > 0);
  double by_problem = 0;
  for (const auto& [problem, area] : a.by_access_problem) by_problem += area;
  CHECK(std::abs(by_problem - a.unreachable_access) <= 1e-9 * a.total);
  const PlanCoverage fits = plan_coverage(plan_probe_points(part, map, groove_options(1)), 5);
  CHECK(fits.area.covered == fits.area.total);
}

TEST_CASE("coverage.png shows the groove's bottom out of reach of a 4 mm ball, and nothing out of reach of a 1 mm ball") {
  // Pixels by hue, which shading does not change: out of reach is red
  // (green and blue under 40 % of red), covered green (green over 1.5 x red).
  auto count = [](const std::vector<unsigned char>& png, bool red) {
    const cv::Mat img = cv::imdecode(png, cv::IMREAD_COLOR);
    REQUIRE_FALSE(img.empty());
    int n = 0;
    for (int y = 0; y < img.rows; ++y)
      for (int x = 0; x < img.cols; ++x) {
        const cv::Vec3b bgr = img.at<cv::Vec3b>(y, x);
        const double b = bgr[0], g = bgr[1], r = bgr[2];
        if (red ? (r > 60 && g < 0.4 * r && b < 0.4 * r) : (g > 60 && g > 1.5 * r && g > 1.5 * b)) ++n;
      }
    return n;
  };
  const Part part = groove_part(1.0);
  const RegionMap map = partition_of(part, 60, 60);
  const PlanResult short_plan = plan_probe_points(part, map, groove_options(4));
  const PlanCoverage short_coverage = plan_coverage(short_plan, 5);
  REQUIRE(short_coverage.area.unreachable_access > 0);
  const std::vector<unsigned char> png = coverage_image_png(part, map, short_plan, short_coverage);
  CHECK(png == coverage_image_png(part, map, short_plan, short_coverage));  // deterministic
  CHECK(count(png, true) > 100);
  CHECK(count(png, false) > 100);
  const PlanResult fits = plan_probe_points(part, map, groove_options(1));
  const PlanCoverage fits_coverage = plan_coverage(fits, 5);
  REQUIRE(fits_coverage.complete());
  const std::vector<unsigned char> all = coverage_image_png(part, map, fits, fits_coverage);
  CHECK(count(all, true) == 0);
  CHECK(count(all, false) > 100);
}

TEST_CASE("furrow plan exits 1 naming an uncovered region, 0 with --allow-uncovered, and compare cannot pass it") {
  const std::string dir = scratch_dir("cli-plan-coverage");
  write_part_json(groove_part(1.0), dir + "/groove.json");
  REQUIRE(run_furrow({"partition", dir + "/groove.json", "--out", dir + "/regions.json", "--grid", "60x60"}).status == 0);
  const std::vector<std::string> plan{"plan", dir + "/groove.json", "--regions", dir + "/regions.json", "--points", "60",
                                      "--border", "0.2", "--probe-diameter", "4", "--stylus-diameter", "2"};
  auto with = [&](std::vector<std::string> args, std::initializer_list<const char*> more) {
    for (const char* m : more) args.push_back(m);
    return args;
  };
  const CliResult strict = run_furrow(with(plan, {"--out", (dir + "/strict").c_str()}));
  CHECK(strict.status == 1);
  CHECK(strict.err.find("fewer points than the minimum:") != std::string::npos);
  CHECK(strict.err.find("(face 1): 0 of 5 points") != std::string::npos);
  CHECK(strict.err.find("--allow-uncovered") != std::string::npos);
  CHECK(fs::exists(dir + "/strict/plan.json"));  // the plan is still written

  const CliResult allowed = run_furrow(with(plan, {"--out", (dir + "/allowed").c_str(), "--allow-uncovered"}));
  REQUIRE(allowed.status == 0);
  CHECK(allowed.out.find("accepted with --allow-uncovered") != std::string::npos);
  CHECK(slurp(dir + "/strict/plan.json") == slurp(dir + "/allowed/plan.json"));

  // report.json and plan.json agree with a recount of the plan's points.
  const auto report = nlohmann::json::parse(slurp(dir + "/allowed/report.json"));
  const InspectionPlan p = read_plan(dir + "/allowed/plan.json");
  std::map<int, int> counted;
  for (const PlannedPoint& q : p.points) ++counted[*q.region];
  const auto& cov = report["coverage"];
  CHECK(cov["complete"] == false);
  CHECK(cov["planned"] == p.points.size());
  REQUIRE(cov["uncovered_regions"].size() == p.uncovered_regions.size());
  REQUIRE(!p.uncovered_regions.empty());
  int regions_short = 0;
  for (const auto& rs : report["regions"]) regions_short += rs["planned"].get<int>() < 5;
  CHECK(static_cast<int>(p.uncovered_regions.size()) == regions_short);
  for (std::size_t k = 0; k < p.uncovered_regions.size(); ++k) {
    const UncoveredRegion& u = p.uncovered_regions[k];
    CHECK(u.planned == counted[u.region]);
    CHECK(u.required == 5);
    CHECK(cov["uncovered_regions"][k]["region"] == u.region);
    CHECK(cov["uncovered_regions"][k]["reason"] == u.reason);
  }
  CHECK(parse_plan(plan_to_json_text(p), "again").uncovered_regions.size() == p.uncovered_regions.size());

  // Measured exactly as planned: every measured region is in tolerance, but
  // the uncovered ones were never seen, so the verdict is INCONCLUSIVE.
  REQUIRE(run_furrow({"simulate-measurement", dir + "/groove.json", "--plan", dir + "/allowed/plan.json", "--out",
                      dir + "/measured.csv", "--noise", "0", "--seed", "3"})
              .status == 0);
  const CliResult compared = run_furrow({"compare", dir + "/groove.json", "--plan", dir + "/allowed/plan.json",
                                         "--measurements", dir + "/measured.csv", "--out", dir + "/comparison.json"});
  CHECK(compared.status == 4);
  const auto comparison = nlohmann::json::parse(slurp(dir + "/comparison.json"));
  const std::string text = comparison.dump();
  CHECK(text.find("region_below_minimum") != std::string::npos);
  CHECK(text.find("region " + std::to_string(p.uncovered_regions.front().region) + " has 0 evaluated points") !=
        std::string::npos);

  // Re-measuring cannot cover it: the plan holds no point there. It says so
  // with the planner's reason instead of planning nothing in silence.
  const CliResult again = run_furrow({"remeasure", dir + "/comparison.json", "--plan", dir + "/allowed/plan.json",
                                      "--out", dir + "/remeasure"});
  CHECK(again.status == 0);
  CHECK(again.out.find("not covered by re-measuring: region " + std::to_string(p.uncovered_regions.front().region)) !=
        std::string::npos);
  CHECK(again.out.find("the planner could not cover it: " + p.uncovered_regions.front().reason) != std::string::npos);
  CHECK(!fs::exists(dir + "/remeasure"));
}
