// furrow plan end to end: the folder and its files, byte-identical reruns,
// and bad input refused with one line, exit status 2 and no folder.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "partition/regions_file.hpp"
#include "prediction_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

// regions.json of the mould, made once per test run by the CLI itself.
std::string mould_regions() {
  static const std::string path = [] {
    const std::string dir = scratch_dir("cli-plan-regions-" + std::to_string(::getpid()));
    const CliResult r = run_furrow({"partition", source_path("examples/parts/mould.json"), "--out", dir + "/regions.json",
                                    "--grid", "200x160"});
    REQUIRE(r.status == 0);
    return dir + "/regions.json";
  }();
  return path;
}

}  // namespace

TEST_CASE("furrow plan writes the plan folder, and the same seed gives the same bytes") {
  const std::string dir = scratch_dir("cli-plan");
  const std::string part = source_path("examples/parts/mould.json");
  const std::vector<std::string> args{"plan", part, "--regions", mould_regions(), "--out", dir + "/mould_a",
                                      "--points", "120", "--seed", "7"};
  const CliResult r = run_furrow(args);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());  // not a terminal: no progress
  CHECK(r.out.find("plan: 120 points in 7 regions") != std::string::npos);
  for (const char* f : {"plan.json", "plan.csv", "mould_a.dmi", "mould_a.prg", "plan.png", "coverage.png", "report.json"})
    CHECK(fs::exists(dir + "/mould_a/" + f));
  const InspectionPlan plan = read_plan(dir + "/mould_a/plan.json");
  CHECK(plan.points.size() == 120);
  check_plan_against_part(plan, read_part(part), "plan.json", 1e-9);
  const ProbeProgram dmis = read_dmis_program(dir + "/mould_a/mould_a.dmi");
  const ProbeProgram ipp = read_ippdme_program(dir + "/mould_a/mould_a.prg");
  REQUIRE(dmis.steps.size() == 120);
  REQUIRE(ipp.steps.size() == 120);
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const PlannedPoint& p = *std::find_if(plan.points.begin(), plan.points.end(),
                                          [&](const PlannedPoint& q) { return q.order == static_cast<int>(k) + 1; });
    CHECK(dmis.steps[k].point.id == p.id);
    CHECK((dmis.steps[k].point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((ipp.steps[k].point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((dmis.steps[k].moves_before.back() - p.approach).cwiseAbs().maxCoeff() <= 5e-7);
  }
  const auto report = nlohmann::json::parse(slurp(dir + "/mould_a/report.json"));
  CHECK(report["points"] == 120);
  CHECK(report["options"]["strategy"] == "hammersley");
  CHECK(report["tour"]["optimised_mm"].get<double>() <= report["tour"]["nearest_neighbour_mm"].get<double>());

  // A second run (the first folder moved aside): the same bytes in every file.
  fs::rename(dir + "/mould_a", dir + "/first");
  REQUIRE(run_furrow(args).status == 0);
  for (const char* f : {"plan.json", "plan.csv", "mould_a.dmi", "mould_a.prg", "plan.png", "coverage.png", "report.json"})
    CHECK(slurp(dir + "/first/" + f) == slurp(dir + "/mould_a/" + f));
}

TEST_CASE("furrow plan: bad input gives one line, exit 2 and no output folder") {
  const std::string dir = scratch_dir("cli-plan-bad");
  const std::string part = source_path("examples/parts/mould.json");
  const std::string other = source_path("examples/parts/quarter_cylinder.json");
  struct Case {
    std::vector<std::string> extra;
    std::string part;
    const char* message;
  };
  const Case cases[] = {
      {{}, other, "another part"},
      {{"--points", "0"}, part, "--points: must be at least 1"},
      {{"--probe-diameter", "-2"}, part, "--probe-diameter"},
      {{"--stylus-diameter", "0"}, part, "--stylus-diameter"},
      {{"--points", "10", "--density", "2"}, part, "exclude each other"},
      {{"--strategy", "sobol"}, part, "unknown strategy"},
      {{"--strategy", "risk"}, part, "needs a machining prediction (--prediction)"},
      {{"--max-tilt", "200"}, part, "--max-tilt"},
      {{"--border", "80"}, part, "--border"},
      {{"--seed", "-1"}, part, "--seed"},
      {{"--bogus", "1"}, part, "unknown option"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"plan", c.part, "--regions", mould_regions(), "--out", dir + "/out"};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const CliResult r = run_furrow(args);
    CAPTURE(c.message);
    CHECK(r.status == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
  // Found in the middle of planning (no region is wide enough for the
  // border): the message still names the part and the regions it came from.
  const CliResult wide = run_furrow({"plan", part, "--regions", mould_regions(), "--out", dir + "/out", "--border", "80"});
  CHECK(wide.status == 2);
  CHECK(wide.err.find("error: " + part + " with " + mould_regions() + ": no region can hold a probe point") !=
        std::string::npos);
  const CliResult missing = run_furrow({"plan", part, "--regions", dir + "/none.json", "--out", dir + "/out"});
  CHECK(missing.status == 2);
  CHECK_FALSE(fs::exists(dir + "/out"));
}

TEST_CASE("furrow plan --prediction: points on the gouge sites, risk strategy, another part's prediction refused") {
  const std::string dir = scratch_dir("cli-plan-prediction");
  const std::string part_path = source_path("examples/parts/mould.json");
  const Part part = read_part(part_path);
  write_prediction(synthetic_prediction(part, {0.3, 0.45}, {{0.3, 0.45}, {0.7, 0.3}}), dir + "/prediction.json");
  for (const char* strategy : {"hammersley", "risk"}) {
    const std::string out = dir + "/" + strategy;
    const CliResult r = run_furrow({"plan", part_path, "--regions", mould_regions(), "--out", out, "--prediction",
                                    dir + "/prediction.json", "--strategy", strategy, "--gouge-points", "2"});
    REQUIRE(r.status == 0);
    const auto report = nlohmann::json::parse(slurp(out + "/report.json"));
    CHECK(report["prediction_file"] == dir + "/prediction.json");
    CHECK(report["gouge_site_points"].size() == 4);
    const InspectionPlan plan = read_plan(out + "/plan.json");
    for (const auto& g : report["gouge_site_points"]) {
      const auto k = plan.find(g["point"].get<std::string>());
      REQUIRE(k.has_value());
      const Eigen::Vector2d centre = g["gouge_site"] == "G1" ? Eigen::Vector2d(0.3, 0.45) : Eigen::Vector2d(0.7, 0.3);
      CHECK((plan.points[*k].uv - centre).cwiseAbs().maxCoeff() <= 0.01);
    }
  }
  const Part other = read_part(source_path("examples/parts/semi_cylinder.json"));
  write_prediction(synthetic_prediction(other, {0.5, 0.5}, {}), dir + "/other.json");
  const CliResult bad = run_furrow({"plan", part_path, "--regions", mould_regions(), "--out", dir + "/bad", "--prediction",
                                    dir + "/other.json"});
  CHECK(bad.status == 2);
  CHECK(line_count(bad.err) == 1);
  CHECK(bad.err.find("another part") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/bad"));
}

TEST_CASE("furrow plan names the faces whose normals point into the material when it drops their points") {
  // The two-face example with both faces reversed: what an IGES surface
  // model with normals into the material looks like to the planner.
  const std::string dir = scratch_dir("cli-plan-orientation");
  auto doc = nlohmann::json::parse(slurp(source_path("examples/parts/two_face.json")));
  for (auto& face : doc["faces"]) face["reversed"] = true;
  write_text(dir + "/flipped.json", doc.dump());
  REQUIRE(run_furrow({"partition", dir + "/flipped.json", "--out", dir + "/flipped_regions.json"}).status == 0);
  const CliResult flipped = run_furrow(
      {"plan", dir + "/flipped.json", "--regions", dir + "/flipped_regions.json", "--out", dir + "/flipped_plan"});
  CHECK(flipped.status == 2);
  CHECK(!fs::exists(dir + "/flipped_plan"));
  CHECK(flipped.err.find("face 0 \"valley_wall\" (100 % of its") != std::string::npos);
  CHECK(flipped.err.find("face 1 \"crown\" (100 % of its") != std::string::npos);
  CHECK(flipped.err.find("normals into the material?") != std::string::npos);

  // The same part as it should be: no face is named.
  REQUIRE(run_furrow({"partition", source_path("examples/parts/two_face.json"), "--out", dir + "/regions.json"}).status ==
          0);
  const CliResult ok = run_furrow(
      {"plan", source_path("examples/parts/two_face.json"), "--regions", dir + "/regions.json", "--out", dir + "/plan"});
  REQUIRE(ok.status == 0);
  CHECK(ok.out.find("orientation:") == std::string::npos);
  const auto report = nlohmann::json::parse(slurp(dir + "/plan/report.json"));
  for (const auto& issue : report["issues"]) CHECK(issue["kind"] != "face_facing_down");
}
