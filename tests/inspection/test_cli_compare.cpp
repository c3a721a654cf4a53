// End-to-end: furrow simulate-measurement and furrow compare as a user runs
// them; bad input files of each kind end with one error naming file:line
// (or the JSON field), exit status 2 and no output written.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "partition/regions_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

// A grid plan of the mould in a fresh scratch folder.
std::string write_mould_plan(const std::string& dir, int nu = 24, int nv = 20) {
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, nu, nv, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, dir + "/plan.json");
  return dir + "/plan.json";
}

// Runs compare on a measurement file that must be refused.
void expect_refused(const std::string& dir, const std::string& file, const std::string& text,
                    const std::string& message) {
  const std::string path = dir + "/" + file;
  test::write_text(path, text);
  const std::string out = dir + "/refused.json";
  const auto r = test::run_furrow(
      {"compare", kMould, "--measurements", path, "--probe-diameter", "2", "--out", out});
  CAPTURE(text);
  CHECK(r.status == 2);
  CHECK(r.err == "error: " + path + message + "\n");
  CHECK(test::line_count(r.err) == 1);
  CHECK_FALSE(fs::exists(out));
}

}  // namespace

TEST_CASE("simulate-measurement then compare: the misalignment comes back, same bytes every run") {
  const std::string dir = test::scratch_dir("cli-compare-roundtrip");
  const std::string plan = write_mould_plan(dir);
  const auto sim = test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--misalign",
                                     "2,-3,90,120,-40,15", "--outliers", "12", "--seed", "3",
                                     "--out", dir + "/m.csv"});
  REQUIRE(sim.status == 0);
  const auto a = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan",
                                   plan, "--tolerance", "0.05", "--out", dir + "/a.json"});
  // Nothing out of tolerance, but 12 points the outlier rule set aside as
  // blunders lie outside the zone: INCONCLUSIVE until they are re-measured.
  CHECK(a.status == 4);
  CHECK(a.out.find("INCONCLUSIVE") != std::string::npos);
  const json_fields::json doc = json_fields::load_file(dir + "/a.json");
  CHECK(doc["summary"]["pass"] == false);
  CHECK(doc["summary"]["verdict"] == "INCONCLUSIVE");
  CHECK(doc["summary"]["out_of_tolerance"] == 0);
  CHECK(doc["summary"]["outliers"] == 12);
  REQUIRE(doc["summary"]["inconclusive"].size() == 12);
  for (const auto& reason : doc["summary"]["inconclusive"]) {
    CHECK(reason["kind"] == "suspected_blunder");
    bool is_blunder = false;  // the subject is a point the fit flagged as a blunder
    for (const auto& p : doc["points"])
      if (p["id"] == reason["subject"]) is_blunder = !p["outlier"].is_null() && p["outlier"]["reason"] == "blunder";
    CHECK(is_blunder);
  }
  CHECK(doc["points"].size() == 480);
  const auto placement = doc["registration"]["placement"];
  CHECK(placement["rotation_deg"][2].get<double>() == doctest::Approx(90).epsilon(1e-3));
  CHECK(placement["translation"][0].get<double>() == doctest::Approx(120).epsilon(1e-4));
  CHECK(doc["registration"]["coarse"]["method"] == "plan ids");
  // Deterministic output, also without the plan's ids (global search).
  const auto b = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan",
                                   plan, "--tolerance", "0.05", "--out", dir + "/b.json"});
  CHECK(test::slurp(dir + "/a.json") == test::slurp(dir + "/b.json"));
  const auto anon = test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--misalign",
                                      "2,-3,180,120,-40,15", "--seed", "3", "--anonymous", "--out",
                                      dir + "/anon.csv"});
  REQUIRE(anon.status == 0);
  const auto c = test::run_furrow({"compare", kMould, "--measurements", dir + "/anon.csv",
                                   "--probe-diameter", "2", "--out", dir + "/c.json"});
  CHECK(c.status == 0);
  const json_fields::json cdoc = json_fields::load_file(dir + "/c.json");
  CHECK(cdoc["registration"]["coarse"]["method"] == "global search");
  CHECK(std::abs(std::abs(cdoc["registration"]["placement"]["rotation_deg"][2].get<double>()) -
                 180) < 0.05);
}

TEST_CASE("compare: out of tolerance is exit status 1, locked DOF and loss options are honoured") {
  const std::string dir = test::scratch_dir("cli-compare-fail");
  const std::string plan = write_mould_plan(dir);
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--noise", "0.004",
                            "--out", dir + "/m.csv"})
              .status == 0);
  const auto tight =
      test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan,
                        "--tolerance", "0.005", "--out", dir + "/t.json"});
  CHECK(tight.status == 1);
  CHECK(tight.out.find("FAIL") != std::string::npos);
  const auto locked =
      test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan,
                        "--dof", "tx,ty,rz", "--loss", "huber", "--out", dir + "/l.json"});
  CHECK(locked.status == 0);
  const json_fields::json doc = json_fields::load_file(dir + "/l.json");
  CHECK(doc["registration"]["dof"] == json_fields::json({"rz", "tx", "ty"}));
  CHECK(doc["registration"]["transform"][2][3].get<double>() == 0.0);
  CHECK(doc["registration"]["coarse"]["method"] == "identity");
}

TEST_CASE("bad measurement files: file:line, exit 2, nothing written") {
  const std::string dir = test::scratch_dir("cli-compare-bad-measurements");
  expect_refused(dir, "dup.csv", "id,x,y,z\nA,1,2,3\nA,4,5,6\n",
                 ":3: duplicate id \"A\" (first on line 2)");
  expect_refused(dir, "nan.csv", "id,x,y,z\nA,1,NaN,3\n",
                 ":2: column 3 (y): \"NaN\" is not a finite number");
  expect_refused(dir, "cols.csv", "id,x,z\nA,1,3\n", ":1: missing column \"y\" (need x, y, z)");
  expect_refused(dir, "text.csv", "id,x,y,z\nA,1,two,3\n", ":2: column 3 (y): \"two\" is not a number");
  expect_refused(dir, "short.csv", "id,x,y,z\nA,1,2\n", ":2: expected 4 fields, got 3");
  expect_refused(dir, "scan.xyz", "1 2 3\n4 5 x\n", ":2: field 3: \"x\" is not a number");
  expect_refused(
      dir, "run.res",
      "UNITS/MM\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
      ":3: duplicate id \"P1\" (first on line 2)");
  expect_refused(dir, "nan.res", "FA(P1)=FEAT/POINT,CART,1,nan,3,0,0,1\n",
                 ":1: value 2: \"nan\" is not a finite number");
}

TEST_CASE("bad plans, options and outputs: one error, exit 2, nothing written") {
  const std::string dir = test::scratch_dir("cli-compare-bad-other");
  const std::string plan = write_mould_plan(dir, 6, 5);
  REQUIRE(
      test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--out", dir + "/m.csv"})
          .status == 0);
  const std::string out = dir + "/out.json";
  auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
    const auto r = test::run_furrow(args);
    CAPTURE(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(test::line_count(r.err) == 1);
    CHECK_FALSE(fs::exists(out));
  };
  std::string text = test::slurp(plan);
  text.replace(text.find("\"order\": 2"), 10, "\"order\": 1");
  test::write_text(dir + "/dup_order.json", text);
  refused({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", dir + "/dup_order.json",
           "--out", out},
          "dup_order.json: points[1].order: duplicate order 1 (also points[0])");
  refused({"compare", test::source_path("examples/parts/two_face.json"), "--measurements",
           dir + "/m.csv", "--plan", plan, "--out", out},
          "face \"mould\" but face 0 of the part is \"valley_wall\"");
  refused({"compare", kMould, "--measurements", dir + "/m.csv", "--out", out},
          "the probe diameter is needed");
  refused({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan, "--dof", "tx,tw",
           "--out", out},
          "--dof: \"tw\" is not a degree of freedom");
  refused({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan, "--outside", "0.2",
           "--out", out},
          "the outside part of the zone must lie between 0 and the tolerance");
  refused({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan, "--out",
           dir + "/m.csv"},
          "m.csv");
  refused({"compare", kMould, "--plan", plan, "--out", out}, "--measurements");
  refused({"simulate-measurement", kMould, "--plan", plan, "--misalign", "1,2,3", "--out", out},
          "--misalign expects 6 comma-separated numbers");
  refused({"simulate-measurement", kMould, "--plan", plan, "--outliers", "31", "--out", dir + "/refused.csv"},
          "31 blunders but the plan has 30 points");
  CHECK_FALSE(fs::exists(dir + "/refused.csv"));
  // A name whose format has no writer is refused before anything is written.
  refused({"simulate-measurement", kMould, "--plan", plan, "--out", dir + "/m.xyz"},
          "\".xyz\" is none of them");
  CHECK_FALSE(fs::exists(dir + "/m.xyz"));
}

TEST_CASE("compare --regions: each point in the region of its foot point, statistics per region") {
  const std::string dir = test::scratch_dir("cli-compare-regions");
  const std::string plan = write_mould_plan(dir, 20, 16);
  REQUIRE(test::run_furrow({"partition", kMould, "--grid", "50x40", "--out", dir + "/regions.json"})
              .status == 0);
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--misalign",
                            "1,2,40,5,6,7", "--noise", "0.003", "--outliers", "3", "--out",
                            dir + "/m.csv"})
              .status == 0);
  const auto r = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan",
                                   plan, "--regions", dir + "/regions.json", "--tolerance",
                                   "0.012", "--out", dir + "/c.json"});
  CAPTURE(r.err);
  REQUIRE((r.status == 0 || r.status == 1));
  const ComparisonDocument d = read_comparison(dir + "/c.json");
  CHECK(d.sources.regions == dir + "/regions.json");
  const RegionMap map = read_regions(dir + "/regions.json");
  // Oracle: region_at of each foot as written, and the statistics recomputed
  // from the points' deviations by brute force.
  std::map<int, std::vector<double>> by_region;
  std::map<int, std::size_t> out;
  for (const ComparisonDocument::Point& p : d.points) {
    CHECK(p.region == map.region_at(p.face_index, p.uv.x(), p.uv.y()));
    if (!p.evaluated || !p.region) continue;
    by_region[*p.region].push_back(p.deviation);
    out[*p.region] += !*p.in_tolerance;
  }
  REQUIRE(d.summary.regions.size() == by_region.size());
  CHECK(by_region.size() >= 4);
  std::size_t k = 0;
  for (const auto& [id, values] : by_region) {
    const RegionStatistics& s = d.summary.regions[k++];
    CHECK(s.region == id);
    CHECK(s.deviations.count == values.size());
    double sum = 0, lo = values[0], hi = values[0];
    for (double v : values) sum += v, lo = std::min(lo, v), hi = std::max(hi, v);
    const double mean = sum / values.size();
    double ss = 0;
    for (double v : values) ss += (v - mean) * (v - mean);
    CHECK(s.deviations.mean == doctest::Approx(mean).epsilon(1e-12));
    if (values.size() > 1)
      CHECK(s.deviations.sigma == doctest::Approx(std::sqrt(ss / (values.size() - 1))).epsilon(1e-12));
    CHECK(s.deviations.min == lo);
    CHECK(s.deviations.max == hi);
    CHECK(s.out_of_tolerance == out[id]);
  }

  // A partition of another part is refused before anything is written.
  REQUIRE(test::run_furrow({"partition", test::source_path("examples/parts/two_face.json"),
                            "--out", dir + "/other.json"})
              .status == 0);
  const auto bad = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan",
                                     plan, "--regions", dir + "/other.json", "--out",
                                     dir + "/bad.json"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("other.json") != std::string::npos);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_FALSE(fs::exists(dir + "/bad.json"));
}
