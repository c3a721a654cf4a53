#include <doctest/doctest.h>

#include "base/error.hpp"
#include "io/machining/toolpath_file.hpp"

using namespace furrow;

namespace {

std::string error_of(const std::string& text, bool csv = false) {
  try {
    if (csv) {
      parse_toolpath_csv(text, "path.csv");
    } else {
      parse_gcode(text, "path.nc");
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("G-code: absolute and relative moves, rapids separate passes, comments and line numbers") {
  const std::string text =
      "%\n"
      "O1000 (finish)\n"
      "N10 G21 G90 G17 ; metric, absolute\n"
      "N20 T1 M6\n"
      "N30 S12000 M3\n"
      "N40 G0 X0 Y0 Z5\n"
      "N50 G1 Z1 F800 (plunge)\n"
      "N60 X10\n"
      "N70 G91 X5 Y-2\n"
      "N80 G0 Z10\n"
      "N90 G90 X20 Y20\n"
      "N100 G1 Z0\n"
      "N110 Y30 Z-1\n"
      "N120 M30\n"
      "%\n";
  const Toolpath p = parse_gcode(text, "t.nc");
  REQUIRE(p.passes.size() == 2);
  const auto& a = p.passes[0].points;
  REQUIRE(a.size() == 4);
  CHECK(a[0].position == Eigen::Vector3d(0, 0, 5));
  CHECK(a[1].position == Eigen::Vector3d(0, 0, 1));
  CHECK(a[2].position == Eigen::Vector3d(10, 0, 1));
  CHECK(a[3].position == Eigen::Vector3d(15, -2, 1));
  CHECK(a[3].line == 9);
  CHECK(a[2].feed == 800);
  const auto& b = p.passes[1].points;
  REQUIRE(b.size() == 3);
  CHECK(b[0].position == Eigen::Vector3d(20, 20, 11));  // "G0 Z10" was still relative (G91)
  CHECK(b[2].position == Eigen::Vector3d(20, 30, -1));
  CHECK(p.move_count() == 5);
  // Ignored words are reported with their lines, nothing silently dropped.
  std::vector<std::string> ignored;
  for (const auto& w : p.ignored) ignored.push_back(std::to_string(w.line) + ":" + w.word);
  CHECK(ignored == std::vector<std::string>{"5:S12000", "5:M3", "14:M30"});
  CHECK(p.passes[0].tool == 1);
  CHECK(p.passes[1].tool == 1);
}

TEST_CASE("G-code: inch units convert to mm, also mid-file, and apply to the line they are on") {
  const Toolpath p = parse_gcode("G20 G90 G0 X0 Y0 Z1\nG1 X1 Y2 Z0.5\nG21 X30\n", "t.nc");
  const auto& pts = p.passes[0].points;
  REQUIRE(pts.size() == 3);
  CHECK(pts[0].position.z() == doctest::Approx(25.4));
  CHECK(pts[1].position.isApprox(Eigen::Vector3d(25.4, 50.8, 12.7)));
  CHECK(pts[2].position.isApprox(Eigen::Vector3d(30, 50.8, 12.7)));
  ToolpathReadOptions inch;
  inch.units = "inch";
  const Toolpath q = parse_gcode("G0 X0 Y0 Z0\nG1 X1\n", "t.nc", inch);
  CHECK(q.passes[0].points[1].position.x() == doctest::Approx(25.4));
}

TEST_CASE("G-code errors name the line") {
  CHECK(error_of("") == "path.nc: no cutting moves (G1, G2, G3) in the file");
  CHECK(error_of("(only a comment)\n") == "path.nc: no cutting moves (G1, G2, G3) in the file");
  CHECK(error_of("G0 X0 Y0 Z0\nG2 X1 Y1 I1 J1\n").find("path.nc:2: G2: arc radius is zero") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 A30\n").find("path.nc:2: word A30 is not supported") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 Y\n").find("path.nc:2: word 'Y' has no valid number") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 (open\n").find("path.nc:2: comment '(' is not closed") == 0);
  CHECK(error_of("X1 Y2 Z3\n").find("path.nc:1: coordinates before any motion mode") == 0);
  CHECK(error_of("G91 G0 X1\n").find("path.nc:1: relative move in X before the position is known") == 0);
  CHECK(error_of("G0 X0 Y0\nG1 X1\n").find("path.nc:2: cutting move before X, Y and Z are all known") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 X2\n").find("path.nc:2: X is given twice") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 F-5\n").find("path.nc:2: feed F-5 must be positive") == 0);
  CHECK(error_of("G0 X0 Y0 Z0\nG1 X1 Y#\n").find("path.nc:2:") == 0);
}

TEST_CASE("CSV: tips or contact points, header in any order, passes by blank line or column") {
  const Toolpath tips = parse_toolpath_csv("0,0,1\n1,0,1\n\n0,1,1\n1,1,1\n2,1,1\n", "p.csv");
  CHECK(tips.kind == ToolpathKind::tool_tips);
  REQUIRE(tips.passes.size() == 2);
  CHECK(tips.passes[1].points.size() == 3);
  const Toolpath cc = parse_toolpath_csv(
      "# contact points\nnz,z,ny,y,nx,x,pass\n1,0,0,0,0,0,1\n2,0,0,0,0,1,1\n1,0,0,1,0,0,2\n1,0,0,1,0,1,2\n", "c.csv");
  CHECK(cc.kind == ToolpathKind::contact_points);
  REQUIRE(cc.passes.size() == 2);
  CHECK(cc.passes[0].points[1].position == Eigen::Vector3d(1, 0, 0));
  CHECK(cc.passes[0].points[1].normal == Eigen::Vector3d(0, 0, 1));  // normalised
  CHECK(error_of("0,0,1\n1,0\n", true).find("path.csv:2: expected 3 columns, found 2") == 0);
  CHECK(error_of("0,0,1\n1,0,x\n", true).find("path.csv:2: z \"x\" is not a finite number") == 0);
  CHECK(error_of("x,y\n", true).find("path.csv:1: the header has no \"z\" column") == 0);
  CHECK(error_of("x,y,z,nx\n", true).find("give all of nx, ny, nz") != std::string::npos);
  CHECK(error_of("0,0,1,0,0,0\n1,0,1,0,0,1\n", true).find("path.csv:1: the normal") == 0);
  CHECK(error_of("0,0,1\n\n1,0,1\n2,0,1\n", true).find("path.csv:2: a pass needs at least 2 points") == 0);
  CHECK(error_of("", true) == "path.csv: no tool-path points in the file");
}

TEST_CASE("CSV: contact points may carry their face and (u, v), unknown columns are refused") {
  const Toolpath cc = parse_toolpath_csv(
      "pass,x,y,z,nx,ny,nz,face,u,v\n0,1,2,3,0,0,1,mould,0.25,0.5\n0,2,2,3,0,0,1,mould,0.5,0.5\n", "c.csv");
  REQUIRE(cc.passes.size() == 1);
  const ToolpathPoint& p = cc.passes[0].points[1];
  CHECK(p.has_uv);
  CHECK(p.uv == Eigen::Vector2d(0.5, 0.5));
  CHECK(p.face == "mould");
  const Toolpath plain = parse_toolpath_csv("x,y,z,u,v\n0,0,0,0,0\n1,0,0,1,0\n", "p.csv");
  CHECK(plain.passes[0].points[0].has_uv);
  CHECK(plain.passes[0].points[0].face.empty());
  CHECK(error_of("x,y,z,u\n", true).find("path.csv:1: give both u and v columns or neither") == 0);
  CHECK(error_of("x,y,z,face\n", true).find("path.csv:1: a face column needs u and v columns") == 0);
  CHECK(error_of("x,y,z,speed\n", true).find("path.csv:1: unknown column \"speed\"") == 0);
  CHECK(error_of("face,x,y,z,u,v\n ,0,0,0,0,0\n", true).find("path.csv:2: the face name is empty") == 0);
}

TEST_CASE("written G-code reads back to the same passes") {
  Toolpath p;
  for (int k = 0; k < 3; ++k) {
    ToolpathPass pass;
    for (int j = 0; j < 5; ++j) {
      ToolpathPoint t;
      t.position = Eigen::Vector3d(j * 1.25, k * 0.5, -0.0001 * j * k);
      pass.points.push_back(t);
    }
    p.passes.push_back(pass);
  }
  const std::string g = toolpath_to_gcode(p, 50.0, 1200, "furrow test (ball 6)\nsecond line");
  const Toolpath back = parse_gcode(g, "back.nc");
  REQUIRE(back.passes.size() == 3);
  for (int k = 0; k < 3; ++k) {
    REQUIRE(back.passes[k].points.size() == 5);
    for (int j = 0; j < 5; ++j)
      CHECK((back.passes[k].points[j].position - p.passes[k].points[j].position).norm() < 1e-4);
  }
  CHECK(back.passes[0].points[1].feed == 1200);
}

TEST_CASE("fuzz: pass numbers beyond 1e15 are refused, large ones are ordered as read, not converted") {
  // fuzz_toolpath_csv under UBSan: a pass of 1e300 (finite and whole) was
  // converted to long, which is undefined behaviour.
  CHECK(error_of("x,y,z,pass\n0,0,0,1e300\n1,0,0,1e300\n", true) ==
        "path.csv:2: pass \"1e300\" is not a whole number up to 1e15");
  const Toolpath path =
      parse_toolpath_csv("x,y,z,pass\n0,0,0,1e14\n1,0,0,1e14\n2,0,0,2e14\n3,0,0,2e14\n", "path.csv");
  REQUIRE(path.passes.size() == 2);
  CHECK(path.passes[1].points[0].line == 4);
  CHECK(error_of("x,y,z,pass\n0,0,0,1e14\n1,0,0,1e14\n2,0,0,-1e14\n3,0,0,-1e14\n", true) ==
        "path.csv:4: pass numbers must not decrease");
}
