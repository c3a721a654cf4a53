// `furrow compensate --tools`: a program that changes tools (T1 M6 ... T2
// M6) compensated with each move's own tool. The mould measured with a
// planted +50 um bump (the shared fixture); a program written here from the
// mould's contact points (examples/toolpaths/mould_ball6.csv), its passes
// on one side of the bump cut with a 6 mm ball (T1) and those on the other
// side with a 4 mm ball (T2), each tip placed for its own ball from the
// contact (T = P + r n - r z, docs/architecture.md "Cutter geometry").
// Oracle, a second implementation: each half written as a program of its
// own, with one tool, and compensated alone; the two-tool program's moves
// must be exactly theirs, one after the other.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/machining/gcode_reader.hpp"
#include "mould_bump_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

struct Contact {
  Eigen::Vector3d p, n;
};

// The contact points of the example program, pass by pass.
std::vector<std::vector<Contact>> example_contacts() {
  std::ifstream in(test::source_path("examples/toolpaths/mould_ball6.csv"));
  std::string line;
  std::map<int, std::vector<Contact>> passes;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("pass", 0) == 0) continue;
    int pass = 0;
    Contact c;
    REQUIRE(std::sscanf(line.c_str(), "%d,%lf,%lf,%lf,%lf,%lf,%lf", &pass, &c.p.x(), &c.p.y(), &c.p.z(), &c.n.x(),
                        &c.n.y(), &c.n.z()) == 7);
    passes[pass].push_back(c);
  }
  std::vector<std::vector<Contact>> out;
  for (auto& [index, pass] : passes) out.push_back(std::move(pass));
  return out;
}

// G-code of `passes`, each tip that of a ball of radius r on its contact,
// after the line `T n M6`, each pass reached from a retract at 40 mm.
std::string ball_passes(const std::vector<std::vector<Contact>>& passes, double r, int tool) {
  std::string out = "T" + std::to_string(tool) + " M6\n";
  char buf[160];
  for (const std::vector<Contact>& pass : passes) {
    for (std::size_t k = 0; k < pass.size(); ++k) {
      const Eigen::Vector3d t = pass[k].p + r * pass[k].n - r * Eigen::Vector3d::UnitZ();
      if (k == 0) {
        std::snprintf(buf, sizeof buf, "G0 Z40.0000\nG0 X%.4f Y%.4f\nG0 Z%.4f\n", t.x(), t.y(), t.z());
      } else {
        std::snprintf(buf, sizeof buf, "G1 X%.4f Y%.4f Z%.4f%s\n", t.x(), t.y(), t.z(), k == 1 ? " F1000" : "");
      }
      out += buf;
    }
  }
  return out + "G0 Z40.0000\n";
}

const char* kHeader = "%\n(two balls)\nG21 G90 G17\n";
const char* kEnd = "M5\nM30\n%\n";

Toolpath compensated(const test::MouldBump& m, const std::string& name, const std::vector<std::string>& tool_args) {
  std::vector<std::string> args = {"compensate", m.part, "--comparison", m.comparison, "--toolpath",
                                   m.dir + "/" + name + ".nc", "--out", m.dir + "/" + name + "_comp.nc"};
  args.insert(args.end(), tool_args.begin(), tool_args.end());
  const auto r = run_furrow(args);
  INFO(name << ": " << r.out << r.err);
  REQUIRE(r.status == 0);
  return parse_gcode(slurp(m.dir + "/" + name + "_comp.nc"), name + "_comp.nc");
}

}  // namespace

TEST_CASE("compensate --tools: a program that changes tools moves each pass as its own tool alone would") {
  const test::MouldBump m = test::measured_mould_bump("cli-compensate-tools", 15, 0.05, 25, 11);
  const std::vector<std::vector<Contact>> passes = example_contacts();
  REQUIRE(passes.size() > 100);
  // The passes run along x; those below the bump's centre are cut with the
  // 6 mm ball, the others with the 4 mm one: both cut through the bump.
  std::vector<std::vector<Contact>> low, high;
  for (const auto& pass : passes) (pass.front().p.y() < m.centre.y() ? low : high).push_back(pass);
  REQUIRE(low.size() > 20);
  REQUIRE(high.size() > 20);
  const std::string first = ball_passes(low, 3, 1), second = ball_passes(high, 2, 2);
  test::write_text(m.dir + "/two.nc", kHeader + first + second + kEnd);
  test::write_text(m.dir + "/first.nc", kHeader + first + kEnd);
  test::write_text(m.dir + "/second.nc", kHeader + second + kEnd);
  test::write_text(m.dir + "/ball4.json", "{\"name\": \"BALL-D4\", \"type\": \"ball\", \"diameter\": 4}\n");
  test::write_text(m.dir + "/table.json",
                   "{\"T1\": \"" + m.tool + "\", \"T2\": \"" + m.dir + "/ball4.json\"}\n");

  const Toolpath two = compensated(m, "two", {"--tools", m.dir + "/table.json", "--predict-out",
                                              m.dir + "/two_prediction.json", "--cell", "2"});
  const Toolpath alone1 = compensated(m, "first", {"--tool", m.tool});
  const Toolpath alone2 = compensated(m, "second", {"--tool", m.dir + "/ball4.json"});

  // The oracle: every move of the two-tool program is the move its tool's
  // half gets compensated alone, to the written decimal.
  REQUIRE(two.passes.size() == alone1.passes.size() + alone2.passes.size());
  std::size_t compared = 0;
  for (std::size_t p = 0; p < two.passes.size(); ++p) {
    const bool in_first = p < alone1.passes.size();
    const ToolpathPass& expected = in_first ? alone1.passes[p] : alone2.passes[p - alone1.passes.size()];
    const ToolpathPass& got = two.passes[p];
    CHECK(got.tool == (in_first ? 1 : 2));
    REQUIRE(got.points.size() == expected.points.size());
    for (std::size_t k = 0; k < got.points.size(); ++k, ++compared) {
      CHECK(got.points[k].position == expected.points[k].position);
      CHECK(got.points[k].feed == expected.points[k].feed);
    }
  }
  MESSAGE(compared << " points compared over " << two.passes.size() << " passes");
  // Structure: the same tool changes, at the same places.
  REQUIRE(two.tool_changes.size() == 2);
  const std::string text = slurp(m.dir + "/two_comp.nc");
  CHECK(text.find("T1 M6\n") == std::string(kHeader).size());
  CHECK(text.find("\nT2 M6\n") != std::string::npos);
  CHECK(test::lines_of(text).size() == test::lines_of(slurp(m.dir + "/two.nc")).size());

  // --predict-out predicts the written program with its tools: what furrow
  // predict --tools gives for the written file, byte for byte.
  const auto predicted = run_furrow({"predict", m.part, "--tools", m.dir + "/table.json", "--toolpath",
                                     m.dir + "/two_comp.nc", "--cell", "2", "--out", m.dir + "/two_again.json"});
  INFO(predicted.err);
  REQUIRE(predicted.status == 0);
  CHECK(slurp(m.dir + "/two_prediction.json") == slurp(m.dir + "/two_again.json"));
  CHECK(json::parse(slurp(m.dir + "/two_prediction.json"))["tools"].size() == 2);

  // Both tools' moves were moved (the halves each cross the bump), so the
  // equality above is not that of unmoved programs.
  const json record1 = json::parse(slurp(m.dir + "/first_comp.json"));
  const json record2 = json::parse(slurp(m.dir + "/second_comp.json"));
  const json record = json::parse(slurp(m.dir + "/two_comp.json"));
  CHECK(record1["moves_moved"].get<int>() > 100);
  CHECK(record2["moves_moved"].get<int>() > 100);
  CHECK(record["moves_moved"].get<int>() == record1["moves_moved"].get<int>() + record2["moves_moved"].get<int>());
  // And the tool matters: the second half compensated as if the 6 mm ball
  // cut it moves differently, so the two-tool program did use the 4 mm one.
  const Toolpath wrong = compensated(m, "second", {"--tool", m.tool});
  bool differs = false;
  for (std::size_t p = 0; p < wrong.passes.size() && !differs; ++p)
    for (std::size_t k = 0; k < wrong.passes[p].points.size() && !differs; ++k)
      differs = wrong.passes[p].points[k].position != alone2.passes[p].points[k].position;
  CHECK(differs);
}

TEST_CASE("compensate --tools: a program that changes tools without a table, or with --rework, fails with status 2") {
  const std::string dir = test::scratch_dir("cli-compensate-tools-refused");
  // Inputs are checked before the comparison is used: any file will do for it.
  const std::string program = dir + "/two.nc";
  test::write_text(program, "%\nG21 G90\nT1 M6\nG0 X0 Y0 Z40\nG0 Z25\nG1 X10 Y0 Z25 F500\nG0 Z40\n"
                            "T2 M6\nG0 X0 Y5 Z40\nG0 Z25\nG1 X10 Y5 Z25\nG0 Z40\nM30\n%\n");
  const test::MouldBump m = test::measured_mould_bump("cli-compensate-tools-refused-mould", 15, 0.05, 25, 11);
  const auto no_table = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", program,
                                    "--tool", m.tool, "--out", dir + "/out.nc"});
  CHECK(no_table.status == 2);
  CHECK(no_table.err.find("changes tools") != std::string::npos);
  CHECK(!fs::exists(dir + "/out.nc"));
  test::write_text(dir + "/table.json", "{\"T1\": \"" + m.tool + "\", \"T2\": \"" + m.tool + "\"}\n");
  const auto rework = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", program,
                                  "--tools", dir + "/table.json", "--out", dir + "/out.nc", "--rework"});
  CHECK(rework.status == 2);
  CHECK(rework.err.find("--rework") != std::string::npos);
  CHECK(!fs::exists(dir + "/out.nc"));
}
