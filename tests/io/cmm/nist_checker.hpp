#pragma once
// NIST's I++ DME context checker (shared/tools/nist-ippdme-checker, README
// beside it) run on a command file, for the tests that hold Furrow's
// programs to it (docs/cmm.md "Checking programs"). The checker must be
// there: standards_path() throws otherwise, and its self-test (it reports
// the planted errors of checkerCmdErrors.prg) must pass before any clean
// result counts.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <sys/wait.h>

#include "support/run_cli.hpp"
#include "support/shared_standards.hpp"

namespace furrow::test {

inline int run_shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

inline const std::string& nist_checker() {
  static const std::string check = [] {
    const std::string path = standards_path("tools/nist-ippdme-checker/check");
    const std::string out = scratch_dir("nist-checker-self-test") + "/out.txt";
    const int rc = run_shell(shell_quote(path) + " --self-test > " + shell_quote(out) + " 2>&1");
    INFO(slurp(out));
    REQUIRE(rc == 0);
    return path;
  }();
  return check;
}

// The checker's findings on `prg_text` (saved as `name`); empty when it
// reports none (exit 0).
inline std::string nist_checker_findings(const std::string& prg_text, const std::string& name) {
  const std::string& check = nist_checker();
  const std::string dir = scratch_dir("nist-checker-" + name);
  const std::string prg = dir + "/" + name;
  write_text(prg, prg_text);
  const int rc = run_shell(shell_quote(check) + " " + shell_quote(prg) + " > " + shell_quote(dir + "/out.txt") + " 2>&1");
  return rc == 0 ? "" : "exit " + std::to_string(rc) + ": " + slurp(dir + "/out.txt");
}

}  // namespace furrow::test
