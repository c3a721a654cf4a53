// `furrow spc` as a quality engineer runs it: 25 parts of the mould stored
// one after another with `furrow compare --db`, a spot wearing in by
// 2.5 um per part under 2 um probing noise. The oracle is built from the
// comparison.json files themselves, not from the database: each point's
// series, its centre and moving-range sigma and its Nelson violations by
// the definitions (tests/results/spc_oracle.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "report_checks.hpp"
#include "results/spc_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow::test;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr int kParts = 25;
constexpr double kWearPerPart = 0.0025;  // mm: the bump's height grows by this per part
constexpr double kBumpRadius = 12;       // mm

struct WearBatch {
  std::string dir, db;
  std::vector<std::string> comparisons;  // by part, oldest first
  std::vector<std::string> worn;         // plan point ids within the bump
};

std::string serial(int part) { return "SN-" + std::to_string(101 + part); }

// `parts` parts stored one after another in a fresh database.
WearBatch make_batch(const std::string& name, int parts) {
  WearBatch b;
  b.dir = scratch_dir(name);
  b.db = b.dir + "/results.db";
  const std::string part = source_path("examples/parts/mould.json");
  REQUIRE(run_furrow({"partition", part, "--out", b.dir + "/regions.json", "--grid", "40x40"}).status == 0);
  REQUIRE(run_furrow({"plan", part, "--regions", b.dir + "/regions.json", "--points", "60", "--out",
                      b.dir + "/plan"}).status == 0);
  const std::string plan = b.dir + "/plan/plan.json";
  // The wear sits on the planned point nearest the mould's middle.
  const json points = json::parse(slurp(plan)).at("points");
  REQUIRE(points.size() >= 40);
  std::vector<double> centre;
  double best = 1e300;
  for (const json& p : points) {
    const double d = std::hypot(p["xyz"][0].get<double>() - 50, p["xyz"][1].get<double>() - 50);
    if (d < best) best = d, centre = p["xyz"].get<std::vector<double>>();
  }
  for (const json& p : points) {
    const double d = std::hypot(p["xyz"][0].get<double>() - centre[0], p["xyz"][1].get<double>() - centre[1],
                                p["xyz"][2].get<double>() - centre[2]);
    if (d < 0.5 * kBumpRadius) b.worn.push_back(p["id"]);  // at least 2/3 of the height
  }
  REQUIRE(!b.worn.empty());
  for (int i = 0; i < parts; ++i) {
    const std::string m = b.dir + "/m" + std::to_string(i) + ".csv";
    char bump[160];
    std::snprintf(bump, sizeof bump, "%.6f,%.6f,%.6f,%g,%g", centre[0], centre[1], centre[2], kBumpRadius,
                  kWearPerPart * (i + 1));
    REQUIRE(run_furrow({"simulate-measurement", part, "--plan", plan, "--out", m, "--seed", std::to_string(i + 1),
                        "--noise", "0.002", "--blunders", "0", "--misalign", "0,0,0,0,0,0", "--bump", bump})
                .status == 0);
    b.comparisons.push_back(b.dir + "/c" + std::to_string(i) + ".json");
    // As measured (the CMM aligned the part): the wear is not fitted away.
    const CliResult c = run_furrow({"compare", part, "--measurements", m, "--plan", plan, "--align", "cmm",
                                    "--out", b.comparisons.back(), "--db", b.db, "--serial", serial(i)});
    REQUIRE_MESSAGE((c.status == 0 || c.status == 1), c.err);
  }
  return b;
}

// The 25-part batch, stored once for every test case of this file that
// reads the series.
const WearBatch& wear_batch() {
  static const WearBatch b = make_batch("cli-spc", kParts);
  return b;
}

// Each evaluated point's deviations over the parts, from the comparisons.
std::map<std::string, std::vector<double>> point_series(const WearBatch& b) {
  std::map<std::string, std::vector<double>> series;
  for (const std::string& c : b.comparisons) {
    const json doc = json::parse(slurp(c));
    for (const json& p : doc["points"])
      if (p["evaluated"].get<bool>()) series[p["id"].get<std::string>()].push_back(p["deviation"].get<double>());
  }
  return series;
}

}  // namespace

TEST_CASE("cli spc: a wearing spot is flagged where the oracle flags it, and the exit status says so") {
  const WearBatch& b = wear_batch();
  const std::string out = b.dir + "/spc";
  const CliResult r = run_furrow({"spc", "--db", b.db, "--out", out});
  REQUIRE_MESSAGE((r.status == 0 || r.status == 1), r.err);
  const json spc = json::parse(slurp(out + "/spc.json"));
  CHECK(fs::exists(out + "/spc.html"));
  CHECK(fs::exists(out + "/spc.qif"));
  REQUIRE(spc["parts"].size() == kParts);
  for (int i = 0; i < kParts; ++i) CHECK(spc["parts"][i]["serial"] == serial(i));

  const auto series = point_series(b);
  REQUIRE(spc["characteristics"].size() == series.size());
  bool latest_violated = false;
  for (const json& c : spc["characteristics"]) {
    const std::string id = c["id"];
    CAPTURE(id);
    const std::vector<double>& x = series.at(id);
    REQUIRE(c["n"] == x.size());
    const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
    // The mean of 25 values read back from the same doubles: a few ulps.
    CHECK(std::abs(c["mean"].get<double>() - centre) < 1e-15);
    std::vector<spc_oracle::Found> found;
    for (const json& v : c["violations"])
      found.push_back({v["rule"].get<int>(), v["index"].get<std::size_t>(), v["last"].get<std::size_t>()});
    const std::vector<spc_oracle::Found> expected = spc_oracle::nelson(x, centre, sigma);
    CHECK(found == expected);
    for (const spc_oracle::Found& f : expected) latest_violated |= f.last + 1 == x.size() && x.size() == kParts;
  }
  // Every worn point drifts by 2.5 um per part against 2 um noise: a run of
  // rises (rule 3) or a value beyond 3 sigma (rule 1) must show.
  for (const std::string& id : b.worn) {
    CAPTURE(id);
    const std::vector<double>& x = series.at(id);
    const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
    bool flagged = false;
    for (const spc_oracle::Found& f : spc_oracle::nelson(x, centre, sigma)) flagged |= f.rule == 1 || f.rule == 3;
    CHECK(flagged);
  }
  CHECK(r.status == (latest_violated ? 1 : 0));
  CHECK(r.out.find("spc: 25 parts (SN-101 .. SN-125)") != std::string::npos);
}

TEST_CASE("cli spc: --serials selects the parts and --by region follows each region's mean deviation") {
  const WearBatch& b = wear_batch();
  const std::string out = b.dir + "/spc-regions";
  const CliResult r = run_furrow({"spc", "--db", b.db, "--out", out, "--by", "region", "--serials",
                                  serial(5) + ".." + serial(19)});
  REQUIRE_MESSAGE((r.status == 0 || r.status == 1), r.err);
  const json spc = json::parse(slurp(out + "/spc.json"));
  REQUIRE(spc["parts"].size() == 15);
  CHECK(spc["parts"][0]["serial"] == serial(5));
  CHECK(spc["parts"][14]["serial"] == serial(19));
  // Oracle: each region's mean over its evaluated points, per comparison.
  std::map<std::string, std::vector<double>> means;
  for (int i = 5; i <= 19; ++i) {
    std::map<int, std::pair<double, int>> sums;
    const json doc = json::parse(slurp(b.comparisons[i]));
    for (const json& p : doc["points"])
      if (p["evaluated"].get<bool>() && p["region"].is_number_integer()) {
        auto& s = sums[p["region"].get<int>()];
        s.first += p["deviation"].get<double>();
        ++s.second;
      }
    for (const auto& [region, s] : sums) means[std::to_string(region)].push_back(s.first / s.second);
  }
  REQUIRE(spc["characteristics"].size() == means.size());
  for (const json& c : spc["characteristics"]) {
    const std::string id = c["id"];
    CAPTURE(id);
    CHECK(c["kind"] == "region");
    const std::vector<double>& x = means.at(id);
    REQUIRE(c["values"].size() == x.size());
    // Summed in another order than the database's: relative 1e-12 of a
    // deviation of at most 0.1 mm.
    for (std::size_t k = 0; k < x.size(); ++k) CHECK(std::abs(c["values"][k].get<double>() - x[k]) < 1e-13);
  }
}

TEST_CASE("cli spc: bad input exits 2 with one line naming it, and writes nothing") {
  // Two parts are enough to be refused for: a case run alone (as ctest and
  // the sanitizer build run it) need not store all 25.
  const WearBatch b = make_batch("cli-spc-bad-db", 2);
  const std::string dir = scratch_dir("cli-spc-bad");
  const auto refused = [&](const std::vector<std::string>& words, const std::string& named) {
    CAPTURE(named);
    const CliResult r = run_furrow(words);
    CHECK(r.status == 2);
    CHECK(r.err.find(named) != std::string::npos);
    CHECK(line_count(r.err) == 1);
  };
  refused({"spc", "--db", dir + "/missing.db", "--out", dir + "/o1"}, dir + "/missing.db");
  refused({"spc", "--db", b.db, "--out", dir + "/o2", "--serials", "SN-999.."}, "SN-999");
  refused({"spc", "--db", b.db, "--out", dir + "/o3", "--by", "face"}, "--by");
  refused({"spc", "--db", b.db, "--out", dir + "/o4", "--serials", "SN-101"}, "--serials");
  refused({"spc", "--out", dir + "/o5"}, "--db");
  for (const char* o : {"/o1", "/o2", "/o3", "/o4", "/o5"}) CHECK_FALSE(fs::exists(dir + o));
  // The output folder may not replace the folder holding the database.
  const std::string before = slurp(b.db);
  refused({"spc", "--db", b.db, "--out", b.dir}, b.db);
  CHECK(slurp(b.db) == before);
}

TEST_CASE("cli spc: report --db puts the part in its process, region means as the comparisons give them") {
  const WearBatch& b = wear_batch();
  const std::string dir = scratch_dir("cli-spc-report");
  // Oracle: each region's mean over the evaluated points of each comparison.
  std::vector<std::map<int, double>> means;
  for (const std::string& c : b.comparisons) {
    const json doc = json::parse(slurp(c));
    std::map<int, std::pair<double, int>> sums;
    for (const json& p : doc["points"])
      if (p["evaluated"].get<bool>() && p["region"].is_number_integer()) {
        auto& s = sums[p["region"].get<int>()];
        s.first += p["deviation"].get<double>();
        ++s.second;
      }
    means.emplace_back();
    for (const auto& [region, s] : sums) means.back()[region] = s.first / s.second;
  }
  for (const int part : {kParts - 1, 3}) {
    CAPTURE(part);
    const std::string out = dir + "/r" + std::to_string(part);
    const CliResult r = run_furrow({"report", b.comparisons[part], "--db", b.db, "--out", out});
    REQUIRE_MESSAGE(r.status <= 1, r.err);
    const json process = json::parse(slurp(out + "/report.json"))["process"];
    CHECK(process["stored"] == true);
    CHECK(process["serial"] == serial(part));
    CHECK(process["parts"] == part + 1);
    REQUIRE(process["regions"].size() == means[part].size());
    for (const json& region : process["regions"]) {
      const int id = region["region"];
      CAPTURE(id);
      const json& recent = region["recent"];
      REQUIRE(recent.size() == static_cast<std::size_t>(part + 1));  // 25 parts at most: all of them here
      for (int k = 0; k <= part; ++k) {
        CHECK(recent[k]["serial"] == serial(k));
        // Summed in another order than the comparison's statistics: 1e-13
        // of deviations of at most 0.1 mm.
        CHECK(std::abs(recent[k]["value"].get<double>() - means[k].at(id)) < 1e-13);
      }
    }
    const std::string html = slurp(out + "/report.html");
    CHECK(html.find("<section id=\"process\">") != std::string::npos);
  }
  // Not stored and no serial to store it under: exit 2, nothing written.
  const std::string copy = dir + "/copy.json";
  write_text(copy, slurp(b.comparisons[0]) + " ");  // other bytes: another digest
  const std::string before = slurp(b.db);
  const CliResult refused = run_furrow({"report", copy, "--db", b.db, "--out", dir + "/none"});
  CHECK(refused.status == 2);
  CHECK(refused.err.find("--serial") != std::string::npos);
  CHECK(line_count(refused.err) == 1);
  CHECK_FALSE(fs::exists(dir + "/none"));
  CHECK(slurp(b.db) == before);
}

TEST_CASE("cli spc: spc.html renders in headless Chromium, one chart per characteristic, its violations as alarms") {
  const WearBatch& b = wear_batch();
  const std::string out = b.dir + "/spc-browser";
  const CliResult r = run_furrow({"spc", "--db", b.db, "--out", out});
  REQUIRE(r.status <= 1);
  const json spc = json::parse(slurp(out + "/spc.json"));
  // Without the browser the check fails rather than passing unrun (scripts/install-deps.sh installs it).
  const BrowserRender page = render_in_chromium(out + "/spc.html", scratch_dir("cli-spc-browser"));
  REQUIRE_MESSAGE(page.available, "the browser check needs /usr/bin/chromium: run scripts/install-deps.sh");
  CHECK(page.dom_status == 0);
  // The DOM as Chromium built it: one chart section per characteristic, each with its SVG.
  std::size_t sections = 0, charts = 0;
  for (std::size_t at = page.dom.find("<section class=\"characteristic\""); at != std::string::npos;
       at = page.dom.find("<section class=\"characteristic\"", at + 1)) {
    ++sections;
    const std::size_t end = page.dom.find("</section>", at);
    charts += page.dom.find("<svg", at) < end;
  }
  CHECK(sections == spc["characteristics"].size());
  CHECK(charts == sections);
  // Values in a violation are drawn as alarms: as many as the violations
  // of spc.json cover (every part is charted: 25 < kSpcChartParts).
  std::size_t alarms_expected = 0, alarms = 0;
  for (const json& c : spc["characteristics"]) {
    std::vector<bool> in(c["values"].size(), false);
    for (const json& v : c["violations"])
      for (std::size_t i = v["index"]; i <= v["last"].get<std::size_t>(); ++i) in[i] = true;
    for (bool x : in) alarms_expected += x;
  }
  for (std::size_t at = page.dom.find("class=\"value alarm\""); at != std::string::npos;
       at = page.dom.find("class=\"value alarm\"", at + 1))
    ++alarms;
  CHECK(alarms_expected > 0);
  CHECK(alarms == alarms_expected);
  // The screenshot shows the page: the capability table, not a blank window.
  REQUIRE(page.screenshot_status == 0);
  REQUIRE_FALSE(page.screenshot.empty());
  const cv::Rect all(0, 0, page.screenshot.cols, page.screenshot.rows);
  CHECK(all.area() - pixels_near(page.screenshot, all, 255, 255, 255, 3) > all.area() / 20);
}
