// A program that changes tools, through `furrow predict --tools` and a job's
// toolpath.tools: the table's tools (inline or as files beside it) cut the
// passes they are loaded for; without a table such a program is bad input.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A plate, a 6 mm ball file, a table with the ball (T1, by file) and a
// 10 mm flat (T2, inline), and a program that cuts one pass with each.
void write_inputs(const std::string& dir) {
  write_part_json(one_face("plate", make_plane({0, 0, 0}, {40, 0, 0}, {0, 40, 0})), dir + "/plate.json");
  write_text(dir + "/ball.json", "{\"name\":\"B6\",\"type\":\"ball\",\"diameter\":6}\n");
  write_text(dir + "/table.json",
             "{\"T1\": \"ball.json\", \"T2\": {\"name\": \"FL10\", \"type\": \"flat\", \"diameter\": 10}}\n");
  write_text(dir + "/two.nc",
             "%\nO0042 (TWO TOOLS)\nG21 G90 G54\n"
             "T1 M6\nG0 X-10 Y10 Z5\nZ0.1\nG1 X50 F800\nG0 Z5\nG28 G91 Z0\n"
             "G90 T2 M6\nG0 X-10 Y25 Z5\nZ-0.2\nG1 X50\nG0 Z5\nM30\n%\n");
}

}  // namespace

TEST_CASE("furrow predict --tools: each pass with the tool loaded for it, listed in the summary and the file") {
  const std::string dir = scratch_dir("predict-tool-table");
  write_inputs(dir);
  const CliResult r = run_furrow({"predict", dir + "/plate.json", "--tools", dir + "/table.json", "--toolpath",
                                  dir + "/two.nc", "--out", dir + "/prediction.json", "--resolution", "0.25"});
  const std::string output = r.out + r.err;
  INFO(output);
  CHECK(r.status == 0);
  CHECK(r.out.find("tools (the program changes tools), tolerance 10.00 um:\n"
                   "  T1 B6 (ball, diameter 6 mm): 1 pass\n"
                   "  T2 FL10 (flat, diameter 10 mm): 1 pass\n") != std::string::npos);
  // The flat's 0.2 mm cut is the deepest overcut (with the ball alone it would be none).
  CHECK(r.out.find("max overcut:  -200.00 um") != std::string::npos);
  const nlohmann::json doc = nlohmann::json::parse(slurp(dir + "/prediction.json"));
  CHECK(doc["pass_tools"] == nlohmann::json::array({0, 1}));
  // Without the table the program is refused, naming both changes.
  const CliResult single = run_furrow({"predict", dir + "/plate.json", "--tool", dir + "/ball.json", "--toolpath",
                                       dir + "/two.nc", "--out", dir + "/single.json"});
  CHECK(single.status == 2);
  CHECK(single.err.find("two.nc: the program changes tools (T1 at line 4, T2 at line 10): give a tool table (--tools)") !=
        std::string::npos);
  // A table that misses T2, and a table that is not JSON by its name.
  write_text(dir + "/short.json", "{\"T1\": \"ball.json\"}\n");
  const CliResult missing = run_furrow({"predict", dir + "/plate.json", "--tools", dir + "/short.json", "--toolpath",
                                        dir + "/two.nc", "--out", dir + "/missing.json"});
  CHECK(missing.status == 2);
  CHECK(missing.err.find("short.json: no tool T2, which " + dir + "/two.nc:10 loads") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/missing.json"));
  // The table's tool files are inputs: never an output.
  const CliResult over = run_furrow({"predict", dir + "/plate.json", "--tools", dir + "/table.json", "--toolpath",
                                     dir + "/two.nc", "--out", dir + "/ball.json"});
  CHECK(over.status == 2);
  CHECK(slurp(dir + "/ball.json") == "{\"name\":\"B6\",\"type\":\"ball\",\"diameter\":6}\n");
}

TEST_CASE("furrow run: toolpath.tools gives a job's program its tools, echoed in job options") {
  const std::string dir = scratch_dir("job-tool-table");
  write_inputs(dir);
  write_text(dir + "/job.json",
             R"({"version": 1, "part": "plate.json", "tool": "ball.json",
                 "toolpath": {"file": "two.nc", "tools": "table.json"},
                 "tolerance": {"zone": 0.05}, "prediction": {"resolution": 0.25},
                 "plan": {"allow_uncovered": true}, "output": "out"})");
  const CliResult r = run_furrow({"run", dir + "/job.json"});
  const std::string output = r.out + r.err;
  INFO(output);
  CHECK(r.status == 0);
  const nlohmann::json doc = nlohmann::json::parse(slurp(dir + "/out/prediction.json"));
  REQUIRE(doc.contains("tools"));
  CHECK(doc["tools"][1]["tool"]["name"] == "FL10");
  // The same job without the table: bad input, before any output.
  write_text(dir + "/plain.json",
             R"({"version": 1, "part": "plate.json", "tool": "ball.json", "toolpath": "two.nc",
                 "tolerance": {"zone": 0.05}, "output": "plain"})");
  const CliResult plain = run_furrow({"run", dir + "/plain.json"});
  CHECK(plain.status == 2);
  CHECK(plain.err.find("the program changes tools") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/plain/prediction.json"));
}
