// End-to-end: simulate-measurement writes CSV, DMIS output and an I++ DME
// response log; each reads back to the same coordinates and `furrow compare`
// finds the same deviations in all three. CSV dialect options on the CLI.
#include <doctest/doctest.h>

#include <filesystem>

#include "base/json_fields.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

std::string write_plan(const std::string& dir) {
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, 12, 10, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, dir + "/plan.json");
  return dir + "/plan.json";
}

MeasurementSet read_centres(const std::string& path) {
  MeasurementReadOptions o;
  o.kind = ProbePointKind::probe_centre;
  o.probe_diameter = 2;
  return read_measurements(path, o);
}

}  // namespace

TEST_CASE("simulate-measurement to .csv, .dmo and .res: same coordinates back, same deviations in compare") {
  const std::string dir = test::scratch_dir("cli-measurement-formats");
  const std::string plan = write_plan(dir);
  const std::vector<std::string> names = {"m.csv", "m.dmo", "m.res"};
  for (const std::string& name : names)
    REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--misalign", "1,-2,30,15,-4,2",
                              "--seed", "5", "--out", dir + "/" + name})
                .status == 0);
  CHECK(test::slurp(dir + "/m.dmo").find("F(") != std::string::npos);  // nominals with the actuals
  CHECK(test::slurp(dir + "/m.res").rfind("00001 &\r\n00001 # X(", 0) == 0);
  const MeasurementSet csv = read_centres(dir + "/m.csv");
  REQUIRE(csv.points.size() == 120);
  for (const char* name : {"m.dmo", "m.res"}) {
    CAPTURE(name);
    const MeasurementSet other = read_centres(dir + "/" + name);
    REQUIRE(other.points.size() == csv.points.size());
    for (std::size_t k = 0; k < csv.points.size(); ++k) {
      if (other.points[k].xyz != csv.points[k].xyz) FAIL_CHECK("point " << k << " differs");
      if ((*other.points[k].ijk - *csv.points[k].ijk).norm() > 1e-15) FAIL_CHECK("direction " << k);
    }
  }
  std::vector<std::vector<double>> deviations;
  for (const std::string& name : names) {
    const auto r = test::run_furrow({"compare", kMould, "--measurements", dir + "/" + name, "--points", "centre",
                                     "--probe-diameter", "2", "--tolerance", "0.05", "--out",
                                     dir + "/" + name + ".json"});
    CAPTURE(r.err);
    REQUIRE(r.status == 0);
    const json_fields::json doc = json_fields::load_file(dir + "/" + name + ".json");
    deviations.emplace_back();
    for (const auto& p : doc["points"]) deviations.back().push_back(p["deviation"].get<double>());
  }
  // The same coordinates, but not the same path to the fit: the DMIS file
  // carries its nominals, so its fit starts from them (4 outer iterations),
  // while the CSV and .res fits start from the global search (15). Each stops
  // when a step moves the part by less than the motion tolerance (1e-10 mm),
  // so they agree to about that, here within 1e-8 mm (10 picometres).
  for (std::size_t f = 1; f < deviations.size(); ++f) {
    REQUIRE(deviations[f].size() == deviations[0].size());
    for (std::size_t k = 0; k < deviations[0].size(); ++k)
      if (std::abs(deviations[f][k] - deviations[0][k]) > 1e-8)
        FAIL_CHECK(names[f] << " point " << k << ": " << deviations[f][k] << " vs " << deviations[0][k]);
  }
}

TEST_CASE("compare: CSV dialect options, a saved dialect, and malformed files naming line and column") {
  const std::string dir = test::scratch_dir("cli-measurement-dialects");
  const std::string plan = write_plan(dir);
  REQUIRE(test::run_furrow({"simulate-measurement", kMould, "--plan", plan, "--seed", "2", "--out", dir + "/m.csv"})
              .status == 0);
  // The same points as a German Excel export: ';', decimal comma, mapped names.
  const MeasurementSet ref = read_centres(dir + "/m.csv");
  std::string excel = "\xEF\xBB\xBFPunkt;Xist;Yist;Zist\r\n";
  for (const MeasuredPoint& p : ref.points) {
    std::string line = p.id;
    for (int a = 0; a < 3; ++a) {
      std::string v = json_fields::json(p.xyz[a]).dump();
      for (char& c : v)
        if (c == '.') c = ',';
      line += ";" + v;
    }
    excel += line + "\r\n";
  }
  test::write_text(dir + "/excel.csv", excel);
  test::write_text(dir + "/dialect.json",
                   R"({"delimiter": ";", "decimal_comma": true, "columns": {"id": "Punkt", "x": "Xist", "y": "Yist", "z": "Zist"}})");
  const auto base = [&](const std::string& file, const std::string& out) {
    return std::vector<std::string>{"compare", kMould, "--measurements", dir + "/" + file, "--probe-diameter", "2",
                                    "--plan", plan, "--out", dir + "/" + out};
  };
  const auto a = test::run_furrow(base("m.csv", "a.json"));
  auto with_columns = base("excel.csv", "b.json");
  with_columns.insert(with_columns.end(), {"--delimiter", ";", "--decimal-comma", "--columns", "id=Punkt,x=Xist,y=Yist,z=Zist"});
  const auto b = test::run_furrow(with_columns);
  auto with_dialect = base("excel.csv", "c.json");
  with_dialect.insert(with_dialect.end(), {"--dialect", dir + "/dialect.json"});
  const auto c = test::run_furrow(with_dialect);
  CAPTURE(b.err);
  CAPTURE(c.err);
  REQUIRE(b.status == a.status);
  REQUIRE(c.status == a.status);
  const auto points = [&](const std::string& f) { return json_fields::load_file(dir + "/" + f)["points"]; };
  CHECK(points("b.json") == points("a.json"));
  CHECK(points("c.json") == points("a.json"));

  test::write_text(dir + "/bad.csv", "Punkt;Xist;Yist;Zist\nP1;1,5;2,5;3\nP2;1,5;zwei;3\n");
  auto bad = base("bad.csv", "bad.json");
  bad.insert(bad.end(), {"--dialect", dir + "/dialect.json"});
  const auto r = test::run_furrow(bad);
  CHECK(r.status == 2);
  CHECK(r.err == "error: " + dir + "/bad.csv:3: column 3 (y): \"zwei\" is not a number\n");
  CHECK_FALSE(fs::exists(dir + "/bad.json"));
  auto wrong = base("m.csv", "w.json");
  wrong.insert(wrong.end(), {"--delimiter", "|"});
  const auto w = test::run_furrow(wrong);
  CHECK(w.status == 2);
  CHECK(w.err.find("--delimiter: \"|\" is not a delimiter") != std::string::npos);
  auto comma = base("m.csv", "w.json");
  comma.insert(comma.end(), {"--delimiter", ",", "--decimal-comma"});
  CHECK(test::run_furrow(comma).err.find("a decimal comma needs a delimiter other than ','") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/w.json"));
}
