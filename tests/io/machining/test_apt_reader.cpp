// APT CL data as UG/NX and CATIA write it (written by hand here in the layout
// of their CLS/APT output), read against the equivalent G-code through the
// G-code reader (a second, independent reader of the same path), and the
// constructs the APT reader refuses, each naming its line.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/machining/gcode_reader.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

std::string error_of(const std::string& text, const ToolpathReadOptions& options = {}) {
  return test::input_error_of([&] { parse_apt(text, "cam.cl", options); });
}

// Same passes, point by point, to 1e-9 mm.
void check_same_passes(const Toolpath& a, const Toolpath& b, bool same_feed) {
  REQUIRE(a.passes.size() == b.passes.size());
  for (std::size_t p = 0; p < a.passes.size(); ++p) {
    CAPTURE(p);
    REQUIRE(a.passes[p].points.size() == b.passes[p].points.size());
    for (std::size_t k = 0; k < a.passes[p].points.size(); ++k) {
      CAPTURE(k);
      CHECK((a.passes[p].points[k].position - b.passes[p].points[k].position).norm() < 1e-9);
      if (same_feed) CHECK(a.passes[p].points[k].feed == b.passes[p].points[k].feed);
    }
  }
}

// NX CLSF layout: header, TLDATA, MSYS, CUTTER with 7 parameters, RAPID
// before each positioning GOTO, CIRCLE/ (with NX's trailing tolerance and
// tool values) before the GOTO that ends each arc, 6-value GOTOs, a
// continuation line and comments.
const char* kNx =
    "$$ -> CLSF_STYLE,ADVANCED\n"                                                                    // 1
    "TOOL PATH/CONTOUR_RING,TOOL,BALL_MILL\n"                                                        // 2
    "TLDATA/MILL,6.0000,3.0000,50.0000,0.0000,0.0000\n"                                              // 3
    "MSYS/0.0000,0.0000,0.0000,1.0000000,0.0000000,0.0000000,0.0000000,1.0000000,0.0000000\n"        // 4
    "PARTNO RING TEST / OP 10\n"                                                                     // 5
    "MACHIN/MILL,1\n"                                                                                // 6
    "UNITS/MM\n"                                                                                     // 7
    "CUTTER/6.0000,3.0000,0.0000,3.0000,0.0000,0.0000,50.0000\n"                                     // 8
    "LOADTL/1,ADJUST,1\n"                                                                            // 9
    "SPINDL/RPM,8000,CLW\n"                                                                          // 10
    "COOLNT/ON\n"                                                                                    // 11
    "PAINT/PATH\n"                                                                                   // 12
    "$$ centerline data\n"                                                                           // 13
    "RAPID\n"                                                                                        // 14
    "GOTO/10.0000,0.0000,30.0000\n"                                                                  // 15
    "RAPID\n"                                                                                        // 16
    "GOTO/10.0000,0.0000,5.0000\n"                                                                   // 17
    "FEDRAT/MMPM,800.0000\n"                                                                         // 18
    "GOTO/10.0000,0.0000,-1.0000,0.0000000,0.0000000,1.0000000\n"                                    // 19
    "CIRCLE/0.0000,0.0000,-1.0000,0.0000000,0.0000000,1.0000000,10.0000,0.0600,0.5000,6.0000,0.0000\n"  // 20
    "GOTO/0.0000,10.0000,-1.0000\n"                                                                  // 21
    "GOTO/-5.0000,10.0000,$\n"                                                                       // 22
    "  -1.0000  $$ continued\n"                                                                      // 23
    "CIRCLE/-5.0000,5.0000,-1.0000,0.0000000,0.0000000,-1.0000000,5.0000,0.0600,0.5000,6.0000,0.0000\n"  // 24
    "GOTO/0.0000,5.0000,-1.5000\n"                                                                   // 25
    "CIRCLE/-5.0000,5.0000,-1.5000,0.0000000,0.0000000,1.0000000,5.0000,0.0600,0.5000,6.0000,0.0000\n"   // 26
    "GOTO/0.0000,5.0000,-1.5000\n"                                                                   // 27
    "PPRINT/ $ not a continuation, RAPID\n"                                                          // 28
    "RAPID\n"                                                                                        // 29
    "GOTO/0.0000,5.0000,30.0000\n"                                                                   // 30
    "RAPID\n"                                                                                        // 31
    "GOTO/20.0000,0.0000,30.0000\n"                                                                  // 32
    "RAPID\n"                                                                                        // 33
    "GOTO/20.0000,0.0000,0.0000\n"                                                                   // 34
    "FEDRAT/250.0000\n"                                                                              // 35
    "GOTO/20.0000,0.0000,-1.0000\n"                                                                  // 36
    "CIRCLE/25.0000,0.0000,-1.0000,0.0000000,1.0000000,0.0000000,5.0000,0.0600,0.5000,6.0000,0.0000\n"   // 37
    "GOTO/30.0000,0.0000,-1.0000\n"                                                                  // 38
    "GOTO/40.0000,0.0000,-1.0000\n"                                                                  // 39
    "END-OF-PATH\n"                                                                                  // 40
    "RAPID\n"                                                                                        // 41
    "GOTO/40.0000,0.0000,30.0000\n"                                                                  // 42
    "FINI\n";                                                                                        // 43

// The same path as a Fanuc post would write it.
const char* kNxGcode =
    "%\nG21 G90 G17\n"
    "G0 X10 Y0 Z30\nG0 X10 Y0 Z5\n"
    "G1 X10 Y0 Z-1 F800\n"
    "G3 X0 Y10 Z-1 I-10 J0\n"
    "G1 X-5 Y10 Z-1\n"
    "G2 X0 Y5 Z-1.5 I0 J-5\n"
    "G3 X0 Y5 Z-1.5 I-5 J0\n"
    "G0 X0 Y5 Z30\nG0 X20 Y0 Z30\nG0 X20 Y0 Z0\n"
    "G1 X20 Y0 Z-1 F250\n"
    "G18 G3 X30 Y0 Z-1 I5 K0\n"
    "G17 G1 X40 Y0 Z-1\n"
    "G0 X40 Y0 Z30\nM30\n%\n";

}  // namespace

TEST_CASE("APT from NX: the same passes as the equivalent G-code, the cutter, the ignored words") {
  const Toolpath apt = parse_apt(kNx, "ring.cls");
  const Toolpath gcode = parse_gcode(kNxGcode, "ring.nc");
  check_same_passes(apt, gcode, true);
  REQUIRE(apt.passes.size() == 2);
  // RAPID GOTOs are the G0 moves, ready for the rapid check; the first starts
  // from an unknown position in both files.
  REQUIRE(apt.rapids.size() == gcode.rapids.size());
  REQUIRE(apt.rapids.size() == 6);
  const int rapid_lines[] = {15, 17, 30, 32, 34, 42};
  for (std::size_t k = 0; k < apt.rapids.size(); ++k) {
    CAPTURE(k);
    CHECK(apt.rapids[k].line == rapid_lines[k]);
    CHECK(apt.rapids[k].known == gcode.rapids[k].known);
    CHECK(apt.rapids[k].known == (k > 0));
    CHECK((apt.rapids[k].from - gcode.rapids[k].from).norm() < 1e-9);
    CHECK((apt.rapids[k].to - gcode.rapids[k].to).norm() < 1e-9);
  }
  CHECK(apt.passes[0].points.front().feed == 800);
  CHECK(apt.passes[1].points.back().feed == 250);

  // Independently of the G-code reader: the counter-clockwise quarter about
  // the origin (lines 20-21) stays in the first quadrant on radius 10; the
  // clockwise quarter about (-5, 5) (lines 24-25) runs through x > -5, y > 5,
  // descending linearly with the angle.
  const std::vector<ToolpathPoint>& pts = apt.passes[0].points;
  int quarter = 0, clockwise = 0;
  for (const ToolpathPoint& p : pts) {
    if (p.line == 21) {
      ++quarter;
      CHECK(p.position.x() >= -1e-12);
      CHECK(p.position.y() >= 0);
      CHECK(std::hypot(p.position.x(), p.position.y()) == doctest::Approx(10).epsilon(1e-12));
    }
    if (p.line == 25) {
      ++clockwise;
      const double ax = p.position.x() + 5, ay = p.position.y() - 5;
      CHECK(ax > 0);
      CHECK(ay >= -1e-12);
      CHECK(std::hypot(ax, ay) == doctest::Approx(5).epsilon(1e-12));
      const double swept = std::atan2(1, 0) - std::atan2(ay, ax);  // from 90 degrees, clockwise
      CHECK(p.position.z() == doctest::Approx(-1 - 0.5 * swept / std::atan2(1, 0)).epsilon(1e-12));
    }
  }
  CHECK(quarter > 10);
  CHECK(clockwise > 5);
  // The continued GOTO (lines 22-23) is named by its first line.
  bool continued = false;
  for (const ToolpathPoint& p : pts)
    if (p.line == 22) continued = (p.position - Eigen::Vector3d(-5, 10, -1)).norm() < 1e-12;
  CHECK(continued);

  REQUIRE(apt.tool.has_value());
  CHECK(apt.tool->type == ToolType::ball);
  CHECK(apt.tool->diameter == 6);
  CHECK(apt.tool->corner_radius == 3);
  CHECK(apt.tool_line == 3);  // TLDATA first; the CUTTER of line 8 agrees with it
  std::vector<int> ignored_lines;
  for (const IgnoredWord& w : apt.ignored) ignored_lines.push_back(w.line);
  CHECK(ignored_lines == std::vector<int>{2, 4, 5, 6, 9, 10, 11, 12, 28, 40});
}

TEST_CASE("APT from CATIA: INDIRV and TLON,GOFWD circles, spaced GOTOs and MULTAX read as G2/G3") {
  const char* catia =
      "$$*CATIA0\n"
      "$$ Manufacturing Program.1\n"
      "PARTNO PART1\n"
      "MULTAX\n"
      "LOADTL/1,1\n"
      "$$ TOOLCHANGEDEFINITION.1 : T1 End Mill D 10\n"
      "CUTTER/ 10.000000, 0.000000, 5.000000, 0.000000, 0.000000, 0.000000, 50.000000\n"
      "SPINDL/  1000.0000,RPM,CLW\n"
      "FEDRAT/  1000.0000,MMPM\n"
      "RAPID\n"
      "GOTO  /   0.00000,   0.00000,  10.00000, 0.000000, 0.000000, 1.000000\n"
      "GOTO  /   0.00000,   0.00000,   0.00000, 0.000000, 0.000000, 1.000000\n"
      "GOTO  /  10.00000,   0.00000,   0.00000, 0.000000, 0.000000, 1.000000\n"
      "INDIRV/ 1.000000, 0.000000, 0.000000\n"
      "TLON,GOFWD/ (CIRCLE/ 10.00000, 5.00000, 0.00000, $\n"
      " 5.00000), ON, (LINE/ 10.00000, 5.00000, 0.00000, $\n"
      " 10.00000, 10.00000, 0.00000)\n"
      "GOTO  /   0.00000,  10.00000,   0.00000, 0.000000, 0.000000, 1.000000\n"
      "INDIRV/ 0.000000, 1.000000, 0.000000\n"
      "TLON,GOFWD/ (CIRCLE/ 5.00000, 10.00000, 0.00000, 5.00000), ON, $\n"
      " (LINE/ 0.00000, 15.00000, 0.00000, 10.00000, 5.00000, 0.00000)\n"
      "RAPID\n"
      "GOTO  /   0.00000,  10.00000,  10.00000\n"
      "FINI\n";
  const char* gcode =
      "G21 G90 G17\nG0 X0 Y0 Z10\nG1 X0 Y0 Z0 F1000\nG1 X10 Y0\n"
      "G3 X10 Y10 I0 J5\nG1 X0 Y10\n"
      // From (0, 10) about (5, 10) starting along +y: clockwise, to the
      // first crossing of the line x + y = 15, (5 - 5/sqrt2, 10 + 5/sqrt2).
      "G2 X1.4644660940672622 Y13.535533905932738 I5 J0\n"
      "G0 Z10\nM30\n";
  const Toolpath apt = parse_apt(catia, "part.aptsource.apt");
  check_same_passes(apt, parse_gcode(gcode, "part.nc"), true);
  REQUIRE(apt.tool.has_value());
  CHECK(apt.tool->type == ToolType::flat);
  CHECK(apt.tool->diameter == 10);
  CHECK(apt.tool->corner_radius == 0);
  CHECK(apt.tool_line == 7);
}

TEST_CASE("APT in inches: UNITS/INCHES, the --units default, IPM feeds and an inch cutter") {
  const char* inch =
      "CUTTER/0.25,0.05\nRAPID\nGOTO/1,0,1\nRAPID\nGOTO/1,0,0\nFEDRAT/IPM,10\nGOTO/2,0,0\n"
      "CIRCLE/2,1,0,0,0,1,1\nGOTO/3,1,0\nUNITS/MM\nGOTO/76.2,50.8,0\nFINI\n";
  const char* metric =
      "G21 G90 G17\nG0 X25.4 Y0 Z25.4\nG0 Z0\nG1 X50.8 F254\nG3 X76.2 Y25.4 I0 J25.4\nG1 X76.2 Y50.8\nM30\n";
  ToolpathReadOptions in_inch;
  in_inch.units = "inch";
  const Toolpath by_option = parse_apt(inch, "inch.cl", in_inch);
  const Toolpath by_statement = parse_apt(std::string("UNITS/INCHES\n") + inch, "inch.cl");
  const Toolpath reference = parse_gcode(metric, "metric.nc");
  check_same_passes(by_option, reference, true);
  check_same_passes(by_statement, reference, true);
  REQUIRE(by_statement.tool.has_value());
  CHECK(by_statement.tool->type == ToolType::bull);
  CHECK(by_statement.tool->diameter == doctest::Approx(6.35).epsilon(1e-15));
  CHECK(by_statement.tool->corner_radius == doctest::Approx(1.27).epsilon(1e-15));
}

TEST_CASE("APT: refused constructs name their line") {
  const std::string head = "CUTTER/6,3\nRAPID\nGOTO/0,0,10\nGOTO/0,0,0\n";  // lines 1-4
  struct Case {
    const char* what;
    std::string text;
    const char* expected;  // in the message after "cam.cl:"
  };
  const std::vector<Case> cases = {
      {"tilted GOTO axis", head + "GOTO/1,0,0,0,0.5,0.866\n", "cam.cl:5: GOTO/ tool axis is not the vertical"},
      {"tilted with MULTAX", head + "MULTAX/ON\nGOTO/1,0,0,0.1,0,1\n", "cam.cl:6: GOTO/ tool axis"},
      {"downward axis", head + "GOTO/1,0,0,0,0,-1\n", "cam.cl:5: GOTO/ tool axis"},
      {"tilted TLAXIS", head + "TLAXIS/0,1,1\n", "cam.cl:5: TLAXIS/ tool axis"},
      {"unknown major word", head + "RETRCT\n", "cam.cl:5: major word \"RETRCT\" is not supported"},
      {"INSERT", head + "INSERT G41 D1\n", "cam.cl:5: major word \"INSERT\""},
      {"cutter compensation", head + "CUTCOM/LEFT\n", "cam.cl:5: CUTCOM (cutter compensation)"},
      {"canned cycle", head + "CYCLE/DRILL,5,10,IPM\n", "cam.cl:5: CYCLE (a canned cycle)"},
      {"tapered cutter", "CUTTER/10,1,4,1,10,0,50\n", "cam.cl:1: CUTTER/ is not a cylindrical"},
      {"cut after a tool change", head + "CUTTER/10\nGOTO/1,0,0\n", "cam.cl:6: cutting move from an unknown position"},
      {"CIRCLE without GOTO", head + "CIRCLE/0,5,0,0,0,1,5\nFINI\n", "cam.cl:5: CIRCLE/ is not followed"},
      {"CIRCLE then RAPID", head + "CIRCLE/0,5,0,0,0,1,5\nRAPID\nGOTO/0,0,10\n", "cam.cl:5: CIRCLE/ is followed by a RAPID"},
      {"tilted CIRCLE", head + "CIRCLE/0,5,0,0,1,1,5\nGOTO/0,10,0\n", "cam.cl:5: CIRCLE/ axis is not along"},
      {"wrong CIRCLE radius", head + "CIRCLE/0,5,0,0,0,1,4\nGOTO/0,10,0\n", "cam.cl:6: the arc starts 5 mm"},
      {"arc end off the circle", head + "CIRCLE/0,5,0,0,0,1,5\nGOTO/0,12,0\n", "cam.cl:6: CIRCLE/ at line 5:"},
      {"after FINI", head + "FINI\nGOTO/1,1,0\n", "cam.cl:6: GOTO after FINI"},
      {"GOTO with 2 values", head + "GOTO/1,2\n", "cam.cl:5: GOTO/ takes x,y,z"},
      {"cut from nowhere", "CUTTER/6\nGOTO/0,0,0\nGOTO/1,0,0\n", "cam.cl:2: cutting move from an unknown position"},
      {"moved frame", "MSYS/10,0,0,1,0,0,0,1,0\n" + head, "cam.cl:1: MSYS/"},
      {"continued at the end", head + "GOTO/1,2,$\n", "cam.cl:5: the statement ends in '$'"},
      {"GOFWD without INDIRV", head + "TLON,GOFWD/(CIRCLE/0,5,0,5),ON,(LINE/0,5,0,0,10,0)\n",
       "cam.cl:5: TLON,GOFWD/ without INDIRV/"},
      {"GOFWD PAST", head + "INDIRV/1,0,0\nTLON,GOFWD/(CIRCLE/0,5,0,5),PAST,(LINE/0,5,0,0,10,0)\n",
       "cam.cl:6: TLON,GOFWD/ is read as"},
      {"unknown units", "UNITS/FEET\n" + head, "cam.cl:1: UNITS/\"FEET\""},
      {"no cut", "CUTTER/6\nRAPID\nGOTO/0,0,10\nFINI\n", "cam.cl: no cutting moves"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    const std::string message = error_of(c.text);
    CAPTURE(message);
    CHECK(message.find(c.expected) != std::string::npos);
  }
}

TEST_CASE("APT: hostile numbers and missing values are refused naming the line") {
  const std::string head = "CUTTER/6,3\nRAPID\nGOTO/0,0,10\n";  // lines 1-3
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "GOTO/1e308,0,0\n", "cam.cl:4: x"},
      {head + "GOTO/2000000,0,0\n", "cam.cl:4: x"},
      {head + "GOTO/nan,0,0\n", "cam.cl:4: GOTO/: value 1 \"NAN\" is not a finite number"},
      {head + "GOTO/1,inf,0\n", "cam.cl:4: GOTO/: value 2"},
      {head + "GOTO/1,,0\n", "cam.cl:4: GOTO/: value 2 is missing"},
      {head + "GOTO/1,0,\n", "cam.cl:4: GOTO/: value 3 is missing"},
      {head + "GOTO/1e999,0,0\n", "cam.cl:4: GOTO/: value 1"},
      {"UNITS/INCHES\n" + head + "GOTO/1e307,0,0\n", "cam.cl:5: x"},
      {head + "GODLTA/900000,0,0\nGODLTA/900000,0,0\n", "cam.cl:5: x"},
      {head + "FEDRAT/nan\n", "cam.cl:4: FEDRAT/: feed"},
      {head + "FEDRAT/0\n", "cam.cl:4: FEDRAT/: the feed must be positive"},
      {"CUTTER/1e308\n", "cam.cl:1: CUTTER.diameter"},
      {"CUTTER/-6\n", "cam.cl:1: CUTTER.diameter"},
      {"CUTTER/6,4\n", "cam.cl:1: CUTTER.corner_radius"},
      {head + "CIRCLE/0,5,10,0,0,1,1e-300\nGOTO/0,10,10\n", "cam.cl:"},
      {head + "CIRCLE/0,5,10,0,0,1,1e308\nGOTO/0,10,10\n", "cam.cl:4: r"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.first);
    const std::string message = error_of(c.first);
    CAPTURE(message);
    CHECK(message.find(c.second) != std::string::npos);
  }
}

TEST_CASE("APT: the tool for a path is the given one or the file's, and a contradiction is refused") {
  const Toolpath path = parse_apt("CUTTER/6,3\nRAPID\nGOTO/0,0,10\nGOTO/0,0,0\n", "p.cl");
  ToolSpec ball{"B6", ToolType::ball, 6, 3};
  ToolSpec flat{"F6", ToolType::flat, 6, 0};
  CHECK(tool_for_path(std::nullopt, "", path).diameter == 6);
  CHECK(tool_for_path(ball, "b6.json", path).name == "B6");
  std::string message;
  try {
    tool_for_path(flat, "f6.json", path);
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK(message.find("f6.json") != std::string::npos);
  CHECK(message.find("p.cl:1") != std::string::npos);
  const Toolpath no_tool = parse_gcode("G21 G90\nG0 X0 Y0 Z1\nG1 X1 F100\n", "p.nc");
  CHECK_THROWS_AS(tool_for_path(std::nullopt, "", no_tool), InputError);
  CHECK(tool_for_path(flat, "f6.json", no_tool).name == "F6");
}
