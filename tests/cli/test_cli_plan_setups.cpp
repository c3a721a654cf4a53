// furrow plan --setups (docs/cmm.md "Setups") on the 40 x 30 x 10 mm box of
// tests/planning/test_setups.cpp with the vertical stylus: one folder per
// setup with plan.json (recording the setup and its part-to-setup
// transform), both programs - which NIST's I++ DME checker accepts - and
// report.json; the top-level report.json holds the coverage per setup and
// combined (top + bottom = 2400 mm^2 of 2 x (1200 + 400 + 300) = 3800);
// two runs give the same bytes; --setup-faces naming no face of the part,
// or a bad list, exits 2 with one message naming it; a job refuses setups.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/cmm/nist_checker.hpp"
#include "io/part_file.hpp"
#include "planning/plan_fixtures.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

struct Inputs {
  std::string dir, part, regions;
};

const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs i;
    i.dir = scratch_dir("cli-plan-setups");
    i.part = i.dir + "/box.json";
    i.regions = i.dir + "/regions.json";
    write_part_json(box_part(40, 30, 10), i.part);
    const CliResult r = run_furrow({"partition", i.part, "--out", i.regions, "--grid", "24x24"});
    REQUIRE(r.status == 0);
    return i;
  }();
  return in;
}

std::vector<std::string> plan_args(const std::string& out) {
  const Inputs& in = inputs();
  return {"plan", in.part, "--regions", in.regions, "--out", out, "--points", "60", "--min-per-region", "4",
          "--allow-uncovered", "--program-date", "2026-11-29"};
}

}  // namespace

TEST_CASE("furrow plan --setups 2: a folder per setup, programs the NIST checker accepts, the same bytes twice") {
  const Inputs& in = inputs();
  std::vector<std::string> args = plan_args(in.dir + "/two");
  args.insert(args.end(), {"--setups", "2"});
  const CliResult r = run_furrow(args);
  CAPTURE(r.err);
  CAPTURE(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("setup 2: the part resting on face 0 (\"top\")") != std::string::npos);
  CHECK(r.out.find("combined over 2 setups:") != std::string::npos);

  const nlohmann::json top = nlohmann::json::parse(slurp(in.dir + "/two/report.json"));
  CHECK(top["format"] == "furrow-plan-setups-report");
  REQUIRE(top["setups"].size() == 2);
  CHECK(top["setups"][1]["resting_face"] == 0);
  CHECK(top["setups"][1]["folder"] == "setup2");
  const double covered = top["combined"]["area"]["covered"].get<double>();
  const double total = top["combined"]["area"]["total"].get<double>();
  CHECK(std::abs(covered - 2400) < 1e-6 * 2400);
  CHECK(std::abs(total - 3800) < 1e-6 * 3800);
  CHECK(std::abs(top["setups"][0]["coverage"]["area"]["covered"].get<double>() - 1200) < 1e-6 * 1200);
  CHECK(std::abs(top["setups"][1]["coverage"]["area"]["covered"].get<double>() - 1200) < 1e-6 * 1200);
  // The sides stay short for the tilt, named with their setup.
  for (const auto& u : top["combined"]["uncovered_regions"]) CHECK(u["state"] == "unreachable_access");

  for (const char* setup : {"setup1", "setup2"}) {
    CAPTURE(setup);
    const std::string folder = in.dir + "/two/" + setup;
    const nlohmann::json plan = nlohmann::json::parse(slurp(folder + "/plan.json"));
    REQUIRE(plan.contains("setup"));
    CHECK(plan["setup"]["index"] == (std::string(setup) == "setup1" ? 1 : 2));
    CHECK(plan["setup"]["part_to_setup"]["rotation"].size() == 3);
    const std::string name = std::string("two_S") + setup[5];
    const std::string prg = slurp(folder + "/" + name + ".prg");
    CHECK(!slurp(folder + "/" + name + ".dmi").empty());
    CHECK(nist_checker_findings(prg, std::string("setups_") + setup + ".prg").empty());
    for (const char* f : {"plan.png", "coverage.png", "report.json", "plan.csv", "plan.qif"})
      CHECK(!slurp(folder + "/" + f).empty());
  }
  CHECK(!slurp(in.dir + "/two/coverage.png").empty());

  // Bytes do not depend on the run (the program names come from the folder's name).
  std::vector<std::string> again = plan_args(in.dir + "/again/two");
  again.insert(again.end(), {"--setups", "2"});
  REQUIRE(run_furrow(again).status == 0);
  for (const char* f : {"report.json", "coverage.png", "setup1/plan.json", "setup2/plan.json", "setup2/two_S2.prg",
                        "setup2/two_S2.dmi", "setup2/report.json", "setup2/coverage.png"}) {
    CAPTURE(f);
    CHECK(slurp(in.dir + "/again/two/" + f) == slurp(in.dir + "/two/" + f));
  }
}

TEST_CASE("furrow plan --setup-faces: a face the part does not have, or not a list of faces, exits 2") {
  const Inputs& in = inputs();
  std::vector<std::string> args = plan_args(in.dir + "/bad");
  args.insert(args.end(), {"--setup-faces", "17"});
  const CliResult r = run_furrow(args);
  CHECK(r.status == 2);
  CHECK(r.err.find("--setup-faces: face 17 is not a face of the part (it has 6 faces") != std::string::npos);
  args = plan_args(in.dir + "/bad2");
  args.insert(args.end(), {"--setup-faces", "3,top"});
  const CliResult b = run_furrow(args);
  CHECK(b.status == 2);
  CHECK(b.err.find("\"top\" is not a face index") != std::string::npos);
  args = plan_args(in.dir + "/bad3");
  args.insert(args.end(), {"--setup-faces", "3,2", "--setups", "2"});
  const CliResult c = run_furrow(args);
  CHECK(c.status == 2);
  CHECK(c.err.find("raise --setups") != std::string::npos);
  // Nothing half-written.
  CHECK(!std::filesystem::exists(in.dir + "/bad"));
}

TEST_CASE("furrow run: a job with plan.setups above 1 is refused before any work, naming the member") {
  nlohmann::json job = nlohmann::json::parse(slurp(source_path("examples/jobs/demo.json")));
  job["part"] = source_path("examples/parts/mould.json");
  job["tool"] = source_path("examples/tools/ball_d24.json");
  job["output"] = "out";
  job["plan"]["setups"] = 2;
  const std::string dir = scratch_dir("cli-plan-setups-job");
  write_text(dir + "/job.json", job.dump(2));
  const CliResult r = run_furrow({"run", dir + "/job.json", "--out", dir + "/out"});
  CHECK(r.status == 2);
  CHECK(r.err.find("plan.setups: a job plans and compares one setup") != std::string::npos);
  CHECK(!std::filesystem::exists(dir + "/out"));
}

TEST_CASE("furrow compare over setups: each setup's file in its frame, one comparison of the whole box, one verdict") {
  // The two setups' plans of the first test, measured by the simulator in
  // their own frames (each program measures its setup's alignment, so a
  // CMM reports setup-frame points), exactly on the nominal surface (no
  // noise): taken back to the part frame they must all fall on the box.
  // Setup 2 is the box upside down, so a file left in its own frame would
  // put the bottom's points 10 mm above the top, far out of tolerance.
  const Inputs& in = inputs();
  std::vector<std::string> args = plan_args(in.dir + "/cmp");
  args.insert(args.end(), {"--setups", "2"});
  REQUIRE(run_furrow(args).status == 0);
  const std::string p1 = in.dir + "/cmp/setup1/plan.json", p2 = in.dir + "/cmp/setup2/plan.json";
  for (const auto& [plan, out] : {std::pair{p1, in.dir + "/m1.csv"}, std::pair{p2, in.dir + "/m2.csv"}}) {
    const CliResult s = run_furrow({"simulate-measurement", in.part, "--plan", plan, "--out", out, "--noise", "0"});
    CAPTURE(s.err);
    REQUIRE(s.status == 0);
  }
  const std::string cmp = in.dir + "/comparison.json";
  const CliResult r = run_furrow({"compare", in.part, "--measurements", in.dir + "/m1.csv", "--measurements",
                                  in.dir + "/m2.csv", "--plan", p1, "--plan", p2, "--out", cmp});
  CAPTURE(r.err);
  CAPTURE(r.out);
  const nlohmann::json plan1 = nlohmann::json::parse(slurp(p1)), plan2 = nlohmann::json::parse(slurp(p2));
  const std::size_t want = plan1["points"].size() + plan2["points"].size();
  const nlohmann::json c = nlohmann::json::parse(slurp(cmp));
  // The sides were never measured: the verdict cannot be PASS (they are
  // named); no point is out of tolerance.
  CHECK(r.status != 2);
  CHECK(r.status != 1);
  std::size_t points = 0;
  double worst = 0;
  for (const auto& p : c["points"]) {
    ++points;
    if (p.contains("deviation") && p["deviation"].is_number()) worst = std::max(worst, std::abs(p["deviation"].get<double>()));
  }
  CHECK(points == want);
  CHECK(worst < 1e-4);
  MESSAGE("compare over 2 setups: " << points << " points, largest |deviation| " << worst << " mm, exit " << r.status);

  // P0001 (setup 1, on the top) measured again in setup 2, in setup 2's
  // frame, 0.01 mm proud of the surface: reported once, with that later
  // reading's deviation, the earlier reading listed as replaced.
  const nlohmann::json& first = plan1["points"][0];
  REQUIRE(first["id"] == "P0001");
  const nlohmann::json& motion = plan2["setup"]["part_to_setup"];
  Eigen::Matrix3d R;
  Eigen::Vector3d t, xyz, ijk;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = motion["rotation"][i][j].get<double>();
    t[i] = motion["translation"][i].get<double>();
    xyz[i] = first["xyz"][i].get<double>();
    ijk[i] = first["ijk"][i].get<double>();
  }
  const Eigen::Vector3d centre = R * (xyz + (1 + 0.01) * ijk) + t, normal = R * ijk;
  char row[256];
  std::snprintf(row, sizeof row, "P0001,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", centre.x(), centre.y(), centre.z(),
                normal.x(), normal.y(), normal.z());
  write_text(in.dir + "/m2again.csv", slurp(in.dir + "/m2.csv") + row);
  const CliResult again = run_furrow({"compare", in.part, "--measurements", in.dir + "/m1.csv", "--measurements",
                                      in.dir + "/m2again.csv", "--plan", p1, "--plan", p2, "--out", in.dir + "/again.json"});
  CAPTURE(again.err);
  CHECK(again.status != 2);
  const nlohmann::json a = nlohmann::json::parse(slurp(in.dir + "/again.json"));
  std::size_t count = 0, p0001 = 0;
  double deviation = 1e9;
  for (const auto& p : a["points"]) {
    ++count;
    if (p["id"] == "P0001") {
      ++p0001;
      deviation = p["deviation"].get<double>();
    }
  }
  CHECK(count == want);
  CHECK(p0001 == 1);
  // Best fit over 47 points moves the part by a small share of the 0.01 mm.
  CHECK(std::abs(deviation - 0.01) < 2e-3);
  REQUIRE(a["replaced"].size() == 1);
  CHECK(a["replaced"][0]["id"] == "P0001");
  CHECK(a["replaced"][0]["file"] == 0);
  CHECK(a["replaced"][0]["by_file"] == 1);
  // The earlier reading, in the part frame: the setup-1 centre on the surface.
  Eigen::Vector3d was;
  for (int i = 0; i < 3; ++i) was[i] = a["replaced"][0]["was"][i].get<double>();
  CHECK((was - (xyz + ijk)).norm() < 1e-9);

  // One plan per file, in the same order.
  const CliResult bad = run_furrow({"compare", in.part, "--measurements", in.dir + "/m1.csv", "--plan", p1, "--plan", p2,
                                    "--out", in.dir + "/bad.json"});
  CHECK(bad.status == 2);
  CHECK(bad.err.find("2 plans (--plan) but 1 measurement files") != std::string::npos);
}
