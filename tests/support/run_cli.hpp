#pragma once
// Runs the built furrow executable as a user would and captures its exit
// status, standard output and standard error (end-to-end CLI tests).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace furrow::test {

struct CliResult {
  int status = -1;
  std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh, empty scratch folder for one test. ctest -j runs each test case as
// its own process, and a fixture shared by several cases of one file is built
// once per process; the pid keeps two of them from writing the same folder.
inline std::string scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(FURROW_BINARY_DIR) / "test-scratch" /
                   (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline CliResult run_furrow(const std::vector<std::string>& args, const std::string& stdin_file = "") {
  static int counter = 0;
  const std::string base = scratch_dir("cli-capture-" + std::to_string(counter++));
  std::string cmd = shell_quote(FURROW_CLI);
  for (const auto& a : args) cmd += " " + shell_quote(a);
  cmd += " < " + shell_quote(stdin_file.empty() ? "/dev/null" : stdin_file);
  cmd += " > " + shell_quote(base + "/out") + " 2> " + shell_quote(base + "/err");
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(base + "/out");
  r.err = slurp(base + "/err");
  return r;
}

inline std::string source_path(const std::string& relative) {
  return std::string(FURROW_SOURCE_DIR) + "/" + relative;
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Number of lines in a text (an error should be exactly one).
inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

}  // namespace furrow::test
