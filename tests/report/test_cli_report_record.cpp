// `furrow report --record`: the record in the report folder, its file
// digested with the inputs; a bad record refused before anything is written.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_cli.hpp"
#include "io/qif/qif_schema.hpp"
#include "report_fixture.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;

namespace {

// The fixture's comparison on disk, naming the bundled part by an absolute
// path, with the measurement file it names next to it.
std::string comparison_on_disk(const std::string& dir) {
  static const ReportFixture f = make_report_fixture();
  json c = json::parse(f.comparison_json);
  c["part"] = source_path("examples/parts/mould.json");
  write_text(dir + "/comparison.json", c.dump(1));
  write_text(dir + "/grid.csv", "the measurements the comparison names\n");
  return dir + "/comparison.json";
}

// SHA-256 by coreutils, independent of Furrow's own digest.
std::string sha256sum(const std::string& path, const std::string& scratch) {
  const std::string out = scratch + "/sha256sum.txt";  // never next to a source file
  REQUIRE(std::system(("sha256sum " + shell_quote(path) + " > " + shell_quote(out)).c_str()) == 0);
  return slurp(out).substr(0, 64);
}

}  // namespace

TEST_CASE("furrow report --record puts the record in the header and report.json and results.qif and the inputs") {
  const std::string dir = scratch_dir("report-record");
  const std::string comparison = comparison_on_disk(dir);
  const std::string record = source_path("examples/records/mould_first_article.json");
  const CliResult r = run_furrow({"report", comparison, "--out", dir + "/out", "--record", record});
  CHECK_MESSAGE(r.status == 1, r.err);  // the fixture's dent fails the part
  const json report = json::parse(slurp(dir + "/out/report.json"));
  CHECK(report["record"]["part_number"] == "MOULD-100-A");
  CHECK(report["record"]["temperature"] == json({{"value", 20.4}, {"unit", "C"}}));
  CHECK(report["record"]["sign_off"] == json({{"prepared", {{"name", "J. Doe"}, {"date", "2026-11-25"}}}}));
  bool digested = false;
  for (const json& in : report["inputs"])
    if (in["role"] == "record") {
      digested = true;
      CHECK(in["path"] == record);
      CHECK(in["sha256"] == sha256sum(record, dir));
    }
  CHECK(digested);
  // The schema knows the record and its input role (python3-jsonschema, as the demo test).
  const std::string validate = "python3 -c 'import json,sys,jsonschema; jsonschema.validate(json.load(open(sys.argv[2])), "
                               "json.load(open(sys.argv[1])))' " +
                               shell_quote(source_path("docs/report.schema.json")) + " " +
                               shell_quote(dir + "/out/report.json") + " > " + shell_quote(dir + "/schema.log") + " 2>&1";
  CHECK_MESSAGE(std::system(validate.c_str()) == 0, slurp(dir + "/schema.log"));
  const std::string html = slurp(dir + "/out/report.html");
  CHECK(html.find("<div data-field=\"serial\"><span class=\"label\">Serial number</span>SN-0042</div>") <
        html.find("</header>"));
  check_qif_valid_file(dir + "/out/results.qif");  // the QIF 3.0 XSD (docs/qif.md "Validity")
  const std::string qif = slurp(dir + "/out/results.qif");
  CHECK(qif.find("<AttributeStr name=\"part_number\" value=\"MOULD-100-A\"/>") != std::string::npos);
  CHECK(qif.find("<Name>J. Doe</Name>") != std::string::npos);
}

TEST_CASE("furrow report --record with a bad record exits 2 naming the member and writes nothing") {
  const std::string dir = scratch_dir("report-record-bad");
  const std::string comparison = comparison_on_disk(dir);
  write_text(dir + "/record.json", R"({"part_number": "A", "serail": "SN 1"})");
  const CliResult r = run_furrow({"report", comparison, "--out", dir + "/out", "--record", dir + "/record.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("record.json: serail: unknown member") != std::string::npos);
  CHECK(line_count(r.err) == 1);
  CHECK_FALSE(std::filesystem::exists(dir + "/out"));
}

namespace {

// The demo job with absolute paths and `record` inline, written to DIR/NAME.
json demo_job_with_record(const std::string& dir, const std::string& name, const json& record) {
  json job = json::parse(slurp(source_path("examples/jobs/demo.json")));
  job["part"] = source_path("examples/parts/mould.json");
  job["tool"] = source_path("examples/tools/ball_d24.json");
  job["output"] = "out";
  job["record"] = record;
  write_text(dir + "/" + name, job.dump(1));
  return job;
}

}  // namespace

// Two whole demo jobs: left out of the sanitizer run, which takes the bad
// record below (docs/testing.md).
TEST_CASE("furrow run: the job's inline record reaches the report and --record replaces it") {
  const std::string dir = scratch_dir("run-record");
  demo_job_with_record(dir, "job.json", {{"serial", "INLINE-1"}, {"operator", "<b>op</b>"}});

  const CliResult r = run_furrow({"run", dir + "/job.json"});
  CHECK_MESSAGE(r.status == 1, r.err);  // the demo's gouge fails the part
  json report = json::parse(slurp(dir + "/out/report.json"));
  CHECK(report["record"] == json({{"serial", "INLINE-1"}, {"operator", "<b>op</b>"}}));
  const std::string html = slurp(dir + "/out/report.html");
  CHECK(html.find("&lt;b&gt;op&lt;/b&gt;") != std::string::npos);
  CHECK(html.find("<b>op</b>") == std::string::npos);

  // --record: the file's record instead, digested as an input.
  const std::string record = source_path("examples/records/mould_first_article.json");
  const CliResult again = run_furrow({"run", dir + "/job.json", "--out", dir + "/out2", "--record", record});
  CHECK_MESSAGE(again.status == 1, again.err);
  report = json::parse(slurp(dir + "/out2/report.json"));
  CHECK(report["record"]["serial"] == "SN-0042");
  std::size_t records = 0;
  for (const json& in : report["inputs"]) records += in["role"] == "record" && in["path"] == record;
  CHECK(records == 1);
}

TEST_CASE("furrow run with a bad inline record exits 2 before any stage runs, nothing written") {
  const std::string dir = scratch_dir("run-record-bad");
  demo_job_with_record(dir, "bad.json", {{"serial", "S"}, {"sign_off", {{"checked", {{"date", "2026-02-30"}}}}}});
  const CliResult bad = run_furrow({"run", dir + "/bad.json", "--out", dir + "/out3"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("record.sign_off.checked.date") != std::string::npos);
  CHECK(line_count(bad.err) == 1);
  CHECK_FALSE(std::filesystem::exists(dir + "/out3"));
}
