// The bad-input corpus (tests/bad_inputs/<reader>/, made by
// scripts/make_bad_inputs.py): every malformed file, given to the command
// that reads it, is refused with exit status 2 and one short line on stderr
// naming the file; nothing is written and the input is byte-identical
// afterwards (docs/formats.md "Limits", docs/architecture.md "Errors").
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

// Path -> bytes of every file under `root`.
std::map<std::string, std::string> folder_snapshot(const std::string& root) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    out[fs::relative(e.path(), root).string()] = e.is_regular_file() ? slurp(e.path().string()) : "<dir>";
  return out;
}

// One reader: the folder of its bad files and the command that reads them.
// "{FILE}" is the bad file, "{OUT}" a fresh output folder, "{REGIONS}" a
// valid regions file of the part.
struct ReaderCase {
  const char* folder;
  std::vector<std::string> command;
};

std::vector<std::string> expand(const std::vector<std::string>& command, const std::string& file,
                                const std::string& out, const std::string& regions) {
  std::vector<std::string> args;
  for (std::string a : command) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{FILE}", file}, {"{OUT}", out},
                                     {"{REGIONS}", regions}})
      if (const auto pos = a.find(key); pos != std::string::npos) a.replace(pos, key.size(), value);
    args.push_back(a);
  }
  return args;
}

}  // namespace

TEST_CASE("bad input: every file of the corpus is refused with exit 2, one line naming it, nothing written") {
  const std::string part = source_path("examples/parts/quarter_cylinder.json");
  const std::string tool = source_path("examples/tools/ball_d6.json");
  const std::string dir = scratch_dir("cli-bad-input");
  const std::string regions = dir + "/regions.json";
  REQUIRE(run_furrow({"partition", part, "--grid", "20", "--out", regions}).status == 0);

  const std::vector<ReaderCase> readers = {
      {"part", {"partition", "{FILE}", "--grid", "20", "--out", "{OUT}/regions.json"}},
      {"tool", {"toolpath", part, "--tool", "{FILE}", "--scallop", "0.05", "--out", "{OUT}/path.nc"}},
      {"tool_library", {"select-tool", part, "--library", "{FILE}", "--grid", "2", "--out", "{OUT}/tools.json"}},
      {"gcode", {"predict", part, "--tool", tool, "--toolpath", "{FILE}", "--out", "{OUT}/prediction.json"}},
      {"apt", {"predict", part, "--toolpath", "{FILE}", "--out", "{OUT}/prediction.json"}},
      {"toolpath_csv", {"predict", part, "--tool", tool, "--toolpath", "{FILE}", "--out", "{OUT}/prediction.json"}},
      {"contact_csv", {"gouge", part, "--tool", tool, "--points", "{FILE}", "--out", "{OUT}/gouge.json"}},
      {"measurements_csv",
       {"compare", part, "--measurements", "{FILE}", "--probe-diameter", "2", "--out", "{OUT}/comparison.json"}},
      {"measurements_xyz",
       {"compare", part, "--measurements", "{FILE}", "--probe-diameter", "2", "--out", "{OUT}/comparison.json"}},
      {"measurements_dmis", {"compare", part, "--measurements", "{FILE}", "--out", "{OUT}/comparison.json"}},
      {"measurements_ippdme", {"compare", part, "--measurements", "{FILE}", "--out", "{OUT}/comparison.json"}},
      {"plan", {"simulate-measurement", part, "--plan", "{FILE}", "--out", "{OUT}/m.csv"}},
      {"regions", {"plan", part, "--regions", "{FILE}", "--points", "12", "--out", "{OUT}/plan"}},
      {"prediction",
       {"plan", part, "--regions", "{REGIONS}", "--prediction", "{FILE}", "--points", "12", "--out", "{OUT}/plan"}},
      {"comparison", {"report", "{FILE}", "--out", "{OUT}/report"}},
      {"job", {"run", "{FILE}", "--out", "{OUT}/job"}},
      {"cad", {"import", "{FILE}", "--out", "{OUT}/part.json"}},
  };
  // The cases through other commands than their folder's.
  const std::vector<std::pair<std::string, std::vector<std::string>>> extra = {
      {"part/point_1e308_times_weight.json", {"info", "{FILE}", "--out", "{OUT}/info.txt"}},
      {"part/coordinate_1e308.json", {"partition", "{FILE}", "--out", "{OUT}/regions.json"}},
      {"tool/diameter_1e-300.json", {"toolpath", part, "--tool", "{FILE}", "--out", "{OUT}/path.nc"}},
      {"tool/diameter_1e300.json", {"gouge", part, "--tool", "{FILE}", "--out", "{OUT}/gouge.json"}},
      {"tool/diameter_1e300.json", {"toolpath", part, "--tool", "{FILE}", "--out", "{OUT}/path.nc"}},
      {"measurements_csv/inch_overflow.csv",
       {"compare", part, "--measurements", "{FILE}", "--units", "inch", "--probe-diameter", "2", "--out",
        "{OUT}/comparison.json"}},
      {"cad/garbage.step", {"info", "{FILE}"}},
  };

  std::vector<std::pair<std::string, std::vector<std::string>>> runs = extra;
  std::set<std::string> folders;
  for (const ReaderCase& r : readers) {
    const fs::path folder = fs::path(source_path("tests/bad_inputs")) / r.folder;
    REQUIRE_MESSAGE(fs::is_directory(folder), folder.string());
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    CHECK_MESSAGE(files.size() >= 5, r.folder);
    for (const std::string& f : files) runs.push_back({std::string(r.folder) + "/" + f, r.command});
    folders.insert(r.folder);
  }
  // Every reader folder of the corpus has its command here.
  for (const auto& e : fs::directory_iterator(source_path("tests/bad_inputs")))
    if (e.is_directory()) CHECK_MESSAGE(folders.count(e.path().filename().string()) == 1, e.path().string());
  CHECK(runs.size() >= 150 + extra.size());

  int index = 0;
  for (const auto& run : runs) {
    // Named copies, not a structured binding: CAPTURE below is a lambda, and
    // C++17 lambdas cannot capture structured bindings (clang refuses).
    const std::string& relative = run.first;
    const std::vector<std::string>& command = run.second;
    const std::string file = source_path("tests/bad_inputs/" + relative);
    const std::string out = dir + "/out" + std::to_string(index++);
    fs::create_directories(out);
    const std::string before = slurp(file);
    const auto outputs_before = folder_snapshot(out);
    const std::vector<std::string> args = expand(command, file, out, regions);
    const CliResult r = run_furrow(args);
    CAPTURE(relative);
    CAPTURE(args[0]);
    INFO("stderr: " << r.err.substr(0, 400));
    CHECK(r.status == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(r.err.find(file) != std::string::npos);
    // The path, the field or line, what is wrong, a value of at most 80 characters.
    CHECK(r.err.size() < file.size() + 400);
    CHECK(r.err.find("internal error") == std::string::npos);
    CHECK(folder_snapshot(out) == outputs_before);
    CHECK(slurp(file) == before);
  }
}
