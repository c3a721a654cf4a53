// Files written the way other programs write them are read like Furrow's
// own (docs/formats.md "Limits"): Excel's CSV (byte-order mark, CRLF, ';'
// between fields), G-code as a CAM post-processor writes it. The expected
// values are the ones written in the text.
#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "base/error.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/machining/contact_point_file.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "io/machining/toolpath_file.hpp"

using namespace furrow;

namespace {

const std::string kBom = "\xEF\xBB\xBF";

std::string crlf(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("measurements: Excel's CSV UTF-8 with semicolons and CRLF reads like the plain CSV") {
  MeasurementReadOptions o;
  o.format = MeasurementFormat::csv;
  o.probe_diameter = 2;
  const std::string excel = kBom + crlf("id;x;y;z\nP1;12.5;40.25;-3\nP2;+1e-3;0;7\n");
  const MeasurementSet m = parse_measurements(excel, "m.csv", MeasurementFormat::csv, o);
  REQUIRE(m.points.size() == 2);
  CHECK(m.points[0].id == "P1");
  CHECK(m.points[0].xyz == Eigen::Vector3d(12.5, 40.25, -3));
  CHECK(m.points[1].id == "P2");
  CHECK(m.points[1].xyz == Eigen::Vector3d(0.001, 0, 7));
  CHECK(m.ids_from_file);
  // Without the mark the header's first column was "\ufeffid".
  const std::string comma = kBom + crlf("id,x,y,z\nP1,12.5,40.25,-3\n");
  CHECK(parse_measurements(comma, "m.csv", MeasurementFormat::csv, o).points[0].id == "P1");
  // With ';' a decimal comma is read as such; a dialect that says the
  // numbers use a point refuses it, naming the file, line and column.
  const std::string semicolon = kBom + "id;x;y;z\nP1;1,5;2;3\n";
  CHECK(parse_measurements(semicolon, "m.csv", MeasurementFormat::csv, o).points[0].xyz.x() == 1.5);
  o.dialect.decimal_comma = false;
  const std::string e = error_of([&] { parse_measurements(semicolon, "m.csv", MeasurementFormat::csv, o); });
  CHECK(e.rfind("m.csv:2: column 2 (x): \"1,5\"", 0) == 0);
}

TEST_CASE("measurements: XYZ and DMIS results with a byte-order mark and CRLF") {
  MeasurementReadOptions o;
  o.probe_diameter = 2;
  const MeasurementSet xyz =
      parse_measurements(kBom + crlf("# cmm\n1 2 3\n4 5 6\n"), "m.xyz", MeasurementFormat::xyz, o);
  REQUIRE(xyz.points.size() == 2);
  CHECK(xyz.points[1].xyz == Eigen::Vector3d(4, 5, 6));
  const MeasurementSet dmis = parse_measurements(
      kBom + crlf("UNITS/MM,ANGDEG\nFA(P7)=FEAT/POINT,CART,1,2,3,0,0,1\n"), "m.dmo", MeasurementFormat::dmis, o);
  REQUIRE(dmis.points.size() == 1);
  CHECK(dmis.points[0].id == "P7");
  CHECK(dmis.points[0].xyz == Eigen::Vector3d(1, 2, 3));
}

TEST_CASE("measurements: coordinates are checked after the inch conversion") {
  MeasurementReadOptions o;
  o.probe_diameter = 2;
  o.units = "inch";
  const std::string e =
      error_of([&] { parse_measurements("id,x,y,z\nP1,1e307,0,0\n", "m.csv", MeasurementFormat::csv, o); });
  CHECK(e == "m.csv:2: x: not a finite number");
  const std::string far =
      error_of([&] { parse_measurements("id,x,y,z\nP1,50000,0,0\n", "m.csv", MeasurementFormat::csv, o); });
  CHECK(far.rfind("m.csv:2: x: 1.27e+06 mm is outside the coordinate range", 0) == 0);
}

TEST_CASE("contact points: Excel's CSV with semicolons, CRLF and a byte-order mark") {
  const auto points = parse_contact_points_csv(kBom + crlf("id;x;y;z\nA;1.5;2;3\nB;4;5;6\n"), "cc.csv", "mm");
  REQUIRE(points.size() == 2);
  CHECK(points[0].id == "A");
  CHECK(points[0].position == Eigen::Vector3d(1.5, 2, 3));
  CHECK(points[1].position == Eigen::Vector3d(4, 5, 6));
  CHECK(points[1].line == 3);
}

TEST_CASE("tool-path CSV: Excel's CSV with semicolons, CRLF and a byte-order mark") {
  const Toolpath p = parse_toolpath_csv(kBom + crlf("x;y;z\n0;0;1\n10;0;1.5\n"), "p.csv", {});
  REQUIRE(p.passes.size() == 1);
  REQUIRE(p.passes[0].points.size() == 2);
  CHECK(p.passes[0].points[1].position == Eigen::Vector3d(10, 0, 1.5));
  // A header column Excel's mark used to hide: refused with the name quoted.
  const std::string e = error_of([&] { parse_toolpath_csv("x,y,z,speed\n0,0,1,5\n1,0,1,5\n", "p.csv", {}); });
  CHECK(e.rfind("p.csv:1: unknown column \"speed\"", 0) == 0);
}

TEST_CASE("G-code as a CAM post-processor writes it: program number, N words, tool change, spindle, coolant") {
  const std::string cam = kBom + crlf(
      "%\n"
      "O0001 (MOULD FINISH)\n"
      "(T1  D=6. CR=3. - BALL END MILL)\n"
      "N10 G90 G94 G17 G49 G40 G80\n"
      "N15 G21\n"
      "N20 T1 M06\n"
      "N25 S12000 M03\n"
      "N30 G54\n"
      "N35 M08\n"
      "N40 G00 X-0.5 Y0.\n"
      "N45 Z30.\n"
      "N50 G01 Z20. F500.\n"
      "N55 X99.5 Y0. Z24. F1000.\n"
      "N60 G00 Z30.\n"
      "N65 M09\n"
      "N70 M05\n"
      "N75 M30\n"
      "%\n");
  const Toolpath p = parse_gcode(cam, "cam.nc", {});
  REQUIRE(p.passes.size() == 1);
  REQUIRE(p.passes[0].points.size() == 3);
  CHECK(p.passes[0].points[0].position == Eigen::Vector3d(-0.5, 0, 30));
  CHECK(p.passes[0].points[1].position == Eigen::Vector3d(-0.5, 0, 20));
  CHECK(p.passes[0].points[2].position == Eigen::Vector3d(99.5, 0, 24));
  CHECK(p.passes[0].points[2].feed == 1000);
  CHECK(p.passes[0].points[1].line == 12);
}

TEST_CASE("G-code: a coordinate beyond the range after G20 or G91 names the line") {
  const std::string inch = error_of([&] { parse_gcode("G20 G90\nG0 X0 Y0 Z1\nG1 X50000 F10\n", "p.nc", {}); });
  CHECK(inch.rfind("p.nc:3: X: 1.27e+06 mm is outside the coordinate range", 0) == 0);
  const std::string rel = error_of(
      [&] { parse_gcode("G21 G90\nG0 X0 Y0 Z1\nG91\nG1 X600000 F100\nG1 X600000\n", "p.nc", {}); });
  CHECK(rel.rfind("p.nc:5: X: 1.2e+06 mm is outside the coordinate range", 0) == 0);
  const std::string huge = error_of([&] { parse_gcode("G1 X" + std::string(5000, '9') + "\n", "p.nc", {}); });
  CHECK(huge.size() < 140);
  CHECK(huge.find("...'") != std::string::npos);
}

TEST_CASE("JSON inputs with a byte-order mark and CRLF (as Windows editors save them)") {
  const Part part = parse_part_json(
      kBom + crlf("{\"units\": \"mm\", \"faces\": [{\"name\": \"p\", \"degree_u\": 1, \"degree_v\": 1,\n"
                  "\"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1],\n"
                  "\"control_points\": [[[0, 0, 0], [0, 10, 0]], [[10, 0, 0], [10, 10, 1]]]}]}\n"),
      "part.json");
  REQUIRE(part.faces.size() == 1);
  CHECK(part.faces[0].surface().control_point(1, 1) == Eigen::Vector3d(10, 10, 1));
  const ToolSpec tool =
      parse_tool_json(kBom + crlf("{\"name\": \"B\",\n\"type\": \"ball\", \"diameter\": 6}\n"), "tool.json");
  CHECK(tool.corner_radius == 3);
}
