// A job's plan with an indexable head (plan.head, docs/formats.md "Job
// file"): the head file is read relative to the job's folder and set up
// exactly as `furrow plan --head` sets it (the oracle: the planner's own
// use_head on the file read apart), so that "tips": "auto" works in a job;
// the same refusals as the command, naming the job's members; the head is
// an input whose echo reads back to the same options.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/cmm/probe_head.hpp"
#include "job/job.hpp"
#include "job/job_options.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

const char* kHead = R"({
  "head": {"type": "test", "a": {"min": 0, "max": 90, "step": 45}, "b": {"min": -90, "max": 180, "step": 90},
           "length": 30, "diameter": 24},
  "stylus": {"length": 21, "ball_diameter": 3, "stem_diameter": 1.5},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": %s
})";

// A job folder holding heads/empty.json (no qualified tip) and
// heads/two.json (A0B0 and A90B0 qualified).
std::string job_folder() {
  const std::string dir = furrow::test::scratch_dir("job-plan-head");
  std::filesystem::create_directories(dir + "/heads");
  for (const auto& [name, qualified] : {std::pair<std::string, std::string>{"empty", "[]"},
                                        {"two", R"([{"a": 0, "b": 0}, {"a": 90, "b": 0}])"}}) {
    char text[1024];
    std::snprintf(text, sizeof text, kHead, qualified.c_str());
    std::ofstream(dir + "/heads/" + name + ".json") << text;
  }
  return dir;
}

std::string job_text(const std::string& plan) {
  return R"({"part": "p.json", "tool": "t.json", "toolpath": "p.nc", "tolerance": 0.05, "plan": )" + plan +
         R"(, "output": "out"})";
}

std::string error_of(const std::string& text, const std::string& folder) {
  try {
    parse_job(text, "job.json", folder);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("job plan.head: read relative to the job, set up as furrow plan --head, tips auto with no qualified tip") {
  const std::string dir = job_folder();
  const Job job = parse_job(job_text(R"({"head": "heads/empty.json", "tips": "auto"})"), "job.json", dir);
  CHECK(job.head_file == (std::filesystem::path(dir) / "heads/empty.json").lexically_normal().string());
  REQUIRE(job.plan.head);
  CHECK(job.plan.tips == TipChoice::automatic);
  // The oracle: the planner's defaults with use_head on the file read apart.
  PlannerOptions expected;
  use_head(expected, read_probe_head(job.head_file));
  CHECK(job.plan.probe_diameter == 3.0);  // the head file's ball
  CHECK(job.plan.probe_diameter == expected.probe_diameter);
  CHECK(job.plan.stylus_diameter == expected.stylus_diameter);
  CHECK(job.plan.stylus_length == expected.stylus_length);
  CHECK(job.plan.head->reach() == expected.head->reach());
  CHECK(job.plan.head->qualified.empty());

  // The echo names the head and not the stylus it gives, and reads back.
  const nlohmann::json echo = nlohmann::json::parse(job_options_json(job));
  CHECK(echo["plan"]["head"] == job.head_file);
  CHECK_FALSE(echo["plan"].contains("probe_diameter"));
  nlohmann::json again = nlohmann::json::parse(job_text("{}"));
  again["plan"] = echo["plan"];
  const Job reread = parse_job(again.dump(), "again.json", "");
  REQUIRE(reread.plan.head);
  CHECK(reread.plan.probe_diameter == job.plan.probe_diameter);
  CHECK(reread.plan.tips == TipChoice::automatic);
}

TEST_CASE("job plan.head: a head with qualified tips plans with them, and the refusals name the job's members") {
  const std::string dir = job_folder();
  const Job job = parse_job(job_text(R"({"head": "heads/two.json"})"), "job.json", dir);
  REQUIRE(job.plan.head);
  CHECK(job.plan.tips == TipChoice::qualified);
  CHECK(job.plan.head->qualified.size() == 2);

  const std::string stylus = error_of(job_text(R"({"head": "heads/two.json", "probe_diameter": 2})"), dir);
  CAPTURE(stylus);
  CHECK(stylus.find("plan.head gives the stylus: leave out probe_diameter, stylus_diameter and stylus_length") !=
        std::string::npos);
  const std::string empty = error_of(job_text(R"({"head": "heads/empty.json"})"), dir);
  CHECK(empty.find("empty.json.qualified: no qualified tip is listed") != std::string::npos);
  CHECK(empty.find("\"tips\": \"auto\"") != std::string::npos);
  CHECK(error_of(job_text(R"({"head": "heads/none.json"})"), dir).find("none.json") != std::string::npos);
  CHECK(error_of(job_text(R"({"head": ""})"), dir).find("plan.head: empty path") != std::string::npos);
  CHECK(error_of(job_text(R"({"tips": "auto"})"), dir).find("plan.head") !=
        std::string::npos);
}
