// furrow plan --head --tips auto (docs/cmm.md "Tips chosen by the planner")
// on the analytic undercut of tests/planning/test_auto_tips.cpp: a head file
// with no qualified tip works with --tips auto and lists both tips it
// chose as new, in plan.json, report.json, the DMIS program (one SNSDEF per
// tip, a comment naming the new ones) and the I++ DME program (tool names),
// which NIST's I++ DME checker accepts; an empty list without --tips auto
// and a bad --tips value exit 2 with one line naming the problem.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "io/cmm/nist_checker.hpp"
#include "io/part_file.hpp"
#include "planning/plan_fixtures.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const char* kEmptyHead = R"({
  "head": {"type": "test", "a": {"min": 0, "max": 90, "step": 45}, "b": {"min": -90, "max": 180, "step": 90},
           "length": 30, "diameter": 24},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": []
})";

struct Inputs {
  std::string dir, part, regions, head;
};

const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs i;
    i.dir = scratch_dir("cli-plan-tips");
    i.part = i.dir + "/undercut.json";
    i.regions = i.dir + "/regions.json";
    i.head = i.dir + "/head.json";
    write_part_json(undercut_part(10, 20, 20, 15), i.part);
    write_text(i.head, kEmptyHead);
    const CliResult r = run_furrow({"partition", i.part, "--out", i.regions, "--grid", "60x60"});
    REQUIRE(r.status == 0);
    return i;
  }();
  return in;
}

std::vector<std::string> plan_args(const std::string& out) {
  const Inputs& in = inputs();
  return {"plan", in.part, "--regions", in.regions, "--out", out, "--head", in.head, "--max-tilt", "50",
          "--points", "40", "--min-per-region", "4"};
}

}  // namespace

TEST_CASE("furrow plan --tips auto: an empty qualified list, the chosen tips listed as new in every file") {
  const Inputs& in = inputs();
  std::vector<std::string> args = plan_args(in.dir + "/auto");
  args.insert(args.end(), {"--tips", "auto"});
  const CliResult r = run_furrow(args);
  CAPTURE(r.err);
  CAPTURE(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("tips in the order used: A0B0 (new) A90B0 (new); 2 to qualify") != std::string::npos);
  CHECK(r.out.find("exact, optimal") != std::string::npos);

  const nlohmann::json plan = nlohmann::json::parse(slurp(in.dir + "/auto/plan.json"));
  REQUIRE(plan["tips"].size() == 2);
  CHECK(plan["tips"][0] == nlohmann::json({{"a", 0}, {"b", 0}, {"qualified", false}}));
  CHECK(plan["tips"][1] == nlohmann::json({{"a", 90}, {"b", 0}, {"qualified", false}}));
  const nlohmann::json report = nlohmann::json::parse(slurp(in.dir + "/auto/report.json"));
  CHECK(report["tips"]["choice"] == "auto");
  CHECK(report["tips"]["to_qualify"] == 2);
  CHECK(report["tips"]["method"] == "exact");
  CHECK(report["tips"]["optimal"] == true);
  CHECK(report["tips"]["order"][1]["name"] == "A90B0");
  // Points per tip add up to the plan's.
  int points = 0;
  for (const auto& t : report["tips"]["order"]) points += t["points"].get<int>();
  CHECK(points == static_cast<int>(plan["points"].size()));

  const std::string dmis = slurp(in.dir + "/auto/auto.dmi");
  CHECK(dmis.find("$$ tips in the order used: A0B0 (new: qualify it), A90B0 (new: qualify it)") != std::string::npos);
  CHECK(dmis.find("S(PROBE1_A0B0)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,45.000000,2.000000") != std::string::npos);
  CHECK(dmis.find("S(PROBE1_A90B0)=SNSDEF/PROBE,INDEX,POL,90,0,0,0,-1,45.000000,2.000000") != std::string::npos);
  CHECK(dmis.find("SNSLCT/S(PROBE1_A90B0)") != std::string::npos);
  const std::string prg = slurp(in.dir + "/auto/auto.prg");
  CHECK(prg.find("ChangeTool(\"Probe1_A0B0\")") != std::string::npos);
  CHECK(prg.find("ChangeTool(\"Probe1_A90B0\")") != std::string::npos);
  CHECK(nist_checker_findings(prg, "auto_tips.prg").empty());

  // Bytes do not depend on the run.
  std::vector<std::string> again = plan_args(in.dir + "/auto2");
  again.insert(again.end(), {"--tips", "auto"});
  REQUIRE(run_furrow(again).status == 0);
  CHECK(slurp(in.dir + "/auto2/plan.json") == slurp(in.dir + "/auto/plan.json"));
}

TEST_CASE("furrow plan --tips: an empty qualified list without auto and a bad value exit 2") {
  const Inputs& in = inputs();
  const CliResult empty = run_furrow(plan_args(in.dir + "/empty"));
  CHECK(empty.status == 2);
  CHECK(empty.err.find("head.json.qualified: no qualified tip is listed") != std::string::npos);
  CHECK(empty.err.find("--tips auto") != std::string::npos);
  std::vector<std::string> bad = plan_args(in.dir + "/bad");
  bad.insert(bad.end(), {"--tips", "best"});
  const CliResult b = run_furrow(bad);
  CHECK(b.status == 2);
  CHECK(b.err.find("\"best\" is not a tip choice") != std::string::npos);
  // --tips auto needs a head.
  const CliResult no_head = run_furrow({"plan", in.part, "--regions", in.regions, "--out", in.dir + "/nohead", "--tips", "auto"});
  CHECK(no_head.status == 2);
  CHECK(no_head.err.find("--tips auto chooses among the orientations of an indexable head") != std::string::npos);
}
