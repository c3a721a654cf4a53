// Every kind of I++ DME program Furrow writes passes NIST's context checker
// with no finding (docs/cmm.md "Checking programs"): the vertical stylus, an
// indexable head, and what `furrow plan` and `furrow remeasure` write. The
// datum programs (planes on a multi-face STEP part, a bore, the free-form
// mould's manual alignment) are checked where they are made
// (test_alignment_programs.cpp, test_bore_alignment.cpp). Each program also
// reads back through the reader of any client's programs, with its PtMeas
// where Furrow's own reader finds them.
#include <doctest/doctest.h>

#include <filesystem>

#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_session.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "nist_checker.hpp"
#include "program_fixtures.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

// The checker clean, and both readers agreeing on the points.
void check_program(const std::string& text, const std::string& name) {
  CAPTURE(name);
  CHECK(test::nist_checker_findings(text, name) == "");
  const ProbeProgram strict = parse_ippdme_program(text, name);
  const IppdmeSession any = parse_ippdme_session(text, name);
  REQUIRE(any.ptmeas.size() == strict.alignment_steps.size() + strict.steps.size());
  std::size_t k = 0;
  for (const auto* steps : {&strict.alignment_steps, &strict.steps})
    for (const ProgramStep& s : *steps) {
      CHECK(*any.ptmeas[k].target == s.point.xyz);
      CHECK((*any.ptmeas[k].ijk - s.point.ijk).norm() < 1e-15);
      ++k;
    }
}

}  // namespace

TEST_CASE("NIST's checker is there and catches the planted errors before any clean result counts") {
  CHECK_FALSE(test::nist_checker().empty());
  const std::string planted = test::slurp(test::standards_path("tools/nist-ippdme-checker/test_files/checkerCmdErrors.prg"));
  CHECK(test::nist_checker_findings(planted, "planted.prg") != "");
}

TEST_CASE("Furrow's I++ DME programs pass NIST's context checker: vertical stylus and indexable head") {
  check_program(ippdme_program_text(test::tiny_program()), "vertical.prg");
  check_program(ippdme_program_text(test::tipped_program()), "head.prg");
}

TEST_CASE("Furrow's I++ DME programs pass NIST's context checker: furrow plan and furrow remeasure") {
  const std::string dir = test::scratch_dir("ippdme-conformance-cli");
  const std::string part = test::source_path("examples/parts/two_face.json");
  REQUIRE(test::run_furrow({"partition", part, "--out", dir + "/regions.json", "--grid", "60x40"}).status == 0);
  const test::CliResult plan = test::run_furrow({"plan", part, "--regions", dir + "/regions.json", "--out",
                                                 dir + "/two", "--points", "40"});
  INFO(plan.err);
  REQUIRE(plan.status == 0);
  check_program(test::slurp(dir + "/two/two.prg"), "two.prg");
  // A blunder makes the comparison inconclusive, and remeasure writes a
  // program for what it left open.
  REQUIRE(test::run_furrow({"simulate-measurement", part, "--plan", dir + "/two/plan.json", "--seed", "3",
                            "--outliers", "1", "--out", dir + "/m.csv"})
              .status == 0);
  const test::CliResult compare = test::run_furrow({"compare", part, "--measurements", dir + "/m.csv", "--plan",
                                                    dir + "/two/plan.json", "--out", dir + "/first.json"});
  INFO(compare.out << compare.err);
  REQUIRE(compare.status == 4);
  const test::CliResult again = test::run_furrow({"remeasure", dir + "/first.json", "--out", dir + "/again"});
  INFO(again.out << again.err);
  REQUIRE(again.status == 0);
  std::size_t programs = 0;
  for (const auto& e : fs::directory_iterator(dir + "/again"))
    if (e.path().extension() == ".prg") {
      check_program(test::slurp(e.path().string()), e.path().filename().string());
      ++programs;
    }
  CHECK(programs == 1);
}
