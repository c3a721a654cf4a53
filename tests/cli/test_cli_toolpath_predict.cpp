#include <doctest/doctest.h>

#include <cmath>

#include <filesystem>

#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const std::string kMould = source_path("examples/parts/mould.json");
const std::string kCylinder = source_path("examples/parts/semi_cylinder.json");
const std::string kBall6 = source_path("examples/tools/ball_d6.json");

bool is_png(const std::string& path) { return slurp(path).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

// A short raster over the mould's dimple flank, written three ways: metric
// absolute, inch absolute, metric relative (with comments and line numbers).
const char* kMetric =
    "%\n(metric, absolute)\nG21 G90\nG0 X60 Y28 Z40\nG0 Z21.9\nN10 G1 X64 Y28 Z21.2 F800\nG1 X68 Y28 Z20.2\n"
    "G0 Z40\nG0 X68 Y28.5\nG0 Z20.2\nG1 X64 Y28.5 Z21.2 ; back\nG1 X60 Y28.5 Z21.9\nG0 Z40\nM30\n%\n";
const char* kInch =
    "(inch, absolute)\nG20 G90\nG0 X2.3622047244 Y1.1023622047 Z1.5748031496\nG0 Z0.8622047244\n"
    "G1 X2.5196850394 Y1.1023622047 Z0.8346456693 F30\nG1 X2.6771653543 Y1.1023622047 Z0.7952755906\n"
    "G0 Z1.5748031496\nG0 X2.6771653543 Y1.1220472441\nG0 Z0.7952755906\n"
    "G1 X2.5196850394 Y1.1220472441 Z0.8346456693\nG1 X2.3622047244 Y1.1220472441 Z0.8622047244\n"
    "G0 Z1.5748031496\nM30\n";
const char* kRelative =
    "(metric, relative moves)\nG21 G90\nG0 X60 Y28 Z40\nG0 Z21.9\nG91\nG1 X4 Z-0.7 F800\nG1 X4 Z-1.0\n"
    "G0 Z19.8\nG0 Y0.5\nG0 Z-19.8\nG1 X-4 Z1.0\nG1 X-4 Z0.7\nG90 G0 Z40\n";

}  // namespace

TEST_CASE("furrow toolpath writes G-code and a contact CSV that read back as the same path") {
  const std::string dir = scratch_dir("cli-toolpath");
  const CliResult r = run_furrow({"toolpath", kCylinder, "--tool", kBall6, "--tolerance", "0.01", "--scallop", "0.05",
                                  "--direction", "plane:0", "--out", dir + "/cyl.nc"});
  CHECK(r.status == 0);
  CHECK(r.err.empty());  // no progress on a pipe
  CHECK(r.out.find("passes") != std::string::npos);
  const Toolpath tips = read_toolpath(dir + "/cyl.nc");
  const Toolpath contacts = read_toolpath(dir + "/cyl.csv");
  CHECK(contacts.kind == ToolpathKind::contact_points);
  REQUIRE(tips.passes.size() == contacts.passes.size());
  REQUIRE(tips.passes.size() > 10);
  const Cutter ball("ball", 3, 3);
  for (std::size_t p = 0; p < tips.passes.size(); ++p) {
    REQUIRE(tips.passes[p].points.size() == contacts.passes[p].points.size());
    for (std::size_t k = 0; k < tips.passes[p].points.size(); ++k) {
      const ToolpathPoint& c = contacts.passes[p].points[k];
      CHECK(c.has_uv);
      CHECK(c.face == "semi_cylinder");
      const Eigen::Vector3d tip = cutter_location(ball, c.position, c.normal).tip;
      CHECK((tip - tips.passes[p].points[k].position).norm() < 1e-4);  // 4 decimals in the G-code
    }
  }
}

TEST_CASE("furrow predict on a planned path: prediction.json, PNG, within tolerance") {
  const std::string dir = scratch_dir("cli-predict");
  REQUIRE(run_furrow({"toolpath", kCylinder, "--tool", kBall6, "--scallop", "0.05", "--direction", "u", "--out",
                      dir + "/cyl.nc"})
              .status == 0);
  for (const std::string input : {"cyl.nc", "cyl.csv"}) {
    CAPTURE(input);
    const std::string out = dir + "/" + input + ".json";
    const CliResult r = run_furrow({"predict", kCylinder, "--tool", kBall6, "--toolpath", dir + "/" + input,
                                    "--resolution", "0.1", "--out", out, "--map", dir + "/" + input + ".png"});
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("0 steps over the tolerance") != std::string::npos);
    const Prediction p = read_prediction(out);
    CHECK(p.summary.steps_evaluated == p.summary.steps);
    CHECK(p.summary.steps_over_tolerance == 0);
    CHECK(p.summary.gouge_sites == 0);
    CHECK(p.predicted_error_at("semi_cylinder", 0.5, 0.5).reached());
    CHECK(is_png(dir + "/" + input + ".png"));
  }
  // By region: the semi-cylinder is one convex region; its extremes are the
  // error map's (sampled, so at most the refinement above them).
  REQUIRE(run_furrow({"partition", kCylinder, "--out", dir + "/regions.json"}).status == 0);
  CliResult r = run_furrow({"predict", kCylinder, "--tool", kBall6, "--toolpath", dir + "/cyl.nc", "--resolution",
                            "0.1", "--regions", dir + "/regions.json", "--out", dir + "/by_region.json"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("region 0 (convex, semi_cylinder)") != std::string::npos);
  const Prediction p = read_prediction(dir + "/by_region.json");
  REQUIRE(p.has_regions);
  REQUIRE(p.regions.size() == 1);
  CHECK(p.regions[0].curvature_class == "convex");
  CHECK(p.regions[0].reached > 0);
  CHECK(p.regions[0].max_overcut.error >= p.summary.max_overcut.error - 1e-9);
  // A sample lies within half a diagonal of the 0.1 mm grid, d = 0.0707 mm,
  // of the refined extreme; the error surface there bends at most like the
  // ball (r = 3) plus the cylinder (R = 25.4), so the sample misses it by at
  // most d^2 / 2 (1/r + 1/R).
  const double d = 0.1 / std::sqrt(2.0);
  CHECK(p.regions[0].max_overcut.error <= p.summary.max_overcut.error + d * d / 2 * (1 / 3.0 + 1 / 25.4));
  // A regions file of another part is refused.
  REQUIRE(run_furrow({"partition", kMould, "--out", dir + "/mould_regions.json"}).status == 0);
  r = run_furrow({"predict", kCylinder, "--tool", kBall6, "--toolpath", dir + "/cyl.nc", "--regions",
                  dir + "/mould_regions.json", "--out", dir + "/wrong.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("computed for another part") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/wrong.json"));
}

TEST_CASE("G-code through furrow predict: inch units and relative moves give the metric absolute prediction") {
  const std::string dir = scratch_dir("cli-gcode");
  const char* texts[] = {kMetric, kInch, kRelative};
  const char* names[] = {"metric.nc", "inch.nc", "relative.nc"};
  std::vector<Prediction> predictions;
  for (int k = 0; k < 3; ++k) {
    write_text(dir + "/" + names[k], texts[k]);
    const CliResult r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/" + names[k],
                                    "--resolution", "0.2", "--out", dir + "/" + names[k] + ".json"});
    CAPTURE(names[k]);
    CAPTURE(r.err);
    // The passes start and end 0.22 mm below the cutter-location surface
    // (summary.points_below_surface): the rapids down onto and up from
    // those ends are rapid gouges, so predict exits 1 (docs/architecture.md
    // "Rapid moves"). The ball resting at an end is part of what the z-map
    // sweeps, so a rapid's depth is at most the z-map's deepest overcut.
    REQUIRE(r.status == 1);
    predictions.push_back(read_prediction(dir + "/" + names[k] + ".json"));
    REQUIRE(predictions.back().rapids.gouges.size() == 2);
    for (const RapidGougeRecord& g : predictions.back().rapids.gouges) {
      CHECK(g.depth > 0.2);
      CHECK(g.depth <= -predictions.back().summary.max_overcut.error + 1e-6);
    }
  }
  const Prediction& m = predictions[0];
  REQUIRE(m.steps.size() == 4);
  for (int k = 1; k < 3; ++k) {
    const Prediction& p = predictions[k];
    REQUIRE(p.steps.size() == m.steps.size());
    for (std::size_t s = 0; s < m.steps.size(); ++s) {
      CHECK(p.steps[s].status == m.steps[s].status);
      // The inch file is written to 10 decimals of an inch (2.5 nm).
      CHECK(p.steps[s].undercut.error == doctest::Approx(m.steps[s].undercut.error).epsilon(0).scale(1).epsilon(1e-6));
      CHECK(std::fabs(p.steps[s].overcut.error - m.steps[s].overcut.error) < 1e-6);
    }
    CHECK(std::fabs(p.summary.max_undercut.error - m.summary.max_undercut.error) < 1e-6);
    CHECK(std::fabs(p.summary.max_overcut.error - m.summary.max_overcut.error) < 1e-6);
  }
  // A plunge cut with G1 from the safe height: the move from the air gets no
  // per-step error, the others are unchanged.
  std::string plunge = kMetric;
  const std::string rapid = "G0 Z21.9\n";
  plunge.replace(plunge.find(rapid), rapid.size(), "G1 Z21.9 F300\n");
  write_text(dir + "/plunge.nc", plunge);
  // The plunge is cut now; the rapid up from the second pass's end, below
  // the surface, is still a rapid gouge.
  REQUIRE(run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/plunge.nc", "--resolution", "0.2",
                      "--out", dir + "/plunge.json"})
              .status == 1);
  const Prediction q = read_prediction(dir + "/plunge.json");
  REQUIRE(q.rapids.gouges.size() == 1);
  CHECK(q.rapids.gouges[0].line == m.rapids.gouges[1].line);
  REQUIRE(q.steps.size() == m.steps.size() + 1);
  CHECK(q.steps[0].status == "in_air");
  CHECK(q.summary.points_in_air == 1);
  for (std::size_t s = 0; s < m.steps.size(); ++s)
    CHECK(std::fabs(q.steps[s + 1].overcut.error - m.steps[s].overcut.error) < 1e-9);
}

TEST_CASE("furrow predict and toolpath: bad input is one clear error and status 2, nothing written") {
  const std::string dir = scratch_dir("cli-predict-errors");
  write_text(dir + "/bad.nc", "G21 G90\nG0 X0 Y0 Z30\nG1 X10 Y# Z20\n");
  CliResult r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/bad.nc", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("bad.nc:3:") != std::string::npos);
  CHECK(line_count(r.err) == 1);
  write_text(dir + "/arc.nc", "G21 G90\nG0 X0 Y0 Z30\nG2 X10 Y1 I5 J0\n");
  r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/arc.nc", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("arc.nc:3: G2: arc start radius") != std::string::npos);
  write_text(dir + "/empty.nc", "");
  r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/empty.nc", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("empty.nc: the file is empty") != std::string::npos);
  r = run_furrow({"predict", kMould, "--toolpath", dir + "/bad.nc", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--tool") != std::string::npos);
  r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/bad.nc", "--out", dir + "/p.txt"});
  CHECK(r.status == 2);
  CHECK(r.err.find("expected a .json file name") != std::string::npos);
  r = run_furrow({"toolpath", kMould, "--tool", kBall6, "--direction", "sideways", "--out", dir + "/t.nc"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--direction: \"sideways\" is not a direction") != std::string::npos);
  r = run_furrow({"toolpath", kMould, "--tool", kBall6, "--rule", "guess", "--out", dir + "/t.nc"});
  CHECK(r.status == 2);
  // A contact point that is not on the part.
  write_text(dir + "/off.csv", "x,y,z,nx,ny,nz\n10,10,50,0,0,1\n20,10,50,0,0,1\n");
  r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/off.csv", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("off.csv:2: the contact point lies") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/p.json"));
  CHECK_FALSE(std::filesystem::exists(dir + "/t.nc"));
}
