// Work offsets in G-code (io/machining/gcode_work_offsets.hpp): G10 L2 / G10 L20 and
// G54-G59.3, checked against the same moves written in the part frame with
// the offsets added by this test, read by the same reader.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/machining/gcode_reader.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

std::string error_of(const std::string& text) {
  return test::input_error_of([&] { parse_gcode(text, "cam.nc"); });
}

constexpr double kNone = NAN;

// One line of a program: words as written, then coordinates in the work
// system `shift` belongs to (NaN: axis not given).
struct Line {
  std::string words;
  double x = kNone, y = kNone, z = kNone;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // the system's origin in the part frame
};

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The line as the program writes it (`shifted` false) or with the offset
// added to its coordinates by hand, in the part frame (`shifted` true).
std::string render(const Line& l, bool shifted) {
  std::string out = l.words;
  const double v[3] = {l.x, l.y, l.z};
  for (int a = 0; a < 3; ++a)
    if (!std::isnan(v[a])) out += std::string(" ") + char('X' + a) + number(shifted ? v[a] + l.shift[a] : v[a]);
  return out + "\n";
}

void check_same_tips(const Toolpath& a, const Toolpath& b) {
  REQUIRE(a.passes.size() == b.passes.size());
  for (std::size_t p = 0; p < a.passes.size(); ++p) {
    REQUIRE(a.passes[p].points.size() == b.passes[p].points.size());
    for (std::size_t k = 0; k < a.passes[p].points.size(); ++k) {
      CAPTURE(p);
      CAPTURE(k);
      // Bit for bit: the same sums of numbers exact in binary.
      CHECK(a.passes[p].points[k].position == b.passes[p].points[k].position);
    }
  }
  REQUIRE(a.rapids.size() == b.rapids.size());
  for (std::size_t k = 0; k < a.rapids.size(); ++k) {
    CHECK(a.rapids[k].known == b.rapids[k].known);
    CHECK(a.rapids[k].from == b.rapids[k].from);
    CHECK(a.rapids[k].to == b.rapids[k].to);
  }
}

}  // namespace

TEST_CASE("G-code work offsets: G10 L2, G10 L20 and G54-G59.3 give the moves the offsets put in the part frame") {
  // Origins in machine coordinates (G10 L2); G54 is the part frame.
  const Eigen::Vector3d g54(10, 20, -5), g55(110.5, 20.25, -5), g591(-40, 7.5, 3);
  const Eigen::Vector3d in55 = g55 - g54, in591 = g591 - g54;
  // G10 L2 P0 while G55 is active: only its Y moves, to 30.25.
  const Eigen::Vector3d in55b(in55.x(), 30.25 - g54.y(), in55.z());
  // G10 L20 P3 X0 Y0 Z2 with the tool at (10, 5, 0) in the part frame:
  // G56's origin is where that position reads (0, 0, 2).
  const Eigen::Vector3d in56(10 - 0, 5 - 0, 0 - 2);
  const std::vector<Line> program = {
      {"G21 G90 G17"},
      {"G10 L2 P1", g54.x(), g54.y(), g54.z()},
      {"G10 L2 P2", g55.x(), g55.y(), g55.z()},
      {"G10 L2 P7", g591.x(), g591.y(), g591.z()},
      {"G54 G0", 0, 0, 5},
      {"G1 F500", kNone, kNone, 0},
      {"G1", 10, 5, kNone},
      {"G10 L20 P3", 0, 0, 2},
      {"G55"},
      {"G0", kNone, kNone, 5, in55},  // X and Y stay where the tool is
      {"G0", 0, 0, kNone, in55},
      {"G1", kNone, kNone, 0.5, in55},
      {"G1", 12.75, 3, kNone, in55},
      {"G91 G1", 1, kNone, kNone},  // incremental: no offset
      {"G90"},
      {"G10 L2 P0", kNone, 30.25, kNone},
      {"G1", kNone, 4, kNone, in55b},
      {"G0", kNone, kNone, 6, in55b},
      {"G59.1 G0", 1, 2, kNone, in591},
      {"G1", kNone, kNone, -1, in591},
      {"G2", 3, 2, kNone, in591},  // centre words I1 J0 added below
      {"G56 G0", kNone, kNone, 4, in56},
      {"G0", 1, 1, kNone, in56},
      {"G1", kNone, kNone, 2.5, in56},
      {"G1", 4, 1.5, kNone, in56},
      {"G54 G1", 20, 6, 0.5},
      {"M30"}};
  std::string with_offsets, by_hand;
  for (const Line& l : program) {
    const bool sets = l.words.find("G10") != std::string::npos;
    const std::string arc = l.words == "G2" ? " I1 J0" : "";
    std::string a = render(l, false), b = render(l, true);
    if (!arc.empty()) a.insert(a.size() - 1, arc), b.insert(b.size() - 1, arc);
    with_offsets += a;
    if (!sets) {
      // The by-hand program names no system and sets no offset.
      std::string words = b;
      for (const char* code : {"G54 ", "G55", "G56 ", "G59.1 "})
        if (words.compare(0, std::string(code).size(), code) == 0) words.erase(0, std::string(code).size());
      by_hand += words;
    }
  }
  CAPTURE(with_offsets);
  CAPTURE(by_hand);
  const Toolpath a = parse_gcode(with_offsets, "offsets.nc");
  const Toolpath b = parse_gcode(by_hand, "by_hand.nc");
  check_same_tips(a, b);
  // And the figures themselves, for one point of each system.
  REQUIRE(a.passes.size() == 4);
  CHECK(a.passes[0].points.back().position == Eigen::Vector3d(10, 5, 0));
  CHECK(a.passes[1].points[2].position == Eigen::Vector3d(12.75 + 100.5, 3 + 0.25, 0.5));
  CHECK(a.passes[1].points.back().position == Eigen::Vector3d(13.75 + 100.5, 4 + 10.25, 0.5));
  CHECK(a.passes[3].points.back().position == Eigen::Vector3d(20, 6, 0.5));
  CHECK(a.passes[3].points.front().position == Eigen::Vector3d(11, 6, 2));
  CHECK(a.passes[3].points[2].position == Eigen::Vector3d(14, 6.5, 0.5));
}

TEST_CASE("G-code work offsets: inch values, and only the axes given need a known offset") {
  const Toolpath p = parse_gcode(
      "G20 G10 L2 P1 X0 Y0 Z0\nG10 L2 P2 X1. Z.5\nG54 G0 X0 Y0 Z0\nG55 G1 X1 F10\nG1 Z0\n", "inch.nc");
  REQUIRE(p.passes.size() == 1);
  CHECK(p.passes[0].points[1].position == Eigen::Vector3d(2 * 25.4, 0, 0));
  CHECK(p.passes[0].points[2].position == Eigen::Vector3d(2 * 25.4, 0, 25.4 * 0.5));
  // G55's Y offset was never given: a Y in G55 is refused, an X is not.
  CHECK(error_of("G10 L2 P1 X0 Y0 Z0\nG10 L2 P2 X5\nG0 X0 Y0 Z0\nG55 G1 X1 F10\nY2\n")
            .find("cam.nc:5: Y in G55: its offset from the part frame (G54") == 0);
}

TEST_CASE("G-code work offsets: switches and G10 forms the file does not explain are refused, naming the line") {
  const std::string start = "G54 G0 X0 Y0 Z5\n";
  CHECK(error_of(start + "G55 G1 X1\n").find("cam.nc:2: X in G55: its offset from the part frame (G54, in effect at "
                                            "the first move) is not in the file") == 0);
  CHECK(error_of(start + "G59.3 G0 Z1\n").find("cam.nc:2: Z in G59.3") == 0);
  // Moving the part frame's own origin by an amount the file does not know.
  CHECK(error_of(start + "G10 L2 P1 X3\nG1 X1\n").find("cam.nc:3: X in G54") == 0);
  CHECK(error_of(start + "G10 L2 P1 X3\nG1 Y1\n").empty());
  // G10 L20 needs the position it is taken from.
  CHECK(error_of("G10 L20 P2 X0 Y0 Z0\n" + start + "G55 G1 X1\n").find("cam.nc:3: X in G55") == 0);
  CHECK(error_of(start + "G1 Z0\nG10 L1 P1 Z-50\n").find("cam.nc:3: G10 L1 (tool table) is not supported") == 0);
  CHECK(error_of(start + "G10 L10 P1 Z0\n").find("cam.nc:2: G10 L10 (tool table) is not supported") == 0);
  CHECK(error_of(start + "G10 L11 P1 Z0\n").find("cam.nc:2: G10 L11 (tool table) is not supported") == 0);
  CHECK(error_of(start + "G10 L3 P1 Z0\n").find("cam.nc:2: G10 L3 is not supported") == 0);
  CHECK(error_of(start + "G10 P1 Z0\n").find("cam.nc:2: G10 without L") == 0);
  CHECK(error_of(start + "G10 L2 X0\n").find("cam.nc:2: G10 L2 needs P0") == 0);
  CHECK(error_of(start + "G10 L2 P10 X0\n").find("cam.nc:2: G10 L2 needs P0") == 0);
  CHECK(error_of(start + "G10 L20 P1.5 X0\n").find("cam.nc:2: G10 L20 needs P0") == 0);
  CHECK(error_of(start + "G10 L2 P1 R45\n").find("cam.nc:2: G10 with R (a rotated work system)") == 0);
  CHECK(error_of(start + "G1 G10 L2 P1 X0\n").find("cam.nc:2: G10 with a move") == 0);
  CHECK(error_of(start + "G10 L2 P1 P2 X0\n").find("cam.nc:2: P is given twice") == 0);
  CHECK(error_of(start + "G1 X1 P2\n").find("cam.nc:2: word P is not supported outside G10") == 0);
  CHECK(error_of(start + "G92 X0\n").find("cam.nc:2: G92 (coordinate system offset) is not supported") == 0);
  CHECK(error_of(start + "G10 L2 P2 X2000000\n").find("cam.nc:2: G10 X") == 0);
  // Selecting another system and coming back without a coordinate in it is fine.
  CHECK(error_of(start + "G55\nG54 G1 X1\n").empty());
}
