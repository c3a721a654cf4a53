// Every command that writes refuses an output path that is, or holds, one of
// its inputs (exit 2, the input named, nothing written, every input
// byte-identical), and a killed run leaves nothing behind that the next run
// does not clean up.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <algorithm>
#include <filesystem>
#include <map>
#include <thread>

#include "support/run_cli.hpp"

using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

// Path -> bytes of every file under `root`, hidden files and folders included.
std::map<std::string, std::string> snapshot(const std::string& root) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string rel = fs::relative(e.path(), root).string();
    out[rel] = e.is_regular_file() ? slurp(e.path().string()) : std::string("<dir>");
  }
  return out;
}

bool has_temporary(const std::string& root) {
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("output safety: no command writes over, or replaces the folder of, one of its inputs") {
  const std::string dir = scratch_dir("cli-output-safety");
  const std::string in = dir + "/in";
  fs::create_directories(in);
  fs::copy_file(source_path("examples/parts/mould.json"), in + "/part.json");
  fs::copy_file(source_path("examples/tools/ball_d6.json"), in + "/tool.json");
  fs::copy_file(source_path("examples/toolpaths/mould_ball6.nc"), in + "/path.nc");
  const std::string part = in + "/part.json", tool = in + "/tool.json", path = in + "/path.nc";
  // Inputs the later stages need, made by the stages themselves.
  REQUIRE(run_furrow({"partition", part, "--out", in + "/regions.json", "--grid", "40x40"}).status == 0);
  REQUIRE(run_furrow({"plan", part, "--regions", in + "/regions.json", "--points", "30", "--out", dir + "/plan"})
              .status == 0);
  fs::copy_file(dir + "/plan/plan.json", in + "/plan.json");
  fs::remove_all(dir + "/plan");
  REQUIRE(run_furrow({"simulate-measurement", part, "--plan", in + "/plan.json", "--out", in + "/m.csv"}).status == 0);
  REQUIRE(run_furrow({"compare", part, "--measurements", in + "/m.csv", "--plan", in + "/plan.json", "--out",
                      in + "/comparison.json"})
              .status == 0);
  write_text(in + "/job.json", R"({"version": 1, "part": "part.json", "tool": "tool.json", "toolpath": "path.nc",
    "tolerance": {"zone": 0.05}, "plan": {"points": 20}, "output": "."})");
  write_text(dir + "/job_parent.json", R"({"version": 1, "part": "in/part.json", "tool": "in/tool.json",
    "toolpath": "in/path.nc", "tolerance": {"zone": 0.05}, "plan": {"points": 20}, "output": "."})");

  struct Case {
    std::vector<std::string> args;
    std::string input;  // the input the message must name
  };
  const std::vector<Case> cases = {
      {{"plan", part, "--regions", in + "/regions.json", "--out", in}, part},
      {{"plan", part, "--regions", in + "/regions.json", "--out", dir}, part},
      {{"plan", part, "--regions", in + "/regions.json", "--out", in + "/../in/"}, part},
      {{"toolpath", part, "--tool", tool, "--out", part}, part},
      {{"toolpath", part, "--tool", tool, "--out", dir + "/t.nc", "--contacts", tool}, tool},
      {{"predict", part, "--tool", tool, "--toolpath", path, "--out", in + "/regions.json", "--regions",
        in + "/regions.json"},
       in + "/regions.json"},
      {{"predict", part, "--tool", tool, "--toolpath", path, "--out", part}, part},
      {{"partition", part, "--out", part}, part},
      {{"gouge", part, "--tool", tool, "--out", tool}, tool},
      {{"gouge", part, "--tool", tool, "--out", dir + "/g.json", "--map", part}, part},
      {{"compare", part, "--measurements", in + "/m.csv", "--out", in + "/m.csv"}, in + "/m.csv"},
      {{"compare", part, "--measurements", in + "/m.csv", "--plan", in + "/plan.json", "--out", in + "/plan.json"},
       in + "/plan.json"},
      {{"report", in + "/comparison.json", "--out", in}, in + "/comparison.json"},
      {{"remeasure", in + "/comparison.json", "--out", in}, in + "/comparison.json"},
      {{"remeasure", in + "/comparison.json", "--out", dir}, in + "/comparison.json"},
      {{"compare", part, "--measurements", dir + "/none.csv", "--measurements", in + "/m.csv", "--out",
        in + "/m.csv"},
       in + "/m.csv"},
      {{"run", in + "/job.json"}, "job.json (job)"},
      {{"run", dir + "/job_parent.json"}, "job_parent.json (job)"},
      {{"simulate-measurement", part, "--plan", in + "/plan.json", "--out", in + "/plan.json"}, in + "/plan.json"},
      {{"select-tool", part, "--library", tool, "--out", tool}, tool},
      {{"info", part, "--out", part}, part},
  };
  const std::map<std::string, std::string> before = snapshot(dir);
  for (const Case& c : cases) {
    std::string line;
    for (const std::string& a : c.args) line += a + " ";
    CAPTURE(line);
    const CliResult r = run_furrow(c.args);
    CHECK(r.status == 2);
    CHECK(r.err.find(c.input) != std::string::npos);
    CHECK(r.err.find("input") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one clear line
    CHECK(snapshot(dir) == before);
  }
}

TEST_CASE("output safety: a run killed while it works leaves nothing that the next run keeps") {
  const std::string dir = scratch_dir("cli-kill");
  const std::string out = dir + "/demo";
  // Plant what a run killed while publishing leaves: a staging folder of a
  // process that no longer exists.
  const pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);
  fs::create_directories(dir + "/.demo.tmp-" + std::to_string(gone) + "-0/plan");
  // And kill a real run part way through its work.
  const pid_t child = fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execl(FURROW_CLI, FURROW_CLI, "demo", "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  const CliResult r = run_furrow({"demo", "--out", out});
  REQUIRE(r.status == 0);
  CHECK_FALSE(has_temporary(dir));
  for (const char* file : {"report.html", "report.json", "comparison.json", "prediction.json", "plan/plan.json"})
    CHECK(fs::exists(out + "/" + file));
}
