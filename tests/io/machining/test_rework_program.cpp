// The rework program writer (io/machining/rework_program.hpp) on tiny
// programs whose expected output is written out here by hand: header and
// end kept byte for byte (CRLF too), rapids at the clearance, a plunge at
// the stretch's feed, F written again only when it changes. Read back,
// the stretches' tips are where they were written.
#include <doctest/doctest.h>

#include "io/machining/apt_reader.hpp"
#include "io/machining/gcode_reader.hpp"
#include "io/machining/rework_program.hpp"

using namespace furrow;

namespace {

std::vector<ReworkStretch> two_stretches() {
  ReworkStretch a, b;
  a.tips = {{1, 0, -0.05}, {2, 0, -0.06}, {3, 0, -0.05}};
  a.feeds = {800, 800, 500};
  b.tips = {{1, 5, -0.04}, {4, 5, -0.04}};
  b.feeds = {500, 500};
  return {a, b};
}

}  // namespace

TEST_CASE("rework program: G-code header and end kept, rapids at the clearance, plunges at the stretch's feed") {
  const std::string original = "%\r\n(mould)\r\nG21 G90\r\nM3 S8000\r\nG0 Z20\r\nG0 X0 Y0\r\nG0 Z0\r\n"
                               "G1 X10 F800\r\nG0 Z20\r\nM5\r\nM30\r\n%\r\n";
  const Toolpath path = parse_gcode(original, "o.nc");
  const std::string text = write_rework_program(original, path, two_stretches(), 20, 3, ReworkFormat::gcode);
  CHECK(text ==
        "%\r\n(mould)\r\nG21 G90\r\nM3 S8000\r\n"
        "G0 Z20.000\r\nG0 X1.000 Y0.000 Z20.000\r\n"
        "G1 X1.000 Y0.000 Z-0.050 F800\r\nG1 X2.000 Y0.000 Z-0.060\r\nG1 X3.000 Y0.000 Z-0.050 F500\r\n"
        "G0 X3.000 Y0.000 Z20.000\r\n"
        "G0 X1.000 Y5.000 Z20.000\r\nG1 X1.000 Y5.000 Z-0.040\r\nG1 X4.000 Y5.000 Z-0.040\r\n"
        "G0 X4.000 Y5.000 Z20.000\r\n"
        "M5\r\nM30\r\n%\r\n");
  const Toolpath back = parse_gcode(text, "r.nc");
  REQUIRE(back.passes.size() == 2);
  CHECK(back.passes[0].points.size() == 4);
  CHECK((back.passes[0].points[2].position - Eigen::Vector3d(2, 0, -0.06)).norm() < 1e-12);
  CHECK(back.passes[0].points[3].feed == 500);
}

TEST_CASE("rework program: APT keeps its header without the first motion's RAPID, and writes RAPID GOTO and FEDRAT") {
  const std::string original = "PARTNO X\nUNITS/MM\nCUTTER/6,3\nFEDRAT/MMPM,800\nRAPID\nGOTO/0,0,20\nRAPID\n"
                               "GOTO/0,0,0\nGOTO/10,0,0\nRAPID\nGOTO/10,0,20\nFINI\n";
  const Toolpath path = parse_apt(original, "o.apt");
  const std::string text = write_rework_program(original, path, two_stretches(), 20, 3, ReworkFormat::apt);
  CHECK(text ==
        "PARTNO X\nUNITS/MM\nCUTTER/6,3\nFEDRAT/MMPM,800\n"
        "RAPID\nGOTO/1.000,0.000,20.000\n"
        "FEDRAT/MMPM,800.0000\nGOTO/1.000,0.000,-0.050\nGOTO/2.000,0.000,-0.060\n"
        "FEDRAT/MMPM,500.0000\nGOTO/3.000,0.000,-0.050\n"
        "RAPID\nGOTO/3.000,0.000,20.000\n"
        "RAPID\nGOTO/1.000,5.000,20.000\nGOTO/1.000,5.000,-0.040\nGOTO/4.000,5.000,-0.040\n"
        "RAPID\nGOTO/4.000,5.000,20.000\n"
        "FINI\n");
  const Toolpath back = parse_apt(text, "r.apt");
  REQUIRE(back.passes.size() == 2);
  CHECK((back.passes[1].points.back().position - Eigen::Vector3d(4, 5, -0.04)).norm() < 1e-12);
  CHECK(back.passes[0].points[3].feed == 500);
}
