// The CLI starts without OpenCASCADE and reaches it through the CAD module
// only for a STEP or IGES file (base/runtime_module.hpp); without the module
// a CAD import is an installation fault: exit 3, one message naming where it
// looked, nothing written.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/run_cli.hpp"

using namespace furrow::test;

namespace {

struct Shell {
  int status = -1;
  std::string out, err;
};

// `env_assignment` is put in front of the CLI inside the shell command, so
// that the shell itself runs without it.
Shell run_with_env(const std::string& env_assignment, const std::string& args, const std::string& dir) {
  const std::string cmd = "env " + env_assignment + " " + shell_quote(FURROW_CLI) + " " + args + " > " +
                          shell_quote(dir + "/out") + " 2> " + shell_quote(dir + "/err") + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir + "/out"), slurp(dir + "/err")};
}

}  // namespace

TEST_CASE("furrow needs no OpenCASCADE library to start") {
  const std::string dir = scratch_dir("cad-module-start");
  // The dynamic loader's own list of what the program needs (what ldd shows).
  const Shell trace = run_with_env("LD_TRACE_LOADED_OBJECTS=1", "", dir);
  REQUIRE(trace.status == 0);
  CHECK(trace.out.find("libstdc++") != std::string::npos);  // the list is really there
  CHECK(trace.out.find("libTK") == std::string::npos);
}

TEST_CASE("furrow import without its CAD module: exit 3, the places looked at named, nothing written") {
  const std::string dir = scratch_dir("cad-module-missing");
  const std::string out = dir + "/part.json";
  const std::string step = source_path("tests/bad_inputs/cad/points_only.step");
  const Shell missing = run_with_env("FURROW_CAD_MODULE=/nonexistent/furrow_cad.so",
                                     "import " + shell_quote(step) + " --out " + shell_quote(out), dir);
  CHECK(missing.status == 3);
  CHECK(missing.err.find("/nonexistent/furrow_cad.so: no such file") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  // The same file through the module: OpenCASCADE reads it and finds no
  // shape, which is the file's fault (exit 2).
  const Shell found = run_with_env("FURROW_CAD_MODULE=", "import " + shell_quote(step) + " --out " + shell_quote(out), dir);
  CHECK(found.status == 2);
  CHECK(found.err.find("no shape to import") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  // A file that is not CAD is refused before any module is looked for.
  const Shell plain = run_with_env("FURROW_CAD_MODULE=/nonexistent/furrow_cad.so",
                                   "import " + shell_quote(source_path("tests/bad_inputs/cad/not_step.step")) +
                                       " --out " + shell_quote(out),
                                   dir);
  CHECK(plain.status == 2);
  CHECK(plain.err.find("furrow_cad.so") == std::string::npos);
}
