// docs/job.schema.json is what `furrow help --job-schema` writes, and it
// agrees with the job reader: the example jobs and the job options a run
// echoes validate (python3-jsonschema, the oracle), and a job the reader
// refuses for a member's value or name is refused by the schema too.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "cli/report_checks.hpp"
#include "job/job.hpp"
#include "job/job_options.hpp"
#include "stage/compare_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;

namespace {

std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kSchema = source_path("docs/job.schema.json");

bool schema_takes(const json& job, const std::string& dir, const std::string& name) {
  write_text(dir + "/" + name, job.dump(2));
  const ShellResult r = validate_with_jsonschema(kSchema, dir + "/" + name, dir);
  REQUIRE_MESSAGE(r.status != 3, r.out);
  return r.status == 0;
}

bool reader_takes(const json& job) {
  try {
    parse_job(job.dump(), "job.json", source_path("examples/jobs"));
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

TEST_CASE("docs/job.schema.json is what furrow help --job-schema writes") {
  const CliResult r = run_furrow({"help", "--job-schema"});
  REQUIRE(r.status == 0);
  CHECK(r.out == text_of(kSchema));
}

TEST_CASE("the job schema names every option of every stage table in its section") {
  const json schema = json::parse(text_of(kSchema));
  const json& p = schema["properties"];
  const auto check = [](const json& section, const std::vector<OptionDoc>& docs) {
    REQUIRE(section.contains("properties"));
    for (const OptionDoc& d : docs) {
      CAPTURE(d.key);
      CHECK(section["properties"].contains(d.key));
    }
    CHECK(section["additionalProperties"] == false);
  };
  check(p["partition"], describe(partition_option_table()));
  check(p["prediction"], describe(prediction_option_table()));
  check(p["plan"], describe(plan_option_table()));
  check(p["comparison"], describe(compare_option_table()));
  check(p["toolpath"]["oneOf"][2]["properties"]["generate"], describe(toolpath_option_table()));
  check(p["measurements"]["oneOf"][2]["properties"]["simulate"], describe(simulation_option_table()));
}

TEST_CASE("the schema and the reader agree on the example jobs, the echoed options and on broken members") {
  const std::string dir = scratch_dir("job-schema");
  for (const std::string name : {"demo.json", "mould.json", "mould-scan.json"}) {
    CAPTURE(name);
    const json job = json::parse(text_of(source_path("examples/jobs/" + name)));
    CHECK(reader_takes(job));
    CHECK(schema_takes(job, dir, name));
    // What a run echoes as the job's options (report.json options.job) is a
    // job file too, with every default written out.
    const Job read = parse_job(job.dump(), "job.json", source_path("examples/jobs"));
    const json echoed = json::parse(job_options_json(read));
    CHECK(reader_takes(echoed));
    CHECK(schema_takes(echoed, dir, "echo_" + name));
  }
  const json demo = json::parse(text_of(source_path("examples/jobs/demo.json")));
  struct Broken {
    const char* what;
    json patch;
  };
  const std::vector<Broken> broken = {
      {"a misspelt plan member", {{"plan", {{"densty", 1}}}}},
      {"a negative probe", {{"plan", {{"probe_diameter", -2}}}}},
      {"a count as text", {{"plan", {{"min_per_region", "5"}}}}},
      {"a fractional count", {{"plan", {{"gouge_points", 1.5}}}}},
      {"a fraction above one", {{"comparison", {{"overcut_fraction", 1.5}}}}},
      {"a toggle as text", {{"comparison", {{"outlier_rejection", "yes"}}}}},
      {"a short stock box", {{"prediction", {{"stock", {0, 0, 0, 1, 1}}}}}},
      {"a zero spacing", {{"partition", {{"spacing", 0}}}}},
      {"a grid of three", {{"partition", {{"grid", {10, 10, 10}}}}}},
      {"an unknown top-level member", {{"outptu", "x"}}},
      {"a misalignment of five", {{"measurements", {{"simulate", {{"misalign", {1, 2, 3, 4, 5}}}}}}}},
  };
  int k = 0;
  for (const Broken& b : broken) {
    const std::string what = b.what;
    CAPTURE(what);
    json job = demo;
    job.merge_patch(b.patch);
    CHECK_FALSE(reader_takes(job));
    CHECK_FALSE(schema_takes(job, dir, "broken_" + std::to_string(k++) + ".json"));
  }
}
