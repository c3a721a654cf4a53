// furrow plan: what the CMM programs state besides the points — header,
// head-to-ball length, speeds, profile tolerance — taken from the options,
// read back by the strict readers, and the date never from the clock.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>

#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

std::string mould_regions_for_programs() {
  static const std::string path = [] {
    const std::string dir = scratch_dir("cli-plan-programs-regions-" + std::to_string(::getpid()));
    const CliResult r = run_furrow({"partition", source_path("examples/parts/mould.json"), "--out", dir + "/regions.json",
                                    "--grid", "120x100"});
    REQUIRE(r.status == 0);
    return dir + "/regions.json";
  }();
  return path;
}

}  // namespace

TEST_CASE("furrow plan: header, head length, speeds and tolerance come from the options") {
  const std::string dir = scratch_dir("cli-plan-programs");
  const std::string part = source_path("examples/parts/mould.json");
  const std::vector<std::string> args{"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/prog",
                                      "--points", "30", "--revision", "B", "--program-date", "2026-03-14",
                                      "--head-length", "75.5", "--move-speed", "40", "--touch-speed", "3",
                                      "--tolerance", "0.1", "--outside", "0.04"};
  REQUIRE(run_furrow(args).status == 0);
  const std::string dmi = slurp(dir + "/prog/prog.dmi");
  CHECK(dmi.find("$$ part: " + part + "; revision: B; date: 2026-03-14\r\n") != std::string::npos);
  CHECK(dmi.find("PR(REV)=PARTRV/'B'\r\n") != std::string::npos);
  CHECK(dmi.find("S(PROBE1)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,75.500000,2.000000\r\n") != std::string::npos);
  // Zone of width 0.1 with 0.04 on the + side: from 0.04 - 0.1 to 0.04.
  CHECK(dmi.find("T(PROFILE)=TOL/PROFP,-0.060000,0.040000\r\n") != std::string::npos);
  const ProbeProgram dmis = read_dmis_program(dir + "/prog/prog.dmi");
  const ProbeProgram ipp = read_ippdme_program(dir + "/prog/prog.prg");
  CHECK(dmis.move_speed == 40);
  CHECK(dmis.measure_speed == 3);
  CHECK(ipp.move_speed == 40);
  CHECK(ipp.measure_speed == 3);
  CHECK(dmis.head_length == 75.5);
  const InspectionPlan plan = read_plan(dir + "/prog/plan.json");
  REQUIRE(dmis.steps.size() == plan.points.size());
  REQUIRE(ipp.steps.size() == plan.points.size());
  for (const PlannedPoint& p : plan.points) {
    const ProgramStep& d = dmis.steps[static_cast<std::size_t>(p.order) - 1];
    CHECK(d.point.id == p.id);
    CHECK((d.point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((ipp.steps[static_cast<std::size_t>(p.order) - 1].point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
  }
  // Without --program-date the header says so, and a rerun gives the same
  // bytes (nothing is read from the clock).
  const std::vector<std::string> plain{"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/a",
                                       "--points", "30"};
  REQUIRE(run_furrow(plain).status == 0);
  std::vector<std::string> again = plain;
  again[5] = dir + "/b";
  REQUIRE(run_furrow(again).status == 0);
  const std::string a = slurp(dir + "/a/a.dmi");
  CHECK(a.find("revision: not stated; date: not stated") != std::string::npos);
  std::string b = slurp(dir + "/b/b.dmi");
  // The program name is the folder's: the only difference allowed.
  for (std::size_t at; (at = b.find("'b'")) != std::string::npos;) b.replace(at, 3, "'a'");
  b.replace(b.find("probe program b\r\n"), 15, "probe program a");
  b.replace(b.find("'b.dmo'"), 7, "'a.dmo'");
  CHECK(a == b);
}

TEST_CASE("furrow plan: bad program options give one line and exit 2") {
  const std::string dir = scratch_dir("cli-plan-programs-bad");
  const std::string part = source_path("examples/parts/mould.json");
  const std::pair<std::vector<std::string>, const char*> cases[] = {
      {{"--program-date", "2026-02-30"}, "--program-date"},
      {{"--program-date", "yesterday"}, "--program-date"},
      {{"--revision", "it's"}, "--revision"},
      {{"--head-length", "10"}, "--head-length"},
  };
  for (const auto& c : cases) {
    // Named copies, not structured bindings: CAPTURE's lambda cannot capture
    // a binding before C++20, and clang refuses it.
    const std::vector<std::string>& extra = c.first;
    const char* message = c.second;
    std::vector<std::string> args{"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/out",
                                  "--points", "10"};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = run_furrow(args);
    CAPTURE(message);
    CHECK(r.status == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
}

TEST_CASE("furrow plan: the mould (one free-form face) gets a manual alignment, in plan.json and both programs") {
  const std::string dir = scratch_dir("cli-plan-alignment");
  const std::string part = source_path("examples/parts/mould.json");
  REQUIRE(run_furrow({"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/m", "--points", "20"})
              .status == 0);
  const InspectionPlan plan = read_plan(dir + "/m/plan.json");
  REQUIRE(plan.alignment.has_value());
  CHECK(plan.alignment->method == PartAlignment::Method::free_form);
  CHECK_FALSE(plan.alignment->reason.empty());
  const std::vector<PlannedPoint> manual = plan.alignment->points();
  REQUIRE(manual.size() == 3);
  const ProbeProgram dmis = read_dmis_program(dir + "/m/m.dmi");
  const ProbeProgram ipp = read_ippdme_program(dir + "/m/m.prg");
  REQUIRE(dmis.alignment_steps.size() == 3);
  REQUIRE(ipp.alignment_steps.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(dmis.alignment_steps[k].point.id == manual[k].id);
    CHECK((dmis.alignment_steps[k].point.xyz - manual[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((ipp.alignment_steps[k].point.xyz - manual[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((ipp.alignment_steps[k].moves_before.back() - manual[k].approach).cwiseAbs().maxCoeff() <= 5e-7);
  }
  // report.json and plan.csv name the same points.
  const nlohmann::json report = nlohmann::json::parse(slurp(dir + "/m/report.json"));
  REQUIRE(report.contains("alignment"));
  CHECK(report["alignment"]["method"] == "free_form");
  CHECK(report["alignment"]["reason"] == plan.alignment->reason);
  CHECK(report["alignment"]["points"] == 3);
  CHECK(report["alignment"]["datums"].empty());
  REQUIRE(report["alignment"]["manual"].size() == 3);
  const std::string csv = slurp(dir + "/m/plan.csv");
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(report["alignment"]["manual"][k] == manual[k].id);
    CHECK(csv.find("\n" + std::to_string(manual[k].order) + "," + manual[k].id + ",") < csv.find(",FREE_FORM\n"));
  }
  CHECK(csv.find(std::to_string(plan.points.size()) + " points after 3 alignment points") != std::string::npos);
  // The free-form points follow, unchanged by the alignment.
  REQUIRE(dmis.steps.size() == plan.points.size());
  REQUIRE(ipp.steps.size() == plan.points.size());
  for (const PlannedPoint& p : plan.points) {
    const std::size_t k = static_cast<std::size_t>(p.order) - 1;
    CHECK((dmis.steps[k].point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((ipp.steps[k].point.xyz - p.xyz).cwiseAbs().maxCoeff() <= 5e-7);
    CHECK((dmis.steps[k].moves_before.back() - p.approach).cwiseAbs().maxCoeff() <= 5e-7);
  }
  // Naming datums on a part without planes is refused, naming the face.
  const CliResult named = run_furrow({"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/n",
                                      "--points", "20", "--datums", "mould,mould,mould"});
  CHECK(named.status == 2);
  CHECK(named.err.find("is not a plane") != std::string::npos);
  const CliResult bad = run_furrow({"plan", part, "--regions", mould_regions_for_programs(), "--out", dir + "/n",
                                    "--datums", "top"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--datums") != std::string::npos);
}
