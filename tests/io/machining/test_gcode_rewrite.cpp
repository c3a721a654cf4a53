// G-code written again with moved tool tips (io/machining/gcode_rewrite.hpp).
// Oracles: the original bytes (nothing moved), programs written by hand for
// the expected words, and the moved tips re-read from the output by the
// reader (its own tests check it against hand-computed positions) compared
// with the tips the test asked for.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/machining/gcode_reader.hpp"
#include "io/machining/gcode_rewrite.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

using Tips = std::vector<std::vector<Eigen::Vector3d>>;

Tips tips_of(const Toolpath& path) {
  Tips tips;
  for (const ToolpathPass& pass : path.passes) {
    tips.emplace_back();
    for (const ToolpathPoint& p : pass.points) tips.back().push_back(p.position);
  }
  return tips;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Work offsets, inch, an arc, a modal arc, comments, CRLF, a tool change,
// G28, incremental moves: what the rewrite must leave alone.
const std::string kMixed =
    "\xEF\xBB\xBF%\r\n"
    "O2002 (MIXED)\r\n"
    "N10 G20 G90 G17 ; inch\r\n"
    "N20 G10 L2 P1 X0 Y0 Z0\r\n"
    "N30 G10 L2 P2 X1.0 Y-0.5 Z0.25 (G55 origin)\r\n"
    "N40 T1 M6\r\n"
    "N50 S9000 M3\r\n"
    "N60 G54 G0 X0.5 Y0.5 Z1.0\r\n"
    "N70 G1 Z0.1 F20.\r\n"
    "N80 G1X1.2345Y0.5\r\n"
    "N90 G2 X1.7345 Y1.0 I0. J0.5\r\n"
    "N100 X1.2345 Y1.5 I-0.5 J0.\r\n"
    "N110 G1 X0.5 F30.\r\n"
    "N120 G0 Z1.0\r\n"
    "N130 G55 X0.1 Y0.2\r\n"
    "N140 G1 Z-0.1 F15.\r\n"
    "N150 G91 X0.25 Y0.125\r\n"
    "N160 X0.25\r\n"
    "N170 G90 G0 Z0.75\r\n"
    "N180 G28 G91 Z0.\r\n"
    "N190 M30\r\n"
    "%";

std::size_t arc_lines(const std::string& text) {
  std::size_t n = 0;
  for (std::size_t at = 0; (at = text.find("G2 ", at)) != std::string::npos; ++at) ++n;
  return n;
}

// Largest per-axis distance between the output's points and the tips asked
// for, pass by pass and point by point (same structure required).
double largest_miss(const Toolpath& got, const Tips& wanted) {
  REQUIRE(got.passes.size() == wanted.size());
  double worst = 0;
  for (std::size_t p = 0; p < wanted.size(); ++p) {
    REQUIRE(got.passes[p].points.size() == wanted[p].size());
    for (std::size_t i = 0; i < wanted[p].size(); ++i)
      worst = std::max(worst, (got.passes[p].points[i].position - wanted[p][i]).cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace

TEST_CASE("G-code rewrite: tips not moved give the program back byte for byte") {
  SUBCASE("the example mould program") {
    const std::string text = read_file(std::string(FURROW_SOURCE_DIR) + "/examples/toolpaths/mould_ball6.nc");
    const Toolpath path = parse_gcode(text, "mould.nc");
    const GcodeRewrite out = rewrite_gcode(text, "mould.nc", {}, tips_of(path));
    CHECK(out.text == text);
    CHECK(out.lines_moved == 0);
    CHECK(out.decimals == 4);
  }
  SUBCASE("work offsets, inch, arcs, comments, CRLF, incremental moves") {
    const Toolpath path = parse_gcode(kMixed, "mixed.nc");
    CHECK(rewrite_gcode(kMixed, "mixed.nc", {}, tips_of(path)).text == kMixed);
    // Moves far below the written precision (0.0001 inch = 2.54 µm) leave
    // every word as it was.
    Tips tips = tips_of(path);
    for (auto& pass : tips)
      for (auto& t : pass) t += Eigen::Vector3d(1e-4, -1e-4, 1e-4);
    CHECK(rewrite_gcode(kMixed, "mixed.nc", {}, tips).text == kMixed);
  }
}

TEST_CASE("G-code rewrite: a moved line gets its words rewritten and omitted ones added, the next line still ends where it did") {
  const std::string program =
      "G21 G90\n"
      "G0 X0. Y0. Z5.\n"
      "G1 Z-1. F100 (down)\n"
      "G1 X10.\n"
      "G1 X20.\n"
      "G0 Z5.\n";
  const Toolpath path = parse_gcode(program, "p.nc");
  Tips tips = tips_of(path);
  REQUIRE(tips.size() == 1);
  REQUIRE(tips[0].size() == 4);  // start, Z-1, X10, X20
  tips[0][2] += Eigen::Vector3d(0.02, 0, -0.05);
  const GcodeRewrite out = rewrite_gcode(program, "p.nc", {}, tips);
  // Hand-written: X rewritten with 4 decimals (the file has none), Z added
  // after X; the next line relied on the modal Z and gets Z-1 back.
  CHECK(out.text ==
        "G21 G90\n"
        "G0 X0. Y0. Z5.\n"
        "G1 Z-1. F100 (down)\n"
        "G1 X10.0200 Z-1.0500\n"
        "G1 X20. Z-1.0000\n"
        "G0 Z5.\n");
  CHECK(out.lines_moved == 2);
  CHECK(out.words_rewritten == 1);
  CHECK(out.words_added == 2);
}

TEST_CASE("G-code rewrite: words are written in the line's units and work system") {
  // G55's origin is 1 inch right of G54's (the part frame): X1.2 in G55 is
  // 2.2 in = 55.88 mm in the part frame. Moving that tip by +0.254 mm
  // (0.01 in) must give X1.2100 in G55 inches.
  const std::string program =
      "G20 G90\n"
      "G10 L2 P1 X0 Y0 Z0\n"
      "G10 L2 P2 X1. Y0 Z0\n"
      "G54 G0 X0. Y0. Z1.\n"
      "G1 Z0. F10.\n"
      "G55 G1 X1.2 Y0.3\n"
      "G0 Z1.\n";
  const Toolpath path = parse_gcode(program, "wo.nc");
  Tips tips = tips_of(path);
  REQUIRE(tips[0].size() == 3);
  CHECK(std::abs(tips[0][2].x() - 55.88) < 1e-12);
  tips[0][2].x() += 0.254;
  const GcodeRewrite out = rewrite_gcode(program, "wo.nc", {}, tips);
  CHECK(out.text ==
        "G20 G90\n"
        "G10 L2 P1 X0 Y0 Z0\n"
        "G10 L2 P2 X1. Y0 Z0\n"
        "G54 G0 X0. Y0. Z1.\n"
        "G1 Z0. F10.\n"
        "G55 G1 X1.2100 Y0.3\n"
        "G0 X1.2000 Z1.\n");  // the retract ends where it did
}

TEST_CASE("G-code rewrite: a known offset on the example program moves exactly those tips, structure kept") {
  const std::string text = read_file(std::string(FURROW_SOURCE_DIR) + "/examples/toolpaths/mould_ball6.nc");
  const Toolpath path = parse_gcode(text, "mould.nc");
  Tips tips = tips_of(path);
  // Every cut point of the passes with y in [20, 40] mm moves by a vector
  // that changes from point to point (not a multiple of 0.0001 mm).
  std::size_t moved = 0;
  for (std::size_t p = 0; p < tips.size(); ++p)
    for (std::size_t i = 1; i < tips[p].size(); ++i) {
      const Eigen::Vector3d t = tips[p][i];
      if (t.y() < 20 || t.y() > 40) continue;
      tips[p][i] += Eigen::Vector3d(0.013 * std::sin(t.x()), -0.007, -0.0421 * std::cos(0.1 * t.x()));
      ++moved;
    }
  REQUIRE(moved > 100);
  const GcodeRewrite out = rewrite_gcode(text, "mould.nc", {}, tips);
  const Toolpath again = parse_gcode(out.text, "again.nc");
  // Written with 4 decimals in mm: each axis within half a unit, 0.05 µm
  // (plus the double rounding of the conversion).
  CHECK(largest_miss(again, tips) <= 0.5e-4 + 1e-12);
  CHECK(again.rapids.size() == path.rapids.size());
  CHECK(again.tool_changes.size() == path.tool_changes.size());
  CHECK(again.move_count() == path.move_count());
  for (std::size_t p = 0; p < path.passes.size(); ++p)
    for (std::size_t i = 0; i < path.passes[p].points.size(); ++i) {
      CHECK(again.passes[p].points[i].feed == path.passes[p].points[i].feed);
      CHECK(again.passes[p].points[i].line == path.passes[p].points[i].line);
    }
  // Lines of passes entirely outside the band are the original bytes.
  std::istringstream a(text), b(out.text);
  std::string la, lb;
  std::size_t same = 0, differ = 0;
  while (std::getline(a, la) && std::getline(b, lb)) (la == lb ? same : differ)++;
  CHECK(differ > 0);
  CHECK(differ <= moved + 2 * tips.size());  // a moved line and the rapid out of its pass at most
  CHECK(same > 0);
}

TEST_CASE("G-code rewrite: a moved arc becomes G1 segments through the moved points") {
  const Toolpath path = parse_gcode(kMixed, "mixed.nc");
  REQUIRE(path.passes.size() == 2);
  Tips tips = tips_of(path);
  // Every cut point of the first pass (the inch pocket, N70-N110) 0.05 mm down.
  for (std::size_t i = 1; i < tips[0].size(); ++i) tips[0][i] += Eigen::Vector3d(0, 0, -0.05);
  const GcodeRewrite out = rewrite_gcode(kMixed, "mixed.nc", {}, tips);
  std::size_t arc_points = 0;  // the flattened points of N90 and N100 (lines 11, 12)
  for (const ToolpathPoint& p : path.passes[0].points) arc_points += p.line == 11 || p.line == 12;
  CHECK(out.arcs_split == 2);
  CHECK(out.lines_inserted == arc_points - 2);
  CHECK(arc_lines(out.text) == 0);
  CHECK(out.text.find("N90 G1 X") != std::string::npos);
  CHECK(out.text.find("N100 G1 X") != std::string::npos);
  CHECK(out.text.find(" I") == std::string::npos);  // no centre word left
  const Toolpath again = parse_gcode(out.text, "again.nc");
  // Written in inch with 4 decimals: within half a unit, 1.27 µm, per axis.
  CHECK(largest_miss(again, tips) <= 0.5e-4 * 25.4 + 1e-12);
  // The second pass (G55, incremental) did not move: its lines are the
  // original bytes.
  CHECK(out.text.find("N140 G1 Z-0.1 F15.\r\nN150 G91 X0.25 Y0.125\r\nN160 X0.25\r\n") != std::string::npos);
}

TEST_CASE("G-code rewrite: a line after a split arc that relied on the modal G2 gets G2 written") {
  const Toolpath path = parse_gcode(kMixed, "mixed.nc");
  Tips tips = tips_of(path);
  // Only the inner points of N90 (line 11) move: its end, and so N100's
  // start, stay.
  std::size_t inner = 0;
  const auto& points = path.passes[0].points;
  for (std::size_t i = 1; i + 1 < points.size(); ++i)
    if (points[i].line == 11 && points[i + 1].line == 11) {
      tips[0][i] += Eigen::Vector3d(0.03, 0, 0);
      ++inner;
    }
  REQUIRE(inner > 2);
  const GcodeRewrite out = rewrite_gcode(kMixed, "mixed.nc", {}, tips);
  CHECK(out.arcs_split == 1);
  CHECK(out.text.find("N100 G2 X1.2345 Y1.5 I-0.5 J0.\r\n") != std::string::npos);
  const Toolpath again = parse_gcode(out.text, "again.nc");
  CHECK(largest_miss(again, tips) <= 0.5e-4 * 25.4 + 1e-12);
}

TEST_CASE("G-code rewrite: incremental lines after a moved one are written from where the tool now is") {
  const std::string program =
      "G21 G90 G0 X0. Y0. Z5.\n"
      "G1 Z-1. F200.\n"
      "G91 X10.\n"
      "X10.\n"
      "Y5.\n"
      "G90 G0 Z5.\n";
  const Toolpath path = parse_gcode(program, "inc.nc");
  Tips tips = tips_of(path);
  REQUIRE(tips[0].size() == 5);
  tips[0][2] += Eigen::Vector3d(0.5, 0.1, 0);  // the end of "G91 X10."
  const GcodeRewrite out = rewrite_gcode(program, "inc.nc", {}, tips);
  CHECK(out.text ==
        "G21 G90 G0 X0. Y0. Z5.\n"
        "G1 Z-1. F200.\n"
        "G91 X10.5000 Y0.1000\n"
        "X9.5000 Y-0.1000\n"
        "Y5.\n"
        "G90 G0 Z5.\n");
  CHECK(largest_miss(parse_gcode(out.text, "again.nc"), tips) <= 1e-12);
}

TEST_CASE("G-code rewrite: a moved pass start moves the rapid that ends there") {
  const std::string program =
      "G21 G90\n"
      "G0 X0. Y0. Z5.\n"
      "G0 Z-1.\n"
      "G1 X10. F100.\n"
      "G0 Z5.\n";
  const Toolpath path = parse_gcode(program, "s.nc");
  Tips tips = tips_of(path);
  tips[0][0].z() = -1.25;
  const GcodeRewrite out = rewrite_gcode(program, "s.nc", {}, tips);
  CHECK(out.text ==
        "G21 G90\n"
        "G0 X0. Y0. Z5.\n"
        "G0 Z-1.2500\n"
        "G1 X10. Z-1.0000 F100.\n"
        "G0 Z5.\n");
}

TEST_CASE("G-code rewrite: tips of another program are refused naming the file") {
  const std::string program = "G21 G90 G0 X0 Y0 Z5\nG1 Z0 F100\nG1 X10\n";
  Tips tips = tips_of(parse_gcode(program, "a.nc"));
  tips[0].pop_back();
  const std::string e = test::input_error_of([&] { rewrite_gcode(program, "a.nc", {}, tips); });
  CHECK(e.find("a.nc: pass 1 has 2 moved tips for 3 points") != std::string::npos);
  tips.push_back({});
  CHECK(test::input_error_of([&] { rewrite_gcode(program, "a.nc", {}, tips); }).find("2 passes") != std::string::npos);
}

TEST_CASE("G-code rewrite: a word to add in a work system whose offset the file does not give is refused naming the line") {
  // G55 set relative to where the tool is (G10 L20): its X shift from the
  // part frame is known, so X words read; the program moves in G55 with X
  // only, and a moved Y would need G55's Y offset, which only X was given.
  const std::string program =
      "G21 G90 G0 X0. Y0. Z5.\n"
      "G1 Z-1. F100.\n"
      "G10 L20 P2 X0.\n"
      "G55 G1 X10.\n"
      "G54 G0 Z5.\n";
  const Toolpath path = parse_gcode(program, "w.nc");
  Tips tips = tips_of(path);
  REQUIRE(tips[0].size() == 3);
  tips[0][2].y() += 0.1;
  const std::string e = test::input_error_of([&] { rewrite_gcode(program, "w.nc", {}, tips); });
  CHECK(e.find("w.nc:4: Y must be written to move the line, but its work offset is not in the file") !=
        std::string::npos);
}

TEST_CASE("G-code rewrite: an axis word added in front of a rewritten one keeps both words whole") {
  // A plunge "G1 Z0." whose tip moves across and down gains a Y in front of
  // its rewritten Z (the insertion and the replacement start at the same
  // byte); the next line relies on the modal Y and Z and needs nothing; the
  // retract goes back to the original Y. Expected output written by hand.
  const std::string program = "G21 G90\nG0 X20. Y10. Z5.\nG1 Z0. F500\nG1 X22.\nG0 Z5.\n";
  const Toolpath path = parse_gcode(program, "plunge.nc");
  Tips tips = tips_of(path);
  REQUIRE(tips.size() == 1);
  REQUIRE(tips[0].size() == 3);
  tips[0][1] += Eigen::Vector3d(0, 0.09, -0.05);
  tips[0][2] += Eigen::Vector3d(0, 0.09, -0.05);
  const GcodeRewrite out = rewrite_gcode(program, "plunge.nc", {}, tips);
  CHECK(out.text == "G21 G90\nG0 X20. Y10. Z5.\nG1 Y10.0900 Z-0.0500 F500\nG1 X22.\nG0 Y10.0000 Z5.\n");
  CHECK(largest_miss(parse_gcode(out.text, "back.nc"), tips) < 1e-12);
}
