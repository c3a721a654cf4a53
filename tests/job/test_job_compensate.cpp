// The job file's "compensate" member through `furrow run`: the mould's
// example program, simulated measurements with a planted bump, compared,
// then compensated inside the job. Oracle: the second implementation -
// `furrow compensate` run by hand on the comparison.json the job wrote must
// give the same program bytes (and the same record apart from its file
// names). Bad members are refused with status 2 before any work, naming
// the member, and nothing is written.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/machining/gcode_reader.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double kBumpRadius = 15;    // [mm]
constexpr double kBumpHeight = 0.05;  // [mm], material left

// The mould job with measurements simulated on a bump; `extra` members are
// added (or replace the defaults) as given.
json mould_job(const std::string& out, const json& extra) {
  const std::string part = test::source_path("examples/parts/mould.json");
  const Eigen::Vector3d c = read_part(part).faces[0].surface().point(0.5, 0.5);
  json job = {{"part", part},
              {"tool", test::source_path("examples/tools/ball_d6.json")},
              {"toolpath", test::source_path("examples/toolpaths/mould_ball6.nc")},
              {"tolerance", {{"zone", 0.2}}},
              {"prediction", {{"tolerance", 0.01}}},
              {"plan", {{"points", 300}}},
              {"measurements",
               {{"simulate",
                 {{"noise", 0.001},
                  {"seed", 3},
                  {"bumps", json::array({{c.x(), c.y(), c.z(), kBumpRadius, kBumpHeight}})}}}}},
              {"comparison", {{"align", "cmm"}, {"outlier_rejection", false}}},
              {"compensate", {{"out", "comp.nc"}, {"gain", 0.5}}},
              {"output", out}};
  for (const auto& [key, value] : extra.items()) {
    if (value.is_null())
      job.erase(key);
    else
      job[key] = value;
  }
  return job;
}

// The record without the members that name files (the job names them
// relative to its output folder, the command as given).
json without_names(json record) {
  for (const char* key : {"part", "comparison", "toolpath", "program"}) record.erase(key);
  return record;
}

}  // namespace

TEST_CASE("job compensate: furrow run writes the program furrow compensate writes from the job's comparison") {
  const std::string dir = test::scratch_dir("job-compensate");
  const std::string out = dir + "/out";
  test::write_text(dir + "/job.json", mould_job(out, json::object()).dump(1));
  const auto run = run_furrow({"run", dir + "/job.json"});
  INFO(run.err);
  REQUIRE(run.status == 0);  // the bump (50 um) is inside the 0.2 mm zone: PASS
  REQUIRE(fs::exists(out + "/comp.nc"));
  REQUIRE(fs::exists(out + "/comp.json"));
  CHECK(run.out.find("compensate: comp.nc") != std::string::npos);

  const std::string program = test::source_path("examples/toolpaths/mould_ball6.nc");
  const auto by_hand = run_furrow({"compensate", test::source_path("examples/parts/mould.json"), "--comparison",
                                   out + "/comparison.json", "--toolpath", program, "--tool",
                                   test::source_path("examples/tools/ball_d6.json"), "--out", dir + "/hand.nc",
                                   "--gain", "0.5"});
  INFO(by_hand.err);
  REQUIRE(by_hand.status == 0);
  const std::string compensated = slurp(out + "/comp.nc");
  CHECK(compensated == slurp(dir + "/hand.nc"));
  // The bump moved the program: the check above is not of two copies of the input.
  CHECK(compensated != slurp(program));
  const json record = json::parse(slurp(out + "/comp.json"));
  CHECK(without_names(record) == without_names(json::parse(slurp(dir + "/hand.json"))));
  CHECK(record["gain"].get<double>() == 0.5);
  // Gain 0.5 of the 50 um bump at its top: the largest offset is half its
  // height, less what the smoothing takes off the peak (well under 10 %).
  CHECK(std::abs(record["largest_offset"].get<double>() - 0.5 * kBumpHeight) < 0.1 * 0.5 * kBumpHeight);
  // The prediction of the written program beside it: furrow predict's of
  // comp.nc with the job's prediction options (the second implementation),
  // but for the file names, which the job gives relative to its folder.
  REQUIRE(fs::exists(out + "/comp_prediction.json"));
  const auto predicted = run_furrow({"predict", test::source_path("examples/parts/mould.json"), "--toolpath",
                                     out + "/comp.nc", "--tool", test::source_path("examples/tools/ball_d6.json"),
                                     "--tolerance", "0.01", "--out", dir + "/hand_prediction.json"});
  INFO(predicted.err);
  REQUIRE(predicted.status == 0);
  json job_prediction = json::parse(slurp(out + "/comp_prediction.json"));
  json hand_prediction = json::parse(slurp(dir + "/hand_prediction.json"));
  CHECK(job_prediction["toolpath"] == "comp.nc");
  for (json* p : {&job_prediction, &hand_prediction})
    for (const char* key : {"part", "toolpath"}) p->erase(key);
  CHECK(job_prediction == hand_prediction);

  // The job's report has the Compensation section of its record: what
  // `furrow report --compensation` makes of the job's comparison and
  // record (the second implementation), but for the record's name.
  const json report = json::parse(slurp(out + "/report.json"));
  REQUIRE(report["compensation"].is_object());
  CHECK(report["compensation"]["record"] == "comp.json");
  CHECK(slurp(out + "/report.html").find("<section id=\"compensation\">") != std::string::npos);
  CHECK(fs::exists(out + "/figures/compensation_after.png"));
  const auto reported = run_furrow({"report", out + "/comparison.json", "--compensation", out + "/comp.json",
                                    "--out", dir + "/hand_report"});
  INFO(reported.err);
  REQUIRE(reported.status == 0);
  json by_job = report["compensation"], by_command = json::parse(slurp(dir + "/hand_report/report.json"))["compensation"];
  by_job.erase("record");
  by_command.erase("record");
  CHECK(by_job == by_command);
  CHECK(by_job["overall"]["rms_after"] == record["expected"]["overall"]["rms_after"]);
  CHECK(slurp(out + "/figures/compensation_after.png") == slurp(dir + "/hand_report/figures/compensation_after.png"));
}

TEST_CASE("job compensate: with rework, furrow run writes the rework program furrow compensate --rework writes") {
  const std::string dir = test::scratch_dir("job-compensate-rework");
  const std::string out = dir + "/out";
  // The job's zone (0.2 mm) would leave the 50 um bump alone: a threshold
  // of 20 um asks for it.
  test::write_text(dir + "/job.json",
                   mould_job(out, {{"compensate", {{"out", "rework.nc"}, {"rework", true}, {"rework_threshold", 0.02}}}})
                       .dump(1));
  const auto run = run_furrow({"run", dir + "/job.json"});
  INFO(run.err);
  REQUIRE(run.status == 0);
  REQUIRE(fs::exists(out + "/rework.nc"));
  CHECK(run.out.find("compensate: rework rework.nc") != std::string::npos);
  const auto by_hand = run_furrow({"compensate", test::source_path("examples/parts/mould.json"), "--comparison",
                                   out + "/comparison.json", "--toolpath",
                                   test::source_path("examples/toolpaths/mould_ball6.nc"), "--tool",
                                   test::source_path("examples/tools/ball_d6.json"), "--out", dir + "/hand.nc",
                                   "--rework", "--rework-threshold", "0.02"});
  INFO(by_hand.err);
  REQUIRE(by_hand.status == 0);
  const std::string rework = slurp(out + "/rework.nc");
  CHECK(rework == slurp(dir + "/hand.nc"));
  const json record = json::parse(slurp(out + "/rework.json"));
  CHECK(without_names(record) == without_names(json::parse(slurp(dir + "/hand.json"))));
  // Not a copy of the whole program: only the stretches over the bump.
  CHECK(record["rework"]["moves_kept"].get<std::size_t>() > 0);
  CHECK(record["rework"]["moves_kept"].get<std::size_t>() < record["rework"]["moves"].get<std::size_t>() / 4);
}

TEST_CASE("job compensate: a bad member is status 2 naming it, before any work, nothing written") {
  const std::string dir = test::scratch_dir("job-compensate-bad");
  struct Case {
    json extra;
    std::string named;
  };
  const std::vector<Case> cases = {
      {{{"compensate", {{"out", "comp.nc"}, {"gain", 3}}}}, "compensate.gain"},
      {{{"compensate", {{"out", "comp.nc"}, {"clip_back", 31}}}}, "compensate.clip_back"},
      {{{"compensate", {{"out", "comp.nc"}, {"max_offset", -1}}}}, "compensate.max_offset"},
      {{{"compensate", {{"out", "comp.nc"}, {"gian", 0.5}}}}, "gian"},
      {{{"compensate", {{"gain", 0.5}}}}, "compensate.out"},
      {{{"compensate", {{"out", "../comp.nc"}}}}, "compensate.out"},
      {{{"compensate", {{"out", "comp.apt"}}}}, "compensate.out"},
      {{{"compensate", {{"out", "comp.json"}}}}, "compensate.out"},
      {{{"compensate", {{"out", "comp.nc"}, {"rework", true}, {"rework_threshold", -0.01}}}},
       "compensate.rework_threshold"},
      {{{"compensate", {{"out", "comp.nc"}, {"rework_threshold", 0.01}}}}, "compensate.rework_threshold"},
      {{{"measurements", nullptr}}, "compensate"},
      // A program with a tool table is compensated pass by pass, but its
      // rework takes one tool.
      {{{"toolpath",
         {{"file", test::source_path("examples/toolpaths/mould_ball6.nc")},
          {"tools", test::source_path("examples/tools/table.json")}}},
        {"compensate", {{"out", "comp.nc"}, {"rework", true}}}},
       "\"rework\" takes a program of one tool"},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string out = dir + "/out" + std::to_string(k);
    test::write_text(dir + "/job.json", mould_job(out, cases[k].extra).dump(1));
    const auto r = run_furrow({"run", dir + "/job.json"});
    INFO(k, r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(cases[k].named) != std::string::npos);
    CHECK(r.err.find("partition") == std::string::npos);  // refused before the stages ran
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("job compensate: a job whose tool path is a CSV path is refused clearly") {
  const std::string dir = test::scratch_dir("job-compensate-no-program");
  const std::string csv = dir + "/path.csv";
  test::write_text(csv, "x,y,z\n0,0,10\n1,0,10\n");
  const std::string out = dir + "/out";
  test::write_text(dir + "/job.json", mould_job(out, {{"toolpath", csv}}).dump(1));
  const auto r = run_furrow({"run", dir + "/job.json"});
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.err.find("compensat") != std::string::npos);
  CHECK(r.err.find("toolpath") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("job compensate: a generated tool path is compensated as furrow compensate compensates the job's toolpath.nc") {
  // A small warped plate (a bilinear patch, 40 x 30 mm, 0 to 4 mm high) so
  // that the job generates its path in a moment; a +50 um bump planted in
  // its middle; steps of at most 1 mm, so that tips stand on the bump
  // (compensation moves tips). The second implementation: furrow compensate on the
  // toolpath.nc and comparison.json the job wrote.
  const std::string dir = test::scratch_dir("job-compensate-generated");
  const std::string part = dir + "/plate.json", out = dir + "/out";
  Part plate;
  plate.faces.emplace_back("plate", make_bilinear({0, 0, 0}, {40, 0, 2}, {0, 30, 1}, {40, 30, 4}));
  write_part_json(plate, part);
  const Eigen::Vector3d c = read_part(part).faces[0].surface().point(0.5, 0.5);
  const std::string tool = test::source_path("examples/tools/ball_d6.json");
  const json job = {{"part", part},
                    {"tool", tool},
                    {"toolpath", {{"generate", {{"scallop", 0.01}, {"tolerance", 0.01}, {"max_step", 1.0}}}}},
                    {"tolerance", {{"zone", 0.2}}},
                    {"plan", {{"points", 150}}},
                    {"measurements",
                     {{"simulate",
                       {{"noise", 0.001},
                        {"seed", 4},
                        {"bumps", json::array({{c.x(), c.y(), c.z(), 10.0, kBumpHeight}})}}}}},
                    {"comparison", {{"align", "cmm"}, {"outlier_rejection", false}}},
                    {"compensate", {{"out", "comp.nc"}, {"gain", 0.5}}},
                    {"output", out}};
  test::write_text(dir + "/job.json", job.dump(1));
  const auto run = run_furrow({"run", dir + "/job.json"});
  INFO(run.out << run.err);
  REQUIRE(run.status == 0);
  REQUIRE(fs::exists(out + "/toolpath.nc"));
  REQUIRE(fs::exists(out + "/comp.nc"));
  const auto by_hand = run_furrow({"compensate", part, "--comparison", out + "/comparison.json", "--toolpath",
                                   out + "/toolpath.nc", "--tool", tool, "--out", dir + "/hand.nc", "--gain", "0.5"});
  INFO(by_hand.err);
  REQUIRE(by_hand.status == 0);
  const std::string compensated = slurp(out + "/comp.nc");
  CHECK(compensated == slurp(dir + "/hand.nc"));
  CHECK(compensated != slurp(out + "/toolpath.nc"));  // the bump moved it
  const json record = json::parse(slurp(out + "/comp.json"));
  CHECK(record["toolpath"] == "toolpath.nc");
  CHECK(without_names(record) == without_names(json::parse(slurp(dir + "/hand.json"))));
  CHECK(record["moves_moved"].get<int>() > 0);
  CHECK(std::abs(record["largest_offset"].get<double>() - 0.5 * kBumpHeight) < 0.2 * 0.5 * kBumpHeight);
  CHECK(json::parse(slurp(out + "/report.json"))["compensation"].is_object());
}

TEST_CASE("job compensate: a program the z-map check still refuses is exit 3 and no folder is written") {
  // One pass of the example program alone, 11 mm beside the planted bump's
  // centre where the field slopes across it (as in furrow compensate's own
  // test): its compensated ball cuts beside the pass deeper than the offset
  // allows, and with no clip-back round the check refuses it.
  const std::string dir = test::scratch_dir("job-compensate-refused");
  const std::string text = slurp(test::source_path("examples/toolpaths/mould_ball6.nc"));
  const Eigen::Vector3d c =
      read_part(test::source_path("examples/parts/mould.json")).faces[0].surface().point(0.5, 0.5);
  const Toolpath all = parse_gcode(text, "mould_ball6.nc");
  std::size_t chosen = 0;
  for (std::size_t p = 1; p < all.passes.size(); ++p)
    if (std::abs(all.passes[p].points[0].position.y() - c.y() - 11) <
        std::abs(all.passes[chosen].points[0].position.y() - c.y() - 11))
      chosen = p;
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const ToolpathPass& pass = all.passes[chosen];
  std::string single = "G21 G90 G17\n";
  char rapid[96];
  std::snprintf(rapid, sizeof rapid, "G0 X%.4f Y%.4f Z34.6326\nG0 Z%.4f\n", pass.points[0].position.x(),
                pass.points[0].position.y(), pass.points[0].position.z());
  single += rapid;
  for (int k = pass.points[1].line; k <= pass.points.back().line; ++k) single += lines[std::size_t(k - 1)] + "\n";
  single += "G0 Z34.6326\nM30\n";
  test::write_text(dir + "/single.nc", single);
  const std::string out = dir + "/out";
  json job = mould_job(out, {{"toolpath", dir + "/single.nc"},
                             {"plan", {{"points", 600}, {"prediction", false}}},
                             {"comparison", {{"align", "cmm"}, {"outlier_rejection", false}, {"prediction", false}}},
                             {"compensate", {{"out", "comp.nc"}, {"clip_back", 0}}}});
  job["measurements"]["simulate"]["prediction"] = false;
  test::write_text(dir + "/job.json", job.dump(1));
  const auto r = run_furrow({"run", dir + "/job.json"});
  INFO(r.out << r.err);
  CHECK(r.status == 3);
  CHECK(r.err.find("compensate: nothing written: after 0 clip-back rounds") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // The command's default rounds rescue the same job: the refusal above was the check's, not the job's.
  job["compensate"].erase("clip_back");
  test::write_text(dir + "/job.json", job.dump(1));
  const auto rescued = run_furrow({"run", dir + "/job.json"});
  INFO(rescued.out << rescued.err);
  CHECK(rescued.status == 0);
  CHECK(fs::exists(out + "/comp.nc"));
}
