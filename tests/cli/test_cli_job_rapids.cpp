// `furrow run` with a G-code path whose rapid dives into the part: the
// prediction stage lists the rapid gouge and the job exits 1 like `furrow
// predict` (docs/architecture.md "Rapid moves"); without it the job is as before.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

int run_job_with(const std::string& dir, const std::string& program, std::string& out) {
  write_part_json(one_face("plate", make_plane({-10, -10, 0}, {20, 0, 0}, {0, 20, 0})), dir + "/plate.json");
  write_text(dir + "/ball.json", "{\"name\":\"B6\",\"type\":\"ball\",\"diameter\":6,\"corner_radius\":3}\n");
  write_text(dir + "/path.nc", program);
  write_text(dir + "/job.json",
             R"({"version": 1, "part": "plate.json", "tool": "ball.json", "toolpath": "path.nc",
                 "tolerance": {"zone": 0.05}, "prediction": {"resolution": 0.25},
                 "plan": {"allow_uncovered": true}, "output": "out"})");
  const CliResult r = run_furrow({"run", dir + "/job.json"});
  out = r.out + r.err;
  return r.status;
}

}  // namespace

TEST_CASE("furrow run: a rapid into the part is a summary line and exit 1, a clean path exits 0") {
  const std::string head = "G21 G90 G54\nG0 X-8 Y0 Z10\nG0 Z0\nG1 X8 F500\nG0 Z10\n";
  std::string out;
  const int crash = run_job_with(scratch_dir("job-rapid-crash"), head + "G0 X0 Y-5 Z-1.5\nG28 G91 Z0\nM30\n", out);
  CHECK(crash == 1);
  CHECK(out.find("RAPID GOUGE line 6 (part): 1.5000 mm deep") != std::string::npos);
  const std::string dir = scratch_dir("job-rapid-clean");
  const int clean = run_job_with(dir, head + "G28 G91 Z0\nM30\n", out);
  CHECK(clean == 0);
  CHECK(out.find("RAPID GOUGE") == std::string::npos);
  CHECK_FALSE(nlohmann::json::parse(slurp(dir + "/out/prediction.json")).contains("rapids"));
}
