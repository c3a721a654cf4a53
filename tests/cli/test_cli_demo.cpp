// End to end: `furrow demo`, `furrow run` on variants of the demo job (one
// change each against the demo: a controlled experiment), `furrow report`
// on the demo's comparison. Every pipeline run here takes a few seconds;
// the checks on one run share it (plain blocks, not SUBCASEs, which would
// run the pipeline again for each).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/part_file.hpp"
#include "job/demo.hpp"
#include "report_checks.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json read_json(const std::string& path) { return json::parse(slurp(path)); }

// The demo job with absolute paths, changed by `edit`, written as DIR/job.json.
std::string demo_variant(const std::string& dir, const std::function<void(json&)>& edit) {
  json job = read_json(source_path("examples/jobs/demo.json"));
  job["part"] = source_path("examples/parts/mould.json");
  job["tool"] = source_path("examples/tools/ball_d24.json");
  job["output"] = "out";
  edit(job);
  write_text(dir + "/job.json", job.dump(2));
  return dir + "/job.json";
}

// Data rows of a CSV with a header line ('#' comments skipped).
std::size_t csv_rows(const std::string& path) {
  std::istringstream in(slurp(path));
  std::size_t rows = 0;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    ++rows;
  }
  return rows;
}

// report.json without the members documented to change between runs.
json deterministic_part(json report) {
  report.erase("generated");
  report.erase("timing");
  return report;
}

std::vector<std::string> files_under(const std::string& root) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) out.push_back(fs::relative(e.path(), root).string());
  std::sort(out.begin(), out.end());
  return out;
}

const json& only_zmap_site(const json& report) {
  const json& sites = report["gouges"]["sites"];
  REQUIRE(sites.size() == 1);
  REQUIRE(sites[0]["source"] == "zmap");
  return sites[0];
}

}  // namespace

TEST_CASE("furrow demo: the planted gouge is confirmed, the report renders, a second run gives the same report") {
  const std::string dir = scratch_dir("cli-demo");
  const std::string out = dir + "/demo";
  const CliResult first = run_furrow({"demo", "--out", out});
  INFO(first.out << first.err);
  REQUIRE(first.status == 0);  // the demo ran; its part fails by design (verdict below)
  CHECK(first.err.empty());    // no progress when stderr is not a terminal
  CHECK(first.out.find("report: " + out + "/report.html") != std::string::npos);
  CHECK(first.out.find("stage times:") != std::string::npos);
  fs::copy(out, dir + "/first", fs::copy_options::recursive);
  const CliResult second = run_furrow({"demo", "--out", out});
  CHECK(second.status == 0);

  const json report = read_json(out + "/report.json");
  const json comparison = read_json(out + "/comparison.json");
  const json prediction = read_json(out + "/prediction.json");

  {  // verdict: FAIL with the predicted gouge confirmed
    CHECK(report["verdict"]["result"] == "FAIL");
    CHECK(report["verdict"]["gouge_sites"]["confirmed"] == 1);
    const json& site = only_zmap_site(report);
    CHECK(site["status"] == "CONFIRMED");
    // The site is the prediction's (the dimple around (72, 30)) ...
    REQUIRE(prediction["gouge_sites"].size() == 1);
    CHECK(site["predicted_depth"] == prediction["gouge_sites"][0]["depth"]);
    CHECK(std::hypot(site["centroid"][0].get<double>() - 72, site["centroid"][1].get<double>() - 30) < 5);
    // ... deep, far beyond the 2 um probing noise and the 25 um lower limit ...
    CHECK(prediction["gouge_sites"][0]["depth"].get<double>() > 0.1);
    // ... and measured as deep as predicted: the deepest point's deviation
    // (points.csv, an independent file) within 10 um of the predicted depth.
    const double measured = site["measured_depth"].get<double>();
    CHECK(measured > 0.05);
    CHECK(measured > site["threshold"].get<double>());
    CHECK(std::fabs(measured - site["predicted_depth"].get<double>()) < 0.01);
    std::set<std::string> on_site;
    for (const json& id : site["points"]) on_site.insert(id.get<std::string>());
    CHECK(on_site.count(site["deepest"].get<std::string>()) == 1);
    CHECK(report["verdict"]["unexplained_overcuts"] == 0);  // nothing planted besides the gouge
  }

  {  // points.csv has one row per measured point
    const std::size_t measured = csv_rows(out + "/measurements.csv");
    CHECK(measured > 50);
    CHECK(csv_rows(out + "/points.csv") == measured);
    CHECK(comparison["points"].size() == measured);
    CHECK(report["points"].size() == measured);
  }

  {  // report.json validates against docs/report.schema.json (python3-jsonschema)
    const ShellResult valid = validate_with_jsonschema(source_path("docs/report.schema.json"), out + "/report.json", dir);
    INFO(valid.out);
    REQUIRE(valid.status != 3);
    CHECK(valid.status == 0);
    // The validator does reject a report that breaks the schema.
    json broken = report;
    broken["verdict"]["result"] = "MAYBE";
    broken["points"][0].erase("deviation");
    write_text(dir + "/broken.json", broken.dump());
    const ShellResult invalid = validate_with_jsonschema(source_path("docs/report.schema.json"), dir + "/broken.json", dir);
    CHECK(invalid.status == 1);
  }

  {  // two runs: the same files, report.json differing only in generated and timing
    CHECK(files_under(out) == files_under(dir + "/first"));
    for (const std::string& f : files_under(out)) {
      if (f == "report.html" || f == "report.json") continue;
      INFO(f);
      if (f == "results.qif") {  // the report's time apart (docs/qif.md)
        const auto timeless = [](std::string t) {
          for (const char* tag : {"TimeCreated>", "ReportPreparationDate>"})
            for (std::size_t at = t.find(tag); at != std::string::npos; at = t.find(tag, at + 1))
              if (t[at - 1] == '<') t.erase(at + std::strlen(tag), t.find('<', at) - at - std::strlen(tag));
          return t;
        };
        CHECK(timeless(slurp(out + "/" + f)) == timeless(slurp(dir + "/first/" + f)));
        continue;
      }
      CHECK(slurp(out + "/" + f) == slurp(dir + "/first/" + f));
    }
    const json again = read_json(dir + "/first/report.json");
    CHECK(deterministic_part(report) == deterministic_part(again));
    CHECK(report["timing"]["stages"].size() >= 7);
    CHECK(report["timing"]["total_seconds"].get<double>() > 0);
  }

  // report.html renders in headless Chromium: every image loads, the verdict is visible.
  // Without the browser the check fails rather than passing unrun (scripts/install-deps.sh installs it).
  if (const BrowserRender r = render_in_chromium(out + "/report.html", dir); !r.available) {
    FAIL_CHECK("the browser check needs /usr/bin/chromium, which is missing: run scripts/install-deps.sh");
  } else {
    const std::string html = slurp(out + "/report.html");
    // Raster figures are <img> (the region map and the 3D view's four views), vector ones inline <svg>.
    std::size_t images = 0, vector = 0;
    for (std::size_t at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) ++images;
    for (std::size_t at = html.find("<svg xmlns"); at != std::string::npos; at = html.find("<svg xmlns", at + 1))
      ++vector;
    CHECK(images + vector == report["figures"].size());
    CHECK(images >= 2);
    CHECK(vector >= 5);
    CHECK(r.dom_status == 0);
    const std::string marker = "data-images-loaded=\"" + std::to_string(images) + "/" + std::to_string(images) + "\"";
    CHECK(r.dom.find(marker) != std::string::npos);
    CHECK(r.dom.find("id=\"verdict-result\">FAIL<") != std::string::npos);
    REQUIRE_FALSE(r.screenshot.empty());
    CHECK(r.screenshot.cols == 1280);
    // The verdict banner (red, #c81e1e) fills the top of the page.
    CHECK(pixels_near(r.screenshot, cv::Rect(0, 0, 1280, 400), 200, 30, 30) > 50000);
    // And the page is not blank below it: figures and tables.
    const int white = pixels_near(r.screenshot, cv::Rect(0, 400, 1280, 1200), 255, 255, 255, 2);
    CHECK(white < 1280 * 1200 * 0.9);
  }

  {  // furrow report on the demo's comparison.json finds its sources and gives the same numbers
    const CliResult again = run_furrow({"report", out + "/comparison.json", "--out", dir + "/again"});
    INFO(again.out << again.err);
    CHECK(again.status == 1);
    const json r = read_json(dir + "/again/report.json");
    for (const char* member : {"verdict", "alignment", "deviations", "regions", "prediction", "gouges", "points"})
      CHECK(r[member] == report[member]);
    CHECK(r["options"]["comparison"] == report["options"]["comparison"]);
    CHECK(r["options"]["job"].is_null());
    // Every input named with the digest of the file the demo wrote.
    std::set<std::string> roles;
    for (const json& in : r["inputs"]) {
      roles.insert(in["role"].get<std::string>());
      for (const json& mine : report["inputs"])
        if (mine["role"] == in["role"] && mine["generated"] == true) CHECK(mine["sha256"] == in["sha256"]);
    }
    CHECK(roles == std::set<std::string>{"comparison", "part", "measurements", "plan", "regions", "prediction"});
    CHECK(csv_rows(dir + "/again/points.csv") == csv_rows(out + "/points.csv"));
  }
}

TEST_CASE("furrow demo: only the planned FAIL exits 0, a failed computation or an inconclusive result is not hidden") {
  // The mapping, against the exit statuses of docs (README "Exit status").
  CHECK(demo_exit_status(0) == 0);
  CHECK(demo_exit_status(1) == 0);  // the planned FAIL: the gouge
  CHECK(demo_exit_status(2) == 2);
  CHECK(demo_exit_status(3) == 3);
  CHECK(demo_exit_status(4) == 4);
  // End to end: `furrow demo` takes examples/jobs/demo.json from the current
  // folder first, so a demo whose measurement cannot pass (the blunders of
  // the simulation left outside the zone: INCONCLUSIVE, as `furrow run`
  // below shows) must exit 4.
  const std::string dir = scratch_dir("cli-demo-inconclusive");
  demo_variant(dir, [](json& j) { j["measurements"]["simulate"]["prediction"] = false; });
  fs::create_directories(dir + "/examples/jobs");
  fs::rename(dir + "/job.json", dir + "/examples/jobs/demo.json");
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  const CliResult r = run_furrow({"demo", "--out", "out"});
  fs::current_path(before);
  INFO(r.out << r.err);
  CHECK(r.status == 4);
  CHECK(read_json(dir + "/out/report.json")["verdict"]["result"] == "INCONCLUSIVE");
  CHECK(r.out.find("fails by design") == std::string::npos);
}

TEST_CASE("furrow run: an error-free part passes with exit status 0, with blunders outside the zone it is INCONCLUSIVE") {
  const std::string dir = scratch_dir("cli-run-error-free");
  const std::string clean = demo_variant(dir, [](json& j) {
    j["measurements"]["simulate"]["prediction"] = false;
    j["measurements"]["simulate"]["blunders"] = 0;
    j["output"] = "clean";
  });
  const CliResult pass = run_furrow({"run", clean});
  INFO(pass.out << pass.err);
  CHECK(pass.status == 0);
  const json passed = read_json(dir + "/clean/report.json");
  CHECK(passed["verdict"]["result"] == "PASS");
  CHECK(passed["verdict"]["reasons"].empty());
  CHECK(passed["verdict"]["inconclusive"].empty());

  const std::string job = demo_variant(dir, [](json& j) { j["measurements"]["simulate"]["prediction"] = false; });
  const CliResult r = run_furrow({"run", job});
  INFO(r.out << r.err);
  // The two planted blunders lie outside the zone: the part cannot pass
  // until they are measured again.
  CHECK(r.status == 4);
  const json report = read_json(dir + "/out/report.json");
  CHECK(report["verdict"]["result"] == "INCONCLUSIVE");
  REQUIRE(report["verdict"]["inconclusive"].size() == 2);
  for (const json& reason : report["verdict"]["inconclusive"]) CHECK(reason["kind"] == "suspected_blunder");
  CHECK(report["verdict"]["out_of_tolerance"] == 0);
  // The predicted site was probed (risk-weighted plan) and found intact.
  CHECK(only_zmap_site(report)["status"] == "NOT CONFIRMED");
  CHECK(report["gouges"]["unexplained"].empty());
  CHECK(report["alignment"]["outliers"]["blunder"] == 2);  // the two planted blunders, set aside
}

TEST_CASE("furrow run: planned without the prediction, the predicted gouge site is NOT MEASURED and the verdict INCONCLUSIVE") {
  const std::string dir = scratch_dir("cli-run-not-measured");
  const std::string job = demo_variant(dir, [](json& j) {
    // A sparse plan without a floor per region: the dimple's small concave
    // region (where the gouge is) gets no point - as can happen to any plan
    // that does not know where the risk is.
    j["plan"] = {{"prediction", false}, {"density", 0.3}, {"min_per_region", 0}, {"seed", 1}};
  });
  const CliResult r = run_furrow({"run", job});
  INFO(r.out << r.err);
  // The gouge is there, but nobody looked: in tolerance where probed, and
  // yet never a PASS - INCONCLUSIVE, exit 4, the site named.
  CHECK(r.status == 4);
  const json report = read_json(dir + "/out/report.json");
  const json& site = only_zmap_site(report);
  CHECK(site["status"] == "NOT MEASURED");
  CHECK(report["verdict"]["result"] == "INCONCLUSIVE");
  // The site; the simulation's two blunders are reasons too, and so is every
  // region they left with fewer evaluated points than min(planned there, 5)
  // (counted here from plan.json and comparison.json).
  std::map<int, int> planned, evaluated;
  const json plan = read_json(dir + "/out/plan/plan.json"), comparison = read_json(dir + "/out/comparison.json");
  for (const json& p : plan["points"]) ++planned[p["region"].get<int>()];
  for (const json& p : comparison["points"])
    if (p["evaluated"].get<bool>() && p.contains("region")) ++evaluated[p["region"].get<int>()];
  std::set<std::string> short_regions, named_regions;
  for (const auto& [region, n] : planned)
    if (evaluated[region] < std::min(n, 5)) short_regions.insert("region " + std::to_string(region));
  std::size_t unmeasured = 0;
  for (const json& reason : report["verdict"]["inconclusive"]) {
    if (reason["kind"] == "gouge_not_measured") {
      ++unmeasured;
      CHECK(reason["subject"] == site["id"]);
    } else if (reason["kind"] == "region_below_minimum") {
      named_regions.insert(reason["subject"].get<std::string>());
    } else {
      CHECK(reason["kind"] == "suspected_blunder");
    }
  }
  CHECK(unmeasured == 1);
  CHECK_FALSE(short_regions.empty());  // the case this check is about happens here
  CHECK(named_regions == short_regions);
  CHECK(report["verdict"]["out_of_tolerance"] == 0);
  CHECK(site["points"].empty());
  CHECK(report["verdict"]["gouge_sites"]["not_measured"] == 1);
  // Independently: no measured point lies on the site's extent in the
  // prediction (its xyz box, grown by the 1 mm site margin).
  const json box = read_json(dir + "/out/prediction.json")["gouge_sites"][0]["xyz_box"];
  for (const json& p : report["points"]) {
    const double x = p["foot"][0].get<double>(), y = p["foot"][1].get<double>();
    const bool inside = x > box["min"][0].get<double>() - 1 && x < box["max"][0].get<double>() + 1 &&
                        y > box["min"][1].get<double>() - 1 && y < box["max"][1].get<double>() + 1;
    CHECK_FALSE(inside);
  }
}

TEST_CASE("furrow run: a dent planted in the simulation is an UNEXPLAINED overcut at the dent") {
  const std::string dir = scratch_dir("cli-run-dent");
  // A 30 um dent of 15 mm radius on the saddle, far from the predicted
  // gouge: beyond the overcut threshold, predicted by nothing.
  const Part part = read_part(source_path("examples/parts/mould.json"));
  const Eigen::Vector3d centre = part.faces[0].surface().point(0.25, 0.8125);
  const std::string job = demo_variant(dir, [&](json& j) {
    j["measurements"]["simulate"]["bumps"] = json::array({{centre.x(), centre.y(), centre.z(), 15.0, -0.03}});
  });
  const CliResult r = run_furrow({"run", job});
  INFO(r.out << r.err);
  CHECK(r.status == 1);  // the demo's gouge still fails it
  const json report = read_json(dir + "/out/report.json");
  const json& unexplained = report["gouges"]["unexplained"];
  REQUIRE(unexplained.size() >= 1);
  for (const json& c : unexplained) {
    CHECK(std::hypot(c["xyz"][0].get<double>() - centre.x(), c["xyz"][1].get<double>() - centre.y()) < 15);
    CHECK(c["depth"].get<double>() > c["threshold"].get<double>());
  }
  CHECK(report["verdict"]["unexplained_overcuts"] == unexplained.size());
  CHECK(only_zmap_site(report)["status"] == "CONFIRMED");  // the rest is the demo
  CHECK(slurp(dir + "/out/report.html").find("UNEXPLAINED") != std::string::npos);
}

TEST_CASE("furrow run: without measurements the job stops after the plan") {
  const std::string dir = scratch_dir("cli-run-plan-only");
  const CliResult r = run_furrow({"run", source_path("examples/jobs/mould.json"), "--out", dir + "/out"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("stopped after the plan") != std::string::npos);
  for (const char* f : {"job.json", "regions.json", "prediction.json", "plan/plan.json", "plan/mould-ball6.dmi",
                        "plan/mould-ball6.prg"})
    CHECK(fs::exists(dir + "/out/" + f));
  for (const char* f : {"comparison.json", "report.html", "report.json", "points.csv"})
    CHECK_FALSE(fs::exists(dir + "/out/" + f));
  CHECK(slurp(dir + "/out/job.json") == slurp(source_path("examples/jobs/mould.json")));
}

TEST_CASE("furrow run and report: bad input is one error naming the field, exit 2, nothing written") {
  const std::string dir = scratch_dir("cli-run-bad");
  auto bad_job = [&](const std::function<void(json&)>& edit, const std::string& expected) {
    const std::string job = demo_variant(dir, edit);
    const CliResult r = run_furrow({"run", job});
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/out"));
  };
  bad_job([](json& j) { j["plan"]["densty"] = 1; }, "job.json: plan.densty: unknown member");
  bad_job([](json& j) { j["tolerance"] = -0.05; }, "job.json: tolerance");
  bad_job([](json& j) { j["part"] = "no/such/part.json"; }, "no/such/part.json");
  bad_job([](json& j) { j["measurements"] = {{"file", "missing.csv"}}; }, "missing.csv");
  bad_job([](json& j) { j["toolpath"] = {{"generate", {{"direction", "diagonal"}}}}; }, "toolpath.generate.direction");
  // The output folder may not hold an input: replacing it would delete it.
  const std::string job = demo_variant(dir, [](json& j) { j["output"] = "."; });
  const CliResult inside = run_furrow({"run", job});
  CHECK(inside.status == 2);
  CHECK(inside.err.find("would be deleted") != std::string::npos);
  CHECK(fs::exists(job));

  const CliResult missing = run_furrow({"report", dir + "/none.json", "--out", dir + "/r"});
  CHECK(missing.status == 2);
  CHECK(missing.err.find("none.json") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/r"));
  const CliResult demo_args = run_furrow({"demo", "extra"});
  CHECK(demo_args.status == 2);
}

TEST_CASE("furrow run gives byte for byte what the chain of single commands gives") {
  // The demo job run by `furrow run`, and the same stages run one by one
  // with the commands inside a folder at the same depth (so that relative
  // file names agree): every intermediate file must be identical.
  const std::string dir = scratch_dir("cli-run-chain");
  fs::create_directories(dir + "/job");
  fs::create_directories(dir + "/chain/out");
  const std::string job = demo_variant(dir + "/job", [](json&) {});
  const CliResult run = run_furrow({"run", job});
  INFO(run.out << run.err);
  REQUIRE(run.status == 1);
  const std::string chain = dir + "/chain/out";
  const std::string part = fs::path(source_path("examples/parts/mould.json")).lexically_relative(chain).string();
  const std::string tool = source_path("examples/tools/ball_d24.json");
  const std::vector<std::vector<std::string>> steps = {
      {"partition", part, "--out", "regions.json", "--image", "regions.png"},
      {"toolpath", part, "--tool", tool, "--tolerance", "0.01", "--scallop", "0.005", "--direction", "u", "--out",
       "toolpath.nc"},
      {"predict", part, "--tool", tool, "--toolpath", "toolpath.nc", "--regions", "regions.json", "--out",
       "prediction.json", "--map", "prediction.png"},
      {"plan", part, "--regions", "regions.json", "--prediction", "prediction.json", "--density", "1", "--seed", "1",
       "--out", "plan"},
      {"simulate-measurement", part, "--plan", "plan/plan.json", "--prediction", "prediction.json", "--misalign",
       "2,-1.5,91,120,60,-15", "--noise", "0.002", "--outliers", "2", "--seed", "7", "--out", "measurements.csv"},
      {"compare", part, "--measurements", "measurements.csv", "--plan", "plan/plan.json", "--regions", "regions.json",
       "--prediction", "prediction.json", "--tolerance", "0.05", "--out", "comparison.json"},
      {"report", "comparison.json", "--out", "report"},
  };
  for (const auto& step : steps) {
    std::string command = "cd " + shell_quote(chain) + " && " + shell_quote(FURROW_CLI);
    for (const std::string& word : step) command += " " + shell_quote(word);
    const ShellResult r = run_shell(command, dir + "/step.log");
    INFO(step[0] << ": " << r.out);
    CHECK((r.status == 0 || (r.status == 1 && (step[0] == "compare" || step[0] == "report"))));
  }
  for (const char* f : {"regions.json", "regions.png", "toolpath.nc", "toolpath.csv", "prediction.json",
                        "prediction.png", "plan/plan.json", "plan/plan.csv", "plan/report.json", "plan/plan.png", "plan/coverage.png",
                        "measurements.csv", "comparison.json"}) {
    INFO(f);
    CHECK(fs::exists(chain + "/" + f));
    CHECK(slurp(chain + "/" + f) == slurp(dir + "/job/out/" + f));
  }
  // The report of the chain carries the same numbers.
  const json a = read_json(chain + "/report/report.json"), b = read_json(dir + "/job/out/report.json");
  for (const char* member : {"verdict", "alignment", "deviations", "regions", "prediction", "gouges", "points"})
    CHECK(a[member] == b[member]);
}

TEST_CASE("furrow run with a list of measurement files merges them by id as furrow compare does") {
  // A first run simulates the demo's measurements; the CMM then re-measured
  // one point. The job lists both files; its comparison must be the bytes
  // `furrow compare` writes for the same files run inside the output folder.
  const std::string dir = scratch_dir("cli-run-remeasure");
  fs::create_directories(dir + "/first");
  const CliResult first = run_furrow({"run", demo_variant(dir + "/first", [](json&) {})});
  REQUIRE((first.status == 1 || first.status == 4));
  fs::create_directories(dir + "/job/cmm");
  fs::copy_file(dir + "/first/out/measurements.csv", dir + "/job/cmm/run1.csv");
  // The re-measure: the first data row's point again, 3 um further along x.
  std::istringstream in(slurp(dir + "/job/cmm/run1.csv"));
  std::string remeasure, line, id;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("id,", 0) == 0) {
      remeasure += line + "\n";
      continue;
    }
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    id = f[0];
    f[1] = std::to_string(std::stod(f[1]) + 0.003);
    for (std::size_t k = 0; k < f.size(); ++k) remeasure += (k ? "," : "") + f[k];
    remeasure += "\n";
    break;
  }
  write_text(dir + "/job/cmm/remeasure.csv", remeasure);
  const std::string job = demo_variant(dir + "/job", [](json& j) {
    j["measurements"] = {{"file", {"cmm/run1.csv", "cmm/remeasure.csv"}}, {"points", "centre"}};
  });
  const CliResult run = run_furrow({"run", job});
  INFO(run.out << run.err);
  REQUIRE((run.status == 1 || run.status == 4));
  CHECK(run.out.find("re-measured: " + id) != std::string::npos);
  const auto doc = read_json(dir + "/job/out/comparison.json");
  REQUIRE(doc["replaced"].size() == 1);
  CHECK(doc["replaced"][0]["id"] == id);

  const std::string out = dir + "/job/out";
  const std::string part = fs::path(source_path("examples/parts/mould.json")).lexically_relative(out).string();
  std::string command = "cd " + shell_quote(out) + " && " + shell_quote(FURROW_CLI);
  for (const std::string& word :
       {std::string("compare"), part, std::string("--measurements"), std::string("../cmm/run1.csv"),
        std::string("--measurements"), std::string("../cmm/remeasure.csv"), std::string("--points"),
        std::string("centre"), std::string("--plan"), std::string("plan/plan.json"), std::string("--regions"),
        std::string("regions.json"), std::string("--prediction"), std::string("prediction.json"),
        std::string("--tolerance"), std::string("0.05"), std::string("--out"), std::string("../compare.json")})
    command += " " + shell_quote(word);
  const ShellResult r = run_shell(command, dir + "/compare.log");
  INFO(r.out);
  CHECK((r.status == 1 || r.status == 4));
  CHECK(slurp(dir + "/job/compare.json") == slurp(out + "/comparison.json"));
}
