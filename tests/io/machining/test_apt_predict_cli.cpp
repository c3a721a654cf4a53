// An APT CL file through `furrow predict` gives the prediction of the
// equivalent G-code file, with the cutter taken from the file's CUTTER/; a
// --tool that contradicts it and hostile numbers are refused with status 2.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

using namespace furrow::test;
using nlohmann::json;

namespace {

const std::string kMould = source_path("examples/parts/mould.json");
const std::string kBall6 = source_path("examples/tools/ball_d6.json");

// A raster over the mould's dimple flank with a turn-around arc.
const char* kApt =
    "PARTNO MOULD FLANK\n"
    "UNITS/MM\n"
    "CUTTER/6.0000,3.0000,0.0000,3.0000,0.0000,0.0000,50.0000\n"
    "LOADTL/1\n"
    "RAPID\nGOTO/60.0000,28.0000,40.0000\n"
    "RAPID\nGOTO/60.0000,28.0000,21.9000\n"
    "FEDRAT/MMPM,800.0000\n"
    "GOTO/64.0000,28.0000,21.2000\n"
    "GOTO/68.0000,28.0000,$\n 20.2000\n"
    "$$ turn around\n"
    "CIRCLE/68.0000,28.2500,20.2000,0.0000000,0.0000000,1.0000000,0.2500,0.0600,0.5000,6.0000,0.0000\n"
    "GOTO/68.0000,28.5000,20.2000\n"
    "GOTO/64.0000,28.5000,21.2000\n"
    "GOTO/60.0000,28.5000,21.9000\n"
    "RAPID\nGOTO/60.0000,28.5000,40.0000\n"
    "FINI\n";
const char* kGcode =
    "%\nG21 G90 G17\nG0 X60 Y28 Z40\nG0 Z21.9\nG1 X64 Y28 Z21.2 F800\nG1 X68 Y28 Z20.2\n"
    "G3 X68 Y28.5 I0 J0.25\nG1 X64 Y28.5 Z21.2\nG1 X60 Y28.5 Z21.9\nG0 Z40\nM30\n%\n";

// Every number of `a` equals the one at the same place in `b` (to 1e-9,
// relative above 1); strings (file names, the tool's name) may differ.
void check_same_numbers(const json& a, const json& b, const std::string& where, int& compared) {
  CAPTURE(where);
  REQUIRE(a.type() == b.type());
  if (a.is_object()) {
    REQUIRE(a.size() == b.size());
    for (auto it = a.begin(); it != a.end(); ++it) {
      REQUIRE(b.contains(it.key()));
      check_same_numbers(*it, b.at(it.key()), where + "." + it.key(), compared);
    }
  } else if (a.is_array()) {
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) check_same_numbers(a[k], b[k], where + "[" + std::to_string(k) + "]", compared);
  } else if (a.is_number() && where.find(".rapids.gouges[") != std::string::npos &&
             where.size() >= 5 && where.compare(where.size() - 5, 5, ".line") == 0) {
    // Source lines differ between the two files; checked by the caller.
  } else if (a.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    CHECK(std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x)));
    ++compared;
  }
}

}  // namespace

TEST_CASE("APT through furrow predict: the G-code file's prediction, the tool from CUTTER/") {
  const std::string dir = scratch_dir("io-apt-predict");
  write_text(dir + "/flank.cl", kApt);
  write_text(dir + "/flank.nc", kGcode);
  // The hand-written path ends 0.22 mm below the surface at both ends of the
  // flank, so the rapid plunge onto it and the retract from it cut the part:
  // two rapid gouges, exit 1, in both files.
  CliResult r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/flank.nc", "--resolution",
                            "0.2", "--out", dir + "/gcode.json"});
  CAPTURE(r.err);
  REQUIRE(r.status == 1);
  // No --tool: the cutter is the file's CUTTER/ (ball, 6 mm).
  r = run_furrow({"predict", kMould, "--toolpath", dir + "/flank.cl", "--resolution", "0.2", "--out",
                  dir + "/apt.json"});
  CAPTURE(r.err);
  REQUIRE(r.status == 1);
  // The same tool given explicitly agrees with the file.
  r = run_furrow({"predict", kMould, "--tool", kBall6, "--toolpath", dir + "/flank.cl", "--resolution", "0.2",
                  "--out", dir + "/apt_tool.json"});
  CAPTURE(r.err);
  REQUIRE(r.status == 1);
  // Each file names its own lines: G0 Z21.9 / G0 Z40 in the G-code, the
  // RAPID GOTOs to 21.9 and to 40 in the CL file.
  const auto gouge_lines = [&](const std::string& file) {
    std::vector<int> lines;
    const json prediction = json::parse(slurp(dir + "/" + file));
    for (const json& g : prediction.at("rapids").at("gouges"))
      lines.push_back(g.at("line").get<int>());
    return lines;
  };
  CHECK(gouge_lines("gcode.json") == std::vector<int>{4, 10});
  CHECK(gouge_lines("apt.json") == std::vector<int>{8, 19});

  const json g = json::parse(slurp(dir + "/gcode.json"));
  REQUIRE(g.contains("steps"));
  REQUIRE(g.at("steps").size() > 10);  // the arc is flattened into many steps
  for (const char* file : {"apt.json", "apt_tool.json"}) {
    CAPTURE(file);
    int compared = 0;
    check_same_numbers(g, json::parse(slurp(dir + "/" + file)), "", compared);
    CHECK(compared > 100);
  }
}

TEST_CASE("APT through furrow predict: a contradicting --tool, a path without a tool and hostile numbers exit 2") {
  const std::string dir = scratch_dir("io-apt-predict-errors");
  write_text(dir + "/flank.cl", kApt);
  write_text(dir + "/flat6.json", "{\"name\": \"F6\", \"type\": \"flat\", \"diameter\": 6}\n");
  CliResult r = run_furrow({"predict", kMould, "--tool", dir + "/flat6.json", "--toolpath", dir + "/flank.cl",
                            "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("flat6.json") != std::string::npos);
  CHECK(r.err.find("flank.cl:3") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/p.json"));

  write_text(dir + "/flank.nc", kGcode);
  r = run_furrow({"predict", kMould, "--toolpath", dir + "/flank.nc", "--out", dir + "/p.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--tool") != std::string::npos);

  const std::string head = "CUTTER/6,3\nRAPID\nGOTO/60,28,40\n";  // lines 1-3
  for (const std::string bad : {"GOTO/1e308,28,20\n", "GOTO/nan,28,20\n", "GOTO/60,,20\n", "GOTO/60,28\n"}) {
    CAPTURE(bad);
    write_text(dir + "/bad.apt", head + bad);
    r = run_furrow({"predict", kMould, "--toolpath", dir + "/bad.apt", "--out", dir + "/p.json"});
    CHECK(r.status == 2);
    CHECK(r.err.find("bad.apt:4:") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir + "/p.json"));
  }
}

TEST_CASE("APT in a job: the job's tool must be the file's CUTTER/") {
  const std::string dir = scratch_dir("apt_job");
  write_text(dir + "/flank.cl", kApt);
  write_text(dir + "/flat6.json", "{\"name\": \"F6\", \"type\": \"flat\", \"diameter\": 6}\n");
  auto job = [&](const std::string& tool, const std::string& out) {
    const std::string file = dir + "/" + out + ".json";
    write_text(file, json{{"part", kMould}, {"tool", tool}, {"toolpath", dir + "/flank.cl"}, {"tolerance", 0.05},
                          {"output", dir + "/" + out}}
                         .dump());
    return file;
  };
  CliResult r = run_furrow({"run", job(dir + "/flat6.json", "wrong")});
  CHECK(r.status == 2);
  CHECK(r.err.find("flat6.json") != std::string::npos);
  CHECK(r.err.find("flank.cl:3") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/wrong"));
  // The same cutter as the file's: the job runs (no measurements: it plans).
  r = run_furrow({"run", job(kBall6, "right")});
  CHECK(r.err.find("CUTTER") == std::string::npos);
  CHECK(std::filesystem::exists(dir + "/right/prediction.json"));
}

TEST_CASE("APT that changes cutters: the prediction of the G-code with T1 M6, T2 M6 and a tool table") {
  // The flank raster above in two passes, the second with a 10 mm flat end
  // mill: in the CL file a second CUTTER/ (and LOADTL/2, ignored), in the
  // G-code T2 M6 with the flat in the table. The numbers agree; only the
  // tool names and source lines differ, and the G-code counts one more
  // unchecked rapid (its first M6; the CL file's first CUTTER/ moves nothing).
  const std::string dir = scratch_dir("io-apt-two-cutters");
  write_text(dir + "/two.cl",
             "PARTNO MOULD FLANK\nUNITS/MM\n"
             "CUTTER/6.0000,3.0000,0.0000,3.0000,0.0000,0.0000,50.0000\nLOADTL/1\n"
             "RAPID\nGOTO/60.0000,28.0000,40.0000\nRAPID\nGOTO/60.0000,28.0000,21.9000\n"
             "FEDRAT/MMPM,800.0000\nGOTO/64.0000,28.0000,21.2000\nGOTO/68.0000,28.0000,20.2000\n"
             "RAPID\nGOTO/68.0000,28.0000,40.0000\n"
             "CUTTER/10.0000\nLOADTL/2\n"
             "RAPID\nGOTO/68.0000,28.5000,40.0000\nRAPID\nGOTO/68.0000,28.5000,20.2000\n"
             "GOTO/64.0000,28.5000,21.2000\nGOTO/60.0000,28.5000,21.9000\n"
             "RAPID\nGOTO/60.0000,28.5000,40.0000\nFINI\n");
  write_text(dir + "/two.nc",
             "%\nG21 G90 G17\nT1 M6\nG0 X60 Y28 Z40\nG0 Z21.9\nG1 X64 Y28 Z21.2 F800\nG1 X68 Y28 Z20.2\nG0 Z40\n"
             "T2 M6\nG0 X68 Y28.5 Z40\nG0 Z20.2\nG1 X64 Y28.5 Z21.2\nG1 X60 Y28.5 Z21.9\nG0 Z40\nM30\n%\n");
  write_text(dir + "/table.json",
             "{\"T1\": \"" + kBall6 + "\", \"T2\": {\"name\": \"FL10\", \"type\": \"flat\", \"diameter\": 10}}\n");
  const CliResult g = run_furrow({"predict", kMould, "--tools", dir + "/table.json", "--toolpath", dir + "/two.nc",
                                  "--resolution", "0.2", "--out", dir + "/gcode.json"});
  CAPTURE(g.err);
  REQUIRE((g.status == 0 || g.status == 1));
  const CliResult a = run_furrow(
      {"predict", kMould, "--toolpath", dir + "/two.cl", "--resolution", "0.2", "--out", dir + "/apt.json"});
  CAPTURE(a.err);
  CHECK(a.status == g.status);
  CHECK(a.out.find("  T2 CUTTER/10,0 (flat, diameter 10 mm): 1 pass") != std::string::npos);
  json gj = json::parse(slurp(dir + "/gcode.json")), aj = json::parse(slurp(dir + "/apt.json"));
  REQUIRE(aj.contains("tools"));
  CHECK(aj["pass_tools"] == json::array({0, 1}));
  if (gj.contains("rapids")) {
    REQUIRE(aj.contains("rapids"));
    CHECK(gj["rapids"]["unchecked"].get<int>() == aj["rapids"]["unchecked"].get<int>() + 1);
    gj["rapids"].erase("unchecked");
    aj["rapids"].erase("unchecked");
  }
  int compared = 0;
  check_same_numbers(gj, aj, "", compared);
  CHECK(compared > 100);
  // A table for a file that defines its own cutters is refused.
  const CliResult both = run_furrow({"predict", kMould, "--tools", dir + "/table.json", "--toolpath", dir + "/two.cl",
                                     "--out", dir + "/both.json"});
  CHECK(both.status == 2);
  CHECK(both.err.find("defines its own cutters (CUTTER/ at lines 3 and 14)") != std::string::npos);
}
