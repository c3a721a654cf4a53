#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;

namespace {

Eigen::Vector3d vec(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

// The tangent direction of an angle in a point's reported cutter frame.
Eigen::Vector3d direction(const json& point, double angle_deg) {
  const double a = angle_deg * M_PI / 180;
  return std::cos(a) * vec(point["cutter"]["dir_max"]) + std::sin(a) * vec(point["cutter"]["dir_min"]);
}

void write_tool(const std::string& path, const std::string& name, const char* type, double d, double r) {
  write_text(path, "{\"name\":\"" + name + "\",\"type\":\"" + type + "\",\"diameter\":" + std::to_string(d) +
                       ",\"corner_radius\":" + std::to_string(r) + "}\n");
}

}  // namespace

TEST_CASE("furrow gouge on the two-face part: border points compare each face over its own side") {
  const std::string dir = scratch_dir("gouge-two-face");
  write_tool(dir + "/b60.json", "BALL-D60", "ball", 60, 30);
  const CliResult r = run_furrow({"gouge", source_path("examples/parts/two_face.json"), "--tool", dir + "/b60.json",
                                  "--grid", "21", "--out", dir + "/g.json", "--map", dir + "/g.png"});
  CHECK(r.status == 1);  // the valley (radius 16.7..25) is tighter than the ball (30)
  CHECK(r.err.empty());
  CHECK(r.out.find("gouge at") != std::string::npos);
  const json doc = json::parse(slurp(dir + "/g.json"));
  CHECK(doc["tool"]["name"] == "BALL-D60");
  CHECK(doc["sites"]["mode"] == "grid");
  REQUIRE(doc["points"].size() == 2 * 21 * 21);
  CHECK(doc["summary"]["border_points"].get<int>() == 2 * 4 * 20);
  int border_checked = 0;
  for (const json& p : doc["points"]) {
    const std::string face = p["face"];
    const bool on_edge = p.contains("border") && !p["border"]["neighbour"].is_null();
    if (face == "crown" && !on_edge) CHECK(p["status"] == "clear");  // convex
    if (!on_edge || p["grid"][1] == 0 || p["grid"][1] == 20) continue;
    // A point of the shared edge x = 50: the other face is the neighbour,
    // and the only gouging directions point into the valley (-x).
    ++border_checked;
    CHECK(p["border"]["neighbour"] == (face == "crown" ? "valley_wall" : "crown"));
    CHECK(p["border"]["crease_deg"].get<double>() < 1e-3);
    REQUIRE(p["status"] == "gouge");
    REQUIRE(p["gouge_ranges_deg"].size() == 1);
    const json& range = p["gouge_ranges_deg"][0];
    const double mid = 0.5 * (range[0].get<double>() + range[1].get<double>());
    CHECK(direction(p, mid).x() == doctest::Approx(-1).epsilon(1e-6));
    // The excess: the valley's curvature across the edge minus 1/30.
    const double y = vec(p["position"]).y();
    const double k_valley = 0.04 * (1 + 0.5 * std::pow((y - 30) / 30, 2));
    CHECK(p["max_excess"].get<double>() == doctest::Approx(k_valley - 1 / 30.0).epsilon(1e-6));
  }
  CHECK(border_checked == 2 * 19);
  const std::string png = slurp(dir + "/g.png");
  CHECK(png.substr(1, 3) == "PNG");

  // Same inputs, same bytes.
  const CliResult again = run_furrow({"gouge", source_path("examples/parts/two_face.json"), "--tool", dir + "/b60.json",
                                      "--grid", "21", "--out", dir + "/g2.json", "--map", dir + "/g2.png"});
  CHECK(again.status == 1);
  CHECK(slurp(dir + "/g2.json") == slurp(dir + "/g.json"));
  CHECK(slurp(dir + "/g2.png") == png);
}

TEST_CASE("furrow gouge on the mould with a bull-nose: every point carries the issue's fields") {
  const std::string dir = scratch_dir("gouge-mould");
  const CliResult r = run_furrow({"gouge", source_path("examples/parts/mould.json"), "--tool",
                                  source_path("examples/tools/bull_d10_r2.json"), "--grid", "40", "--out", dir + "/g.json"});
  CHECK(r.status == 1);
  const json doc = json::parse(slurp(dir + "/g.json"));
  int gouging = 0;
  for (const json& p : doc["points"]) {
    for (const char* key : {"position", "normal", "k1", "k2", "cutter", "tip", "gouge_ranges_deg", "status", "max_excess"})
      REQUIRE(p.contains(key));
    // Exact excess everywhere: a gouge exactly where it exceeds the tolerance.
    CHECK((p["status"] == "gouge") == (p["max_excess"].get<double>() > 1e-6));
    CHECK(p["cutter"]["k_max"].get<double>() == doctest::Approx(0.5));  // 1 / corner radius
    const double k_min = p["cutter"]["k_min"].get<double>();
    const double s = std::sin(p["cutter"]["contact_angle_deg"].get<double>() * M_PI / 180);
    CHECK(std::abs(k_min - s / (3 + 2 * s)) < 5e-7);  // the angle is written to 1e-4 degrees
    if (p["status"] == "gouge") {
      ++gouging;
      CHECK(p["max_excess"].get<double>() > 0);
      CHECK_FALSE(p["gouge_ranges_deg"].empty());
      // The worst direction lies in a reported range.
      const double a = p["max_excess_angle_deg"].get<double>();
      bool inside = false;
      for (const json& range : p["gouge_ranges_deg"])
        for (double turn : {0.0, 360.0})
          inside |= a + turn >= range[0].get<double>() - 1e-3 && a + turn <= range[1].get<double>() + 1e-3;
      CHECK(inside);
    } else {
      CHECK(p["gouge_ranges_deg"].empty());
    }
  }
  CHECK(gouging == doc["summary"]["gouge"].get<int>());
  CHECK(gouging > 0);
}

TEST_CASE("furrow gouge --points: contact points from a CSV, with line numbers") {
  const std::string dir = scratch_dir("gouge-points");
  // On the semi-cylinder (convex, radius 25.4, axis along y): x = 25.4 cos t, z = 25.4 sin t.
  std::string csv = "x,y,z\n";
  for (double t : {0.5, 1.0, 1.57, 2.5}) csv += std::to_string(25.4 * std::cos(t)) + ",10," + std::to_string(25.4 * std::sin(t)) + "\n";
  write_text(dir + "/cc.csv", csv);
  const CliResult r = run_furrow({"gouge", source_path("examples/parts/semi_cylinder.json"), "--tool",
                                  source_path("examples/tools/flat_d8.json"), "--points", dir + "/cc.csv", "--out", dir + "/g.json"});
  CHECK(r.status == 0);
  const json doc = json::parse(slurp(dir + "/g.json"));
  CHECK(doc["sites"]["mode"] == "points");
  REQUIRE(doc["points"].size() == 4);
  CHECK(doc["points"][2]["line"] == 4);
  for (const json& p : doc["points"]) {
    CHECK(p["status"] == "clear");
    CHECK(p["k2"].get<double>() == doctest::Approx(-1 / 25.4).epsilon(1e-6));
    CHECK(p["cutter"]["k_max"].is_null());  // the flat end mill's sharp rim
  }
}

TEST_CASE("furrow select-tool: a concave cylinder picks the largest ball that fits") {
  const std::string dir = scratch_dir("select-tool");
  Part trough;
  trough.faces.emplace_back("trough", make_cylinder(7, 30, M_PI + 0.3, 2 * M_PI - 0.3));
  write_part_json(trough, dir + "/trough.json");
  const CliResult r = run_furrow({"select-tool", dir + "/trough.json", "--library", source_path("examples/tools/library.json"),
                                  "--grid", "9", "--out", dir + "/s.json"});
  CHECK(r.status == 0);
  CHECK(r.out.find("largest tool gouge-free everywhere: BALL-D12") != std::string::npos);
  const json doc = json::parse(slurp(dir + "/s.json"));
  CHECK(doc["whole_surface"] == "BALL-D12");  // R 6 <= 7 < R 8
  CHECK(doc["tools"][0]["name"] == "BALL-D20");
  CHECK(doc["points"].size() == 81);

  // A groove tighter than every tool: exit 1, and the curvature the design needs.
  Part groove;
  groove.faces.emplace_back("groove", make_cylinder(0.3, 5, M_PI + 0.3, 2 * M_PI - 0.3));
  write_part_json(groove, dir + "/groove.json");
  const CliResult g = run_furrow({"select-tool", dir + "/groove.json", "--library", source_path("examples/tools/library.json"),
                                  "--grid", "5", "--out", dir + "/g.json"});
  CHECK(g.status == 1);
  CHECK(g.out.find("no tool of the library is gouge-free everywhere") != std::string::npos);
  const json gd = json::parse(slurp(dir + "/g.json"));
  CHECK(gd["whole_surface"].is_null());
  const json& p = gd["points"][12];
  CHECK(p["tool"].is_null());
  CHECK(p["needed"]["design_radius"].get<double>() == doctest::Approx(0.3).epsilon(1e-6));
  CHECK(p["needed"]["required_radius"].get<double>() == doctest::Approx(0.5).epsilon(1e-6));  // BALL-D1
}

TEST_CASE("bad input to gouge and select-tool: exit 2, one line, no output") {
  const std::string dir = scratch_dir("gouge-bad");
  write_tool(dir + "/big_corner.json", "X", "bull", 6, 4);
  write_text(dir + "/negative.json", "{\"name\":\"X\",\"type\":\"flat\",\"diameter\":-4}\n");
  write_text(dir + "/taper.json", "{\"name\":\"X\",\"type\":\"taper\",\"diameter\":4}\n");
  write_text(dir + "/down.csv", "x,y,z,nx,ny,nz\n0,10,25.4,0,0,-1\n");
  // Just below the horizontal: n_z < 0 is out of reach (n_z = 0 is a side contact).
  write_text(dir + "/side.csv", "x,y,z,nx,ny,nz\n25.4,10,0,1,0,-1e-12\n");
  write_text(dir + "/off.csv", "0,10,25.4\n0,10,30\n");
  const std::string part = source_path("examples/parts/semi_cylinder.json");
  const std::string ball = source_path("examples/tools/ball_d6.json");
  const std::string out = dir + "/out.json";
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"gouge", part, "--tool", dir + "/big_corner.json", "--out", out}, "big_corner.json: corner_radius: 4 exceeds the tool radius 3"},
      {{"gouge", part, "--tool", dir + "/negative.json", "--out", out}, "negative.json: diameter: must be positive, got -4"},
      {{"gouge", part, "--tool", dir + "/taper.json", "--out", out}, "taper.json: type: unknown tool type \"taper\""},
      {{"gouge", part, "--tool", ball, "--points", dir + "/down.csv", "--out", out}, "down.csv:2: the given normal (0, 0, -1) has n_z < 0"},
      {{"gouge", part, "--tool", ball, "--points", dir + "/side.csv", "--out", out}, "side.csv:2: the given normal"},
      {{"gouge", part, "--tool", ball, "--points", dir + "/off.csv", "--out", out}, "off.csv:2: the point is 4.6 mm from the part"},
      {{"gouge", part, "--tool", ball, "--points", dir + "/off.csv", "--grid", "5", "--out", out}, "either --points or --grid"},
      {{"gouge", part, "--out", out}, "--tool is required"},
      {{"gouge", part, "--tool", ball}, "--out is required"},
      {{"gouge", part, "--tool", ball, "--grid", "1", "--out", out}, "--grid must be between 2 and 250"},
      {{"gouge", part, "--tool", ball, "--out", part}, "the output would overwrite the input"},
      {{"select-tool", part, "--library", ball, "--out", out}, "expected a tool library (a JSON array of tools)"},
      {{"select-tool", part, "--library", dir + "/absent.json"}, "absent.json: cannot open the file"},
      {{"select-tool", part}, "--library is required"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    const CliResult r = run_furrow(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(c.expected) != std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("furrow gouge on a vertical wall: side contacts are checked, not refused") {
  // A wall facing -y ((10,0,0) x (0,0,10) = (0,-100,0)); a point with the
  // wall's own normal (n_z = 0), one with n_z = +1e-300. The bull-nose
  // touches with its torus equator: tip = P + R n - r z (docs/architecture.md
  // "Side contact"); a plane wall is touched, not gouged.
  const std::string dir = scratch_dir("gouge-wall");
  Part part;
  part.faces.emplace_back("wall", make_plane({0, 0, 0}, {10, 0, 0}, {0, 0, 10}));
  write_part_json(part, dir + "/wall.json");
  write_tool(dir + "/bull.json", "BULL-D8-R1", "bull", 8, 1);
  write_text(dir + "/points.csv", "x,y,z,nx,ny,nz\n5,0,5,0,-1,0\n3,0,7,0,-1,1e-300\n");
  const CliResult r = run_furrow({"gouge", dir + "/wall.json", "--tool", dir + "/bull.json", "--points",
                                  dir + "/points.csv", "--out", dir + "/g.json"});
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  const json doc = json::parse(slurp(dir + "/g.json"));
  REQUIRE(doc["points"].size() == 2);
  const Eigen::Vector3d expected[] = {{5, -4, 4}, {3, -4, 6}};
  for (int k = 0; k < 2; ++k) {
    const json& p = doc["points"][k];
    CAPTURE(k);
    CHECK(p["status"] == "clear");
    CHECK(p["cutter"]["side"] == true);
    CHECK(p["cutter"]["contact_angle_deg"].get<double>() == doctest::Approx(90));
    CHECK((vec(p["tip"]) - expected[k]).norm() < 1e-6);
    CHECK((vec(p["cutter"]["dir_max"]) - Eigen::Vector3d::UnitZ()).norm() < 1e-9);
  }
  CHECK(doc["summary"]["unreachable"] == 0);
}
