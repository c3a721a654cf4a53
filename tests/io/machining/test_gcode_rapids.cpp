// Rapid moves kept by the G-code reader (io/machining/toolpath_file.hpp RapidMove):
// positions as programmed, lines, and the moves not in the part frame
// marked unknown rather than placed.
#include <doctest/doctest.h>

#include <string>

#include "io/machining/gcode_reader.hpp"

using namespace furrow;

namespace {

std::string lines_of(const Toolpath& p, bool known) {
  std::string out;
  for (const RapidMove& r : p.rapids)
    if (r.known == known) out += std::to_string(r.line) + " ";
  return out;
}

}  // namespace

TEST_CASE("G-code rapids: a Fusion-style program keeps its G0, G28 moves with their lines") {
  const std::string program =
      "%\n"                        // 1
      "N10 G90 G17 G21\n"          // 2
      "N20 G28 G91 Z0.\n"          // 3  home: unchecked
      "N25 G90 G54\n"              // 4
      "N50 G0 X20. Y0.\n"          // 5  Z not known yet: unchecked
      "N55 G43 Z15. H1\n"          // 6  starts with Z unknown: unchecked
      "N60 Z5.\n"                  // 7  (20,0,15) -> (20,0,5)
      "N65 G1 Z-1. F300.\n"        // 8
      "N70 X25.\n"                 // 9
      "N85 G0 Z15.\n"              // 10 (25,0,-1) -> (25,0,15)
      "N86 G91 X-5. Y2.\n"         // 11 relative: (25,0,15) -> (20,2,15)
      "N87 G90 Z15.\n"             // 12 no motion: not a rapid
      "N95 G28 G91 Z0.\n"          // 13 home: unchecked
      "N100 G90 M30\n"             // 14
      "%\n";                       // 15
  const Toolpath p = parse_gcode(program, "fusion.nc");
  REQUIRE(p.passes.size() == 1);
  CHECK(p.passes[0].points.size() == 3);  // the passes are as without rapids
  REQUIRE(p.rapids.size() == 7);
  CHECK(lines_of(p, false) == "3 5 6 13 ");
  CHECK(lines_of(p, true) == "7 10 11 ");
  const RapidMove& down = p.rapids[3];
  CHECK(down.line == 7);
  CHECK(down.from == Eigen::Vector3d(20, 0, 15));
  CHECK(down.to == Eigen::Vector3d(20, 0, 5));
  CHECK(p.rapids[4].from == Eigen::Vector3d(25, 0, -1));
  CHECK(p.rapids[4].to == Eigen::Vector3d(25, 0, 15));
  CHECK(p.rapids[5].to == Eigen::Vector3d(20, 2, 15));
  // Unknown moves carry no invented positions.
  for (const RapidMove& r : p.rapids)
    if (!r.known) CHECK((r.from.isZero() && r.to.isZero()));
}

TEST_CASE("G-code rapids: inch, G53, and a rapid that moves nothing") {
  const Toolpath p = parse_gcode(
      "G20 G90 G0 X1 Y0 Z1\n"  // 1 unknown start
      "G0 Z0.5\n"              // 2 (25.4,0,25.4) -> (25.4,0,12.7)
      "G0 Z0.5\n"              // 3 already there: nothing
      "G1 X2 F10\n"            // 4
      "G53 G0 Z0\n"            // 5 machine coordinates: unchecked
      "G0 X1\n",               // 6 Z unknown after G53: unchecked
      "inch.nc");
  REQUIRE(p.rapids.size() == 4);
  CHECK(lines_of(p, false) == "1 5 6 ");
  CHECK(p.rapids[1].line == 2);
  CHECK((p.rapids[1].from - Eigen::Vector3d(25.4, 0, 25.4)).norm() < 1e-12);
  CHECK((p.rapids[1].to - Eigen::Vector3d(25.4, 0, 12.7)).norm() < 1e-12);
}

TEST_CASE("G-code rapids: CSV tool paths have none, and furrow toolpath's G-code reads back with its rapids") {
  const Toolpath csv = parse_toolpath_csv("0,0,0\n1,0,0\n\n0,1,0\n1,1,0\n", "p.csv");
  CHECK(csv.passes.size() == 2);
  CHECK(csv.rapids.empty());
  const Toolpath back = parse_gcode(toolpath_to_gcode(csv, 10, 500, "test"), "back.nc");
  REQUIRE(back.passes.size() == 2);
  // Per pass up to the safe height, over the first point, down to it, and
  // a final retract. The program starts wherever the machine is: its first
  // rapid (Z only) and the next (X, Y from an unknown X, Y) are unchecked.
  REQUIRE(back.rapids.size() == 7);
  CHECK_FALSE(back.rapids[0].known);
  CHECK_FALSE(back.rapids[1].known);
  for (std::size_t k = 2; k < back.rapids.size(); ++k) CHECK(back.rapids[k].known);
  CHECK(back.rapids[2].to == Eigen::Vector3d(0, 0, 0));
  CHECK(back.rapids[3].from == Eigen::Vector3d(1, 0, 0));
  CHECK(back.rapids.back().to.z() == 10);
}
