// `furrow run` of a scan job (examples/jobs/mould-scan.json) gives byte for
// byte what the chain of single commands gives: partition, compare --scan
// with the regions and the deviation cloud, report. The oracle is the
// commands themselves, each run as a user would, inside a folder at the
// same depth as the job's output (so that relative file names agree).
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report_checks.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::shell_quote;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

TEST_CASE("furrow run of the scan job gives byte for byte what partition, compare --scan and report give") {
  const std::string dir = test::scratch_dir("cli-run-scan");
  fs::create_directories(dir + "/job");
  fs::create_directories(dir + "/chain/out");
  // The bundled job, its files named absolutely, its output beside it.
  json job = json::parse(slurp(test::source_path("examples/jobs/mould-scan.json")));
  const std::string part = test::source_path("examples/parts/mould.json");
  const std::string scan = test::source_path("examples/scans/mould_dent.ply");
  job["part"] = part;
  job["tool"] = test::source_path("examples/tools/ball_d20.json");
  job["measurements"]["scan"]["file"] = scan;
  job["output"] = "out";
  test::write_text(dir + "/job/job.json", job.dump(2));
  const auto run = run_furrow({"run", dir + "/job/job.json"});
  INFO(run.out << run.err);
  REQUIRE(run.status == 1);  // the dent fails the part
  const std::string out = dir + "/job/out";

  const std::string chain = dir + "/chain/out";
  const std::string part_rel = fs::path(part).lexically_relative(chain).string();
  const std::string scan_rel = fs::path(scan).lexically_relative(chain).string();
  // The job compares with its prediction (comparison.prediction defaults to
  // true): the chain is given the job's prediction.json.
  REQUIRE(fs::exists(out + "/prediction.json"));
  fs::copy_file(out + "/prediction.json", chain + "/prediction.json");
  const std::vector<std::vector<std::string>> steps = {
      {"partition", part_rel, "--out", "regions.json"},
      {"compare", part_rel, "--scan", scan_rel, "--regions", "regions.json", "--prediction", "prediction.json",
       "--tolerance", "0.05", "--out", "comparison.json", "--deviations", "deviations.ply"},
      {"report", "comparison.json", "--out", "report", "--title", "mould-scan"},
  };
  for (const auto& step : steps) {
    std::string command = "cd " + shell_quote(chain) + " && " + shell_quote(FURROW_CLI);
    for (const std::string& word : step) command += " " + shell_quote(word);
    const test::ShellResult r = test::run_shell(command, dir + "/step.log");
    INFO(step[0] << ": " << r.out);
    CHECK((r.status == 0 || (r.status == 1 && step[0] != "partition")));
  }
  for (const char* f : {"regions.json", "comparison.json", "deviations.ply"}) {
    INFO(f);
    REQUIRE(fs::exists(chain + "/" + f));
    CHECK(slurp(chain + "/" + f) == slurp(out + "/" + f));
  }
  // The report of the chain carries the same numbers and the same figures.
  const json a = json::parse(slurp(chain + "/report/report.json")), b = json::parse(slurp(out + "/report.json"));
  for (const char* member : {"verdict", "alignment", "deviations", "regions", "scan", "points", "figures"})
    CHECK(a[member] == b[member]);
  CHECK(b["scan"]["display"]["points"].get<std::size_t>() > 4000);
  for (const char* f : {"figures/scan_histogram.svg", "figures/scan_deviation_top.png", "figures/region_map.png"}) {
    INFO(f);
    CHECK(slurp(chain + "/report/" + f) == slurp(out + "/" + f));
  }
  const auto valid = test::validate_with_jsonschema(test::source_path("docs/report.schema.json"), out + "/report.json", dir);
  INFO(valid.out);
  CHECK(valid.status == 0);
}

TEST_CASE("a job's simulated scan gives byte for byte what simulate-measurement --scan and compare --scan give") {
  // The bundled scan's simulation (examples/scans/README.md) as the job's
  // measurements.scan.simulate; the oracle is the chain of commands run in
  // a folder at the same depth as the job's output.
  const std::string dir = test::scratch_dir("cli-run-scan-simulated");
  fs::create_directories(dir + "/job");
  fs::create_directories(dir + "/chain/out");
  json job = json::parse(slurp(test::source_path("examples/jobs/mould-scan.json")));
  const std::string part = test::source_path("examples/parts/mould.json");
  job["part"] = part;
  job["tool"] = test::source_path("examples/tools/ball_d20.json");
  job["measurements"]["scan"] = {{"simulate",
                                  {{"stripe_pitch", 1.5},
                                   {"point_pitch", 1.2},
                                   {"view", {0.2, 0.1, -1}},
                                   {"spray", 0.005},
                                   {"misalign", {5, -3, 170, 10, 20, 30}},
                                   {"seed", 11},
                                   {"bumps", {{30, 40, 28.85, 5, -0.1}}}}}};
  job["output"] = "out";
  test::write_text(dir + "/job/job.json", job.dump(2));
  const auto run = run_furrow({"run", dir + "/job/job.json"});
  INFO(run.out << run.err);
  REQUIRE(run.status == 1);  // the dent fails the part
  const std::string out = dir + "/job/out";

  const std::string chain = dir + "/chain/out";
  const std::string part_rel = fs::path(part).lexically_relative(chain).string();
  REQUIRE(fs::exists(out + "/prediction.json"));
  fs::copy_file(out + "/prediction.json", chain + "/prediction.json");
  const std::vector<std::vector<std::string>> steps = {
      {"simulate-measurement", part_rel, "--scan", "--out", "scan.ply", "--stripe-pitch", "1.5", "--point-pitch",
       "1.2", "--view", "0.2,0.1,-1", "--spray", "0.005", "--misalign", "5,-3,170,10,20,30", "--seed", "11", "--bump",
       "30,40,28.85,5,-0.1"},
      {"partition", part_rel, "--out", "regions.json"},
      {"compare", part_rel, "--scan", "scan.ply", "--regions", "regions.json", "--prediction", "prediction.json",
       "--tolerance", "0.05", "--out", "comparison.json", "--deviations", "deviations.ply"},
      {"report", "comparison.json", "--out", "report", "--title", "mould-scan"},
  };
  for (const auto& step : steps) {
    std::string command = "cd " + shell_quote(chain) + " && " + shell_quote(FURROW_CLI);
    for (const std::string& word : step) command += " " + shell_quote(word);
    const test::ShellResult r = test::run_shell(command, dir + "/step.log");
    INFO(step[0] << ": " << r.out);
    CHECK((r.status == 0 || (r.status == 1 && step[0] == "compare") || (r.status == 1 && step[0] == "report")));
  }
  for (const char* f : {"scan.ply", "regions.json", "comparison.json", "deviations.ply"}) {
    INFO(f);
    REQUIRE(fs::exists(chain + "/" + f));
    CHECK(slurp(chain + "/" + f) == slurp(out + "/" + f));
  }
  // The bundled scan was made by the same command line.
  CHECK(slurp(out + "/scan.ply") == slurp(test::source_path("examples/scans/mould_dent.ply")));
  const json a = json::parse(slurp(chain + "/report/report.json")), b = json::parse(slurp(out + "/report.json"));
  for (const char* member : {"verdict", "alignment", "deviations", "regions", "scan", "gouges", "prediction", "figures"})
    CHECK(a[member] == b[member]);
  // The job's report names the scan as a file the run wrote.
  bool named = false;
  for (const json& in : b["inputs"])
    if (in["role"] == "scan") named = in["path"] == "scan.ply" && in["generated"] == true;
  CHECK(named);
  // The job echoes its simulation, and the echo is a job the schema takes.
  const auto valid = test::validate_with_jsonschema(test::source_path("docs/report.schema.json"), out + "/report.json", dir);
  INFO(valid.out);
  CHECK(valid.status == 0);
  CHECK(b["options"]["job"]["measurements"]["scan"]["simulate"]["seed"] == 11);
  CHECK(b["options"]["job"]["measurements"]["scan"]["simulate"]["stripe_pitch"] == 1.5);
}

TEST_CASE("a scan job takes a file or a simulation, not both") {
  const std::string dir = test::scratch_dir("cli-run-scan-both");
  json job = json::parse(slurp(test::source_path("examples/jobs/mould-scan.json")));
  job["part"] = test::source_path("examples/parts/mould.json");
  job["tool"] = test::source_path("examples/tools/ball_d20.json");
  job["measurements"]["scan"] = {{"file", test::source_path("examples/scans/mould_dent.ply")},
                                 {"simulate", {{"seed", 3}}}};
  job["output"] = "out";
  test::write_text(dir + "/both.json", job.dump());
  const auto both = run_furrow({"run", dir + "/both.json"});
  CHECK(both.status == 2);
  CHECK(both.err.find("measurements.scan.file") != std::string::npos);
  json unknown = job;
  unknown["measurements"]["scan"] = {{"simulate", {{"blunders", 3}}}};
  test::write_text(dir + "/unknown.json", unknown.dump());
  const auto u = run_furrow({"run", dir + "/unknown.json"});
  CHECK(u.status == 2);
  CHECK(u.err.find("blunders") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/out"));
}

TEST_CASE("a scan job refuses compensation and a bad units member, naming the member") {
  const std::string dir = test::scratch_dir("cli-run-scan-bad");
  json job = json::parse(slurp(test::source_path("examples/jobs/mould-scan.json")));
  job["part"] = test::source_path("examples/parts/mould.json");
  job["tool"] = test::source_path("examples/tools/ball_d20.json");
  job["measurements"]["scan"]["file"] = test::source_path("examples/scans/mould_dent.ply");
  job["output"] = "out";
  json units = job;
  units["measurements"]["scan"]["units"] = "furlong";
  test::write_text(dir + "/units.json", units.dump());
  const auto u = run_furrow({"run", dir + "/units.json"});
  CHECK(u.status == 2);
  CHECK(u.err.find("measurements.scan.units") != std::string::npos);
  json comp = job;
  comp["compensate"] = {{"out", "comp.nc"}};
  test::write_text(dir + "/comp.json", comp.dump());
  const auto c = run_furrow({"run", dir + "/comp.json"});
  CHECK(c.status == 2);
  CHECK(c.err.find("compensat") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/out"));
}
