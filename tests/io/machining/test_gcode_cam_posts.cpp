// G-code as Fanuc-style CAM posts write it (written by hand here the way the
// Fusion 360 and Mastercam Fanuc posts lay out their programs), and the
// words this reader refuses, each naming its line.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "io/machining/gcode_reader.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

std::string error_of(const std::string& text) {
  return test::input_error_of([&] { parse_gcode(text, "cam.nc"); });
}

}  // namespace

TEST_CASE("G-code from a Fusion 360 style Fanuc post: O number, N numbers, G28, tool change, G43 H, arcs") {
  const std::string program =
      "%\n"                                          // 1
      "O1001 (POCKET RING)\n"                        // 2
      "(T1 D=6. CR=3. - ZMIN=-1. - BALL END MILL)\n"  // 3
      "N10 G90 G94 G17 G49 G40 G80\n"                // 4
      "N15 G21\n"                                    // 5
      "N20 G28 G91 Z0.\n"                            // 6
      "N25 G90\n"                                    // 7
      "\n"                                           // 8
      "(CONTOUR1)\n"                                 // 9
      "N30 T1 M6\n"                                  // 10
      "N35 S8000 M3\n"                               // 11
      "N40 G54\n"                                    // 12
      "N45 M8\n"                                     // 13
      "N50 G0 X20. Y0.\n"                            // 14
      "N55 G43 Z15. H1\n"                            // 15
      "N60 Z5.\n"                                    // 16
      "N65 G1 Z-1. F300.\n"                          // 17
      "N70 G3 X-20. I-20. J0. F1200.\n"              // 18
      "N75 X20. Y0. I20. J0.\n"                      // 19
      "N80 G1 X25.\n"                                // 20
      "N85 G0 Z15.\n"                                // 21
      "N90 M9\n"                                     // 22
      "N95 G28 G91 Z0.\n"                            // 23
      "N100 G90\n"                                   // 24
      "N105 G28 G91 X0. Y0.\n"                       // 25
      "N110 G90\n"                                   // 26
      "N115 M30\n"                                   // 27
      "%\n";                                         // 28
  const Toolpath p = parse_gcode(program, "fusion.nc");
  REQUIRE(p.passes.size() == 1);
  const auto& pts = p.passes[0].points;
  CHECK(pts.front().position == Eigen::Vector3d(20, 0, 5));
  CHECK(pts[1].position == Eigen::Vector3d(20, 0, -1));
  CHECK(pts[1].line == 17);
  CHECK(pts[1].feed == 300);
  CHECK(pts.back().position == Eigen::Vector3d(25, 0, -1));
  CHECK(pts.back().line == 20);
  // Between them a full circle of radius 20 about the origin, counter-clockwise
  // through (-20, 0) (line 18) and back (line 19), at feed 1200.
  double swept = 0;
  for (std::size_t k = 2; k + 1 < pts.size(); ++k) {
    CHECK(std::abs(pts[k].position.head<2>().norm() - 20) < 1e-9);
    CHECK(pts[k].position.z() == -1);
    CHECK(pts[k].feed == 1200);
    CHECK((pts[k].line == 18 || pts[k].line == 19));
    const Eigen::Vector2d a = pts[k - 1].position.head<2>(), b = pts[k].position.head<2>();
    swept += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  CHECK(swept == doctest::Approx(2 * 3.14159265358979323846).epsilon(1e-12));
  std::vector<std::string> ignored;
  for (const auto& w : p.ignored) ignored.push_back(std::to_string(w.line) + ":" + w.word);
  CHECK(ignored == std::vector<std::string>{"4:G94", "4:G49", "4:G40", "4:G80", "11:S8000", "11:M3", "13:M8",
                                            "15:G43", "15:H1", "22:M9", "27:M30"});
  // T1 M6 is a tool change: the pass is cut with tool 1.
  REQUIRE(p.tool_changes.size() == 1);
  CHECK(p.tool_changes[0].line == 10);
  CHECK(p.tool_changes[0].tool == 1);
  CHECK(p.passes[0].tool == 1);
}

TEST_CASE("G-code from a Mastercam style Fanuc post: modal words without spaces, R arcs, inch") {
  const std::string program =
      "%\n"                                                        // 1
      "O0100(RING)\n"                                              // 2
      "(DATE=DD-MM-YY - 25-11-26 TIME=HH:MM - 20:00)\n"            // 3
      "( T2 |  1/4 BALL ENDMILL | H2 )\n"                          // 4
      "N100G20\n"                                                  // 5
      "N102G0G17G40G49G80G90\n"                                    // 6
      "N104T2M6\n"                                                 // 7
      "N106G0G90G54X1.Y0.S5000M3\n"                                // 8
      "N108G43H2Z1.\n"                                             // 9
      "N110G1Z-.05F20.\n"                                          // 10
      "N112G2X0.Y-1.R1.\n"                                         // 11
      "N114G3X-1.Y0.R-1. ; the long way round\n"                   // 12
      "N116G1X-1.5\n"                                              // 13
      "N118G0Z1.\n"                                                // 14
      "N120M5\n"                                                   // 15
      "N122G91G28Z0.\n"                                            // 16
      "N124M30\n"                                                  // 17
      "%\n";                                                       // 18
  const Toolpath p = parse_gcode(program, "mastercam.nc");
  REQUIRE(p.passes.size() == 1);
  const auto& pts = p.passes[0].points;
  CHECK(pts.front().position == Eigen::Vector3d(25.4, 0, 25.4));
  CHECK(pts[1].position == Eigen::Vector3d(25.4, 0, -0.05 * 25.4));
  CHECK(pts.back().position == Eigen::Vector3d(-1.5 * 25.4, 0, -0.05 * 25.4));
  // Line 11: a clockwise quarter about the origin (R > 0: the short arc).
  // Line 12: chord (0,-r) -> (-r,0); G3 with R > 0 would turn 90 degrees about
  // (-r,-r), left of the chord; R < 0 puts the centre right of it, at the
  // origin, and the arc turns 270 degrees through (r,0) and (0,r).
  const double r = 25.4;
  int on_first = 0, on_second = 0;
  for (const auto& t : pts) {
    if (t.line == 11) {
      ++on_first;
      CHECK(std::abs(t.position.head<2>().norm() - r) < 1e-9);
      CHECK(t.position.x() >= -1e-12);
      CHECK(t.position.y() <= 1e-12);
    }
    if (t.line == 12) {
      ++on_second;
      CHECK(std::abs(t.position.head<2>().norm() - r) < 1e-9);
    }
  }
  CHECK(on_first > 10);
  CHECK(on_second > 2 * on_first);  // 270 degrees against 90
  bool passes_top = false;
  for (const auto& t : pts)
    if (t.line == 12 && (t.position.head<2>() - Eigen::Vector2d(0, r)).norm() < 0.1) passes_top = true;
  CHECK(passes_top);
}

TEST_CASE("G-code: numbers as posts write them, and G28 and G53 make the axes unknown") {
  const Toolpath p = parse_gcode("G90G21G0X.5Y-.5Z1.\nG1X1.Y2.Z+0.25\n", "p.nc");
  REQUIRE(p.passes.size() == 1);
  CHECK(p.passes[0].points[0].position == Eigen::Vector3d(0.5, -0.5, 1));
  CHECK(p.passes[0].points[1].position == Eigen::Vector3d(1, 2, 0.25));
  CHECK(error_of("G90 G0 X0 Y0 Z0\nG28 G91 Z0.\nG90 G1 X1\n").find("cam.nc:3: cutting move before X, Y and Z") == 0);
  CHECK(error_of("G90 G0 X0 Y0 Z0\nG28\nG90 G0 Z5\nG1 X1\n").find("cam.nc:4: cutting move before X, Y and Z") == 0);
  CHECK(error_of("G90 G0 X0 Y0 Z0\nG53 G0 Z0.\nG0 Z5\nG1 X1\n").empty());
  CHECK(error_of("G90 G0 X0 Y0 Z0\nG53 G1 Z0.\n").find("cam.nc:2: G53 with a cutting move") == 0);
  // G53 rapids whatever the motion mode: after it the pass is over and Z unknown.
  CHECK(error_of("G90 G0 X0 Y0 Z0\nG1 X1\nG53 Z0.\nX2\n").find("cam.nc:4: cutting move before X, Y and Z") == 0);
}

TEST_CASE("G-code: constructs the control would expand or offset are refused, naming the line") {
  const std::string start = "G90 G0 X0 Y0 Z5\n";
  CHECK(error_of(start + "G41 D1 G1 X10\n").find("cam.nc:2: G41 (cutter compensation) is not supported") == 0);
  CHECK(error_of(start + "G1 Z0\nG42 X1\n").find("cam.nc:3: G42 (cutter compensation)") == 0);
  for (const char* cycle : {"G81", "G82", "G83", "G84", "G85", "G86", "G87", "G88", "G89", "G73", "G76"})
    CHECK(error_of(start + std::string(cycle) + " X1 Y1 Z-2 R1 F100\n")
              .find("cam.nc:2: " + std::string(cycle) + " (canned cycle) is not supported") == 0);
  // The offset between G54 and G55 is not in this file
  // (test_gcode_work_offsets.cpp has the files that give it).
  CHECK(error_of("G54\n" + start + "G55 G1 X1\n").find("cam.nc:3: X in G55: its offset from the part frame") == 0);
  CHECK(error_of("G54\n" + start + "G54 G1 X1\n").empty());
  CHECK(error_of(start + "G1 X1 A90.\n").find("cam.nc:2: word A90. is not supported") == 0);
  CHECK(error_of(start + "G1 X1\nG4 P1.\n").find("cam.nc:3: G4 is not supported") == 0);
}

TEST_CASE("G-code: tool changes as posts write them give each pass and rapid the tool in the spindle") {
  // A roughing and a finishing tool, the way Fanuc posts write the change:
  // T3 M6 on one line, a preselected T7 loaded by a later bare M06, and
  // M6 before its T word ("M6T2", word order is free).
  const std::string program =
      "%\n"                               // 1
      "O2000\n"                           // 2
      "N10 G90 G21 G17\n"                 // 3
      "N20 T3 M6\n"                       // 4
      "N30 G0 G54 X0. Y0. S9000 M3\n"     // 5
      "N40 G43 Z5. H3\n"                  // 6
      "N50 G1 Z-1. F500.\n"               // 7
      "N60 X20.\n"                        // 8
      "N70 G0 Z50. T7\n"                  // 9  (T7 preselected while cutting ends)
      "N80 G28 G91 Z0.\n"                 // 10
      "N90 G90 M06\n"                     // 11
      "N100 G0 X0. Y5.\n"                 // 12
      "N110 Z5.\n"                        // 13
      "N120 G1 Z-1.2\n"                   // 14
      "N130 X20.\n"                       // 15
      "N140 G0 Z50.\n"                    // 16
      "N150 M6T2\n"                       // 17
      "N160 G0 X0. Y10. Z5.\n"            // 18
      "N170 G1 Z-1.1\n"                   // 19
      "N180 X20.\n"                       // 20
      "N190 M30\n"                        // 21
      "%\n";
  const Toolpath p = parse_gcode(program, "tools.nc");
  REQUIRE(p.passes.size() == 3);
  CHECK(p.passes[0].tool == 3);
  CHECK(p.passes[1].tool == 7);
  CHECK(p.passes[2].tool == 2);
  REQUIRE(p.tool_changes.size() == 3);
  CHECK(p.tool_changes[0].line == 4);
  CHECK(p.tool_changes[1].line == 11);
  CHECK(p.tool_changes[1].tool == 7);
  CHECK(p.tool_changes[2].line == 17);
  CHECK(p.tool_changes[2].tool == 2);
  // Rapids carry the tool loaded when they run; a change is an unchecked
  // move to the change position (machine coordinates), like G28.
  std::vector<std::string> rapids;
  for (const RapidMove& r : p.rapids)
    rapids.push_back(std::to_string(r.line) + (r.known ? "" : "?") + ":T" + std::to_string(r.tool));
  CHECK(rapids == std::vector<std::string>{"4?:T0", "5?:T3", "6?:T3", "9:T3", "10?:T3", "11?:T3", "12?:T7",
                                           "13?:T7", "16:T7", "17?:T7", "18?:T2"});
  for (const IgnoredWord& w : p.ignored) {
    CHECK(w.word != "M6");
    CHECK(w.word != "M06");
    CHECK(w.word.front() != 'T');
  }
}

TEST_CASE("G-code: tool changes the reader cannot follow are refused, naming the line") {
  const std::string start = "G90 G0 X0 Y0 Z5\n";
  CHECK(error_of(start + "M6\n").find("cam.nc:2: M6 (tool change) without a tool number") == 0);
  CHECK(error_of("T1.5 M6\n").find("cam.nc:1: tool number T1.5 must be a whole number") == 0);
  CHECK(error_of("T-1 M6\n").find("cam.nc:1: tool number T-1 must be a whole number") == 0);
  CHECK(error_of("T1 M6 G0 X0 Y0 Z5\n").find("cam.nc:1: M6 (tool change) with a move on its line") == 0);
  // After a change the tool is at the change position: a cut needs a position first.
  CHECK(error_of("T1 M6\n" + start + "G1 X1\nT2 M6\nG1 X2\n").find("cam.nc:5: cutting move before X, Y and Z") == 0);
  // T0 M6 empties the spindle.
  CHECK(error_of("T1 M6\n" + start + "T0 M6\n" + start + "G1 X3\n")
            .find("cam.nc:5: cutting move with an empty spindle (T0 M6 at line 3)") == 0);
}
