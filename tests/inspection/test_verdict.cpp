// The three-state verdict end to end: what was not shown to be good is never
// PASS. Each case plants one known cause (a one-point dent, an undetermined
// alignment) and checks that the verdict names it.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <utility>

#include "base/json_fields.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

std::string write_grid_plan(const std::string& dir, int nu, int nv) {
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, nu, nv, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, dir + "/plan.json");
  return dir + "/plan.json";
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

TEST_CASE("verdict: a dent seen by one probe point is INCONCLUSIVE and names the point to re-measure") {
  const std::string dir = test::scratch_dir("verdict-dent");
  const std::string plan_path = write_grid_plan(dir, 12, 10);  // points about 8 mm apart
  const InspectionPlan plan = read_plan(plan_path);
  // A dent 6 mm across and 80 um deep centred on one planned point: no
  // neighbour sees it, so the outlier rule cannot confirm it.
  const PlannedPoint& target = plan.points[plan.points.size() / 2 + 3];
  const std::string bump = number(target.xyz.x()) + "," + number(target.xyz.y()) + "," + number(target.xyz.z()) +
                           ",3,-0.08";
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan_path, "--noise", "0.002", "--outliers",
                            "0", "--bump", bump, "--out", dir + "/m.csv"})
              .status == 0);
  const test::CliResult r = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan",
                                              plan_path, "--tolerance", "0.05", "--out", dir + "/c.json"});
  INFO(r.out << r.err);
  CHECK(r.status == 4);
  CHECK(r.out.find("INCONCLUSIVE") != std::string::npos);
  CHECK(r.out.find("re-measure point " + target.id) != std::string::npos);
  const ComparisonDocument doc = read_comparison(dir + "/c.json");
  CHECK(doc.summary.verdict == Verdict::inconclusive);
  CHECK_FALSE(doc.summary.pass);
  REQUIRE(doc.summary.inconclusive.size() == 1);
  CHECK(doc.summary.inconclusive[0].kind == "suspected_blunder");
  CHECK(doc.summary.inconclusive[0].subject == target.id);
  CHECK(doc.summary.out_of_tolerance == 0);  // nothing was shown to be bad

  // The same measurement without the dent passes: the dent alone made the
  // difference.
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan_path, "--noise", "0.002", "--outliers",
                            "0", "--out", dir + "/clean.csv"})
              .status == 0);
  const test::CliResult clean = test::run_furrow({"compare", kMould, "--measurements", dir + "/clean.csv", "--plan",
                                                  plan_path, "--tolerance", "0.05", "--out", dir + "/clean.json"});
  CHECK(clean.status == 0);
  CHECK(read_comparison(dir + "/clean.json").summary.verdict == Verdict::pass);

  // The report of the comparison says INCONCLUSIVE with the reason, exit 4.
  const test::CliResult report = test::run_furrow({"report", dir + "/c.json", "--out", dir + "/report"});
  CHECK(report.status == 4);
  const json_fields::json rj = json_fields::load_file(dir + "/report/report.json");
  CHECK(rj["verdict"]["result"] == "INCONCLUSIVE");
  REQUIRE(rj["verdict"]["inconclusive"].size() == 1);
  CHECK(rj["verdict"]["inconclusive"][0]["subject"] == target.id);
  CHECK(test::slurp(dir + "/report/report.html").find("class=\"verdict inconclusive\"") != std::string::npos);
}

TEST_CASE("verdict: identical or collinear points never PASS (weakly constrained: exit 3)") {
  const std::string dir = test::scratch_dir("verdict-degenerate");
  const std::string plan_path = write_grid_plan(dir, 12, 10);
  const InspectionPlan plan = read_plan(plan_path);
  // Contact points on the nominal surface, in the part frame: every point
  // has deviation 0, so only the alignment can stop a PASS.
  const Eigen::Vector3d a = plan.points[30].xyz;
  const Eigen::Vector3d b = plan.points[31].xyz;
  std::string identical = "id,x,y,z\n", collinear = "id,x,y,z\n";
  for (int k = 0; k < 40; ++k)
    identical += "Q" + std::to_string(k) + "," + number(a.x()) + "," + number(a.y()) + "," + number(a.z()) + "\n";
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d p = a + (b - a) * (k / 19.0);  // a chord: off the surface between a and b
    collinear += "L" + std::to_string(k) + "," + number(p.x()) + "," + number(p.y()) + "," + number(p.z()) + "\n";
  }
  test::write_text(dir + "/identical.csv", identical);
  test::write_text(dir + "/collinear.csv", collinear);
  auto compare = [&](const std::string& name) {
    const test::CliResult r =
        test::run_furrow({"compare", kMould, "--measurements", dir + "/" + name + ".csv", "--points", "contact",
                          "--tolerance", "1", "--out", dir + "/" + name + ".json"});
    INFO(r.out << r.err);
    CHECK(r.out.find("PASS") == std::string::npos);
    return std::make_pair(r.status, read_comparison(dir + "/" + name + ".json"));
  };
  {  // 40 copies of one point: every deviation 0; only the motion along the
     // normal is fixed, and the mould's face would fix the other five.
    const auto [status, doc] = compare("identical");
    CHECK(status == 3);
    CHECK(doc.summary.verdict == Verdict::inconclusive);
    CHECK(doc.summary.alignment == "weakly_constrained");
    REQUIRE(doc.summary.inconclusive.size() == 1);
    CHECK(doc.summary.inconclusive[0].kind == "alignment_failed");
    CHECK(doc.registration.fitted_dof == 1);
    std::size_t from_points = 0;
    for (const auto& w : doc.registration.weak) from_points += w.from_points;
    CHECK(from_points == 5);
  }
  {  // points on one line: at least the turn about the line is free
    const auto [status, doc] = compare("collinear");
    CHECK(status == 3);
    CHECK(doc.summary.verdict == Verdict::inconclusive);
    CHECK(doc.summary.alignment != "ok");
  }
}

TEST_CASE("verdict: a plan region with fewer evaluated points than its minimum is INCONCLUSIVE and named") {
  const std::string dir = test::scratch_dir("verdict-region-minimum");
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, 12, 10, {"ruby 2 mm", 2});
  plan.part = kMould;
  // Region 1: all points but the last three; region 2: those three, so its
  // minimum is min(3, 5) = 3 (region_minimums).
  for (std::size_t k = 0; k < plan.points.size(); ++k) plan.points[k].region = k + 3 < plan.points.size() ? 1 : 2;
  const std::map<int, std::size_t> minimum = region_minimums(plan);
  CHECK(minimum == std::map<int, std::size_t>{{1, 5}, {2, 3}});
  write_plan(plan, dir + "/plan.json");
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", dir + "/plan.json", "--noise", "0.002",
                            "--outliers", "0", "--out", dir + "/all.csv"})
              .status == 0);
  auto compare = [&](const std::string& name) {
    const test::CliResult r = test::run_furrow({"compare", kMould, "--measurements", dir + "/" + name, "--plan",
                                                dir + "/plan.json", "--out", dir + "/" + name + ".json"});
    INFO(r.out << r.err);
    return r;
  };
  // Every point measured: PASS (the rule does not fire on a complete plan).
  CHECK(compare("all.csv").status == 0);
  // The last planned point (region 2) missing from the file: 2 of 3.
  const std::string all = test::slurp(dir + "/all.csv");
  const std::string last_id = plan.points.back().id;
  const std::size_t at = all.find("\n" + last_id + ",");
  REQUIRE(at != std::string::npos);
  const std::size_t end = all.find('\n', at + 1);
  test::write_text(dir + "/short.csv", all.substr(0, at + 1) + (end == std::string::npos ? "" : all.substr(end + 1)));
  const test::CliResult r = compare("short.csv");
  CHECK(r.status == 4);
  CHECK(r.out.find("region 2 has 2 evaluated points, fewer than the plan's minimum of 3") != std::string::npos);
  const ComparisonDocument doc = read_comparison(dir + "/short.csv.json");
  REQUIRE(doc.summary.inconclusive.size() == 1);
  CHECK(doc.summary.inconclusive[0].kind == "region_below_minimum");
  CHECK(doc.summary.inconclusive[0].subject == "region 2");
  CHECK(doc.summary.evaluated == plan.points.size() - 1);

  // furrow remeasure plans exactly the region's point that was not measured.
  const test::CliResult rm = test::run_furrow({"remeasure", dir + "/short.csv.json", "--out", dir + "/again"});
  INFO(rm.out << rm.err);
  REQUIRE(rm.status == 0);
  const InspectionPlan again = read_plan(dir + "/again/plan.json");
  REQUIRE(again.points.size() == 1);
  CHECK(again.points[0].id == last_id);
  CHECK(again.points[0].xyz == plan.points.back().xyz);
  CHECK(again.points[0].region == std::optional<int>(2));
}
