// Programs that change tools (machining/cutter/path_tools.hpp): each pass is
// predicted with the cutter loaded when it is cut, the z-map is what all of
// them leave together, and each rapid is checked with the tool that travels
// it. Oracles: the closed-form lower envelopes of a ball and a flat end mill
// over a plane, and the overcut of a flat end mill's rim on a slope.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/machining/gcode_reader.hpp"
#include "machining/cutter/path_tools.hpp"
#include "machining/prediction/path_prediction.hpp"
#include "machining/prediction/prediction_file.hpp"

using namespace furrow;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ToolSpec tool(const std::string& name, ToolType type, double diameter, double corner) {
  ToolSpec t;
  t.name = name;
  t.type = type;
  t.diameter = diameter;
  t.corner_radius = corner;
  return t;
}

const ToolSpec kBall = tool("B6", ToolType::ball, 6, 3);
const ToolSpec kFlat = tool("FL10", ToolType::flat, 10, 0);

std::vector<ToolTableEntry> table_of(std::initializer_list<std::pair<int, ToolSpec>> entries) {
  std::vector<ToolTableEntry> table;
  for (const auto& [number, spec] : entries) {
    ToolTableEntry e;
    e.number = number;
    e.tool = spec;
    table.push_back(e);
  }
  return table;
}

std::string error_of(const Toolpath& path, const std::optional<ToolSpec>& single,
                     const std::optional<std::vector<ToolTableEntry>>& table) {
  try {
    tools_for_path(path, single, "ball.json", table, "table.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Two passes along x over the plate z = 0: the ball (T1) 0.1 mm above it at
// y = 10, the flat (T2) 0.2 mm into it at y = 25.
const char* kTwoTools =
    "G21 G90 G54\n"            // 1
    "T1 M6\n"                  // 2
    "G0 X-10 Y10 Z5\n"         // 3
    "Z0.1\n"                   // 4
    "G1 X2 F800\n"             // 5  onto the plate (from off it: not evaluated)
    "X20\n"                    // 6
    "X38\n"                    // 7
    "X50\n"                    // 8  off it again
    "G0 Z5\n"                  // 9
    "G28 G91 Z0\n"             // 10
    "G90 T2 M6\n"              // 11
    "G0 X-10 Y25 Z5\n"         // 12
    "Z-0.2\n"                  // 13
    "G1 X2\n"                  // 14
    "X20\n"                    // 15
    "X38\n"                    // 16
    "X50\n"                    // 17
    "G0 Z5\n"                  // 18
    "M30\n";                   // 19

}  // namespace

TEST_CASE("path tools: a program that changes tools needs a table that has every tool it loads") {
  const Toolpath path = parse_gcode(kTwoTools, "two.nc");
  CHECK(error_of(path, kBall, std::nullopt)
            .find("two.nc: the program changes tools (T1 at line 2, T2 at line 11): give a tool table") == 0);
  CHECK(error_of(path, std::nullopt, table_of({{1, kBall}})).find("table.json: no tool T2, which two.nc:11 loads") == 0);
  // A cut before the first change, with a table: the spindle's tool is not in the file.
  const Toolpath early = parse_gcode("G0 X0 Y0 Z1\nG1 X5\nT2 M6\nG0 X0 Y5 Z1\nG1 X5\n", "early.nc");
  CHECK(error_of(early, std::nullopt, table_of({{2, kFlat}})).find("early.nc:2: a cut before the first tool change") == 0);
  const PathTools with_single = tools_for_path(early, kBall, "ball.json", table_of({{2, kFlat}}), "table.json");
  CHECK(with_single.numbers == std::vector<int>{0, 2});
  CHECK(with_single.of_pass == std::vector<int>{0, 1});
  // One tool number, loaded twice: no table needed.
  const Toolpath again = parse_gcode("T4 M6\nG0 X0 Y0 Z1\nG1 X5\nT4 M6\nG0 X0 Y5 Z1\nG1 X5\n", "again.nc");
  const PathTools one = tools_for_path(again, kBall, "ball.json", std::nullopt, "");
  CHECK_FALSE(one.changes_tools());
  CHECK(one.of_pass == std::vector<int>{0, 0});
}

TEST_CASE("path tools: each pass cut with its own tool, the z-map what both leave, against closed forms") {
  const double R_ball = 3, R_flat = 5;
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {40, 0, 0}, {0, 40, 0}));
  const Toolpath path = parse_gcode(kTwoTools, "two.nc");
  const PathTools tools = tools_for_path(path, std::nullopt, "", table_of({{1, kBall}, {2, kFlat}}), "table.json");
  REQUIRE(tools.cutters.size() == 2);
  CHECK(tools.numbers == std::vector<int>{1, 2});
  CHECK(tools.of_pass == std::vector<int>{0, 1});
  PathPredictionOptions options;
  options.resolution = 0.1;
  const PathPrediction r = predict_path(part, tools, path, options);
  // Machined height over the plate (normal +z, so the error is the height):
  // the ball's sphere bottom within 3 mm of y = 10, the flat's bottom within
  // 5 mm of y = 25; nothing cut elsewhere.
  auto expected = [&](double y) {
    double h = kInf;
    const double d_ball = std::fabs(y - 10);
    if (d_ball < R_ball) h = std::min(h, 0.1 + R_ball - std::sqrt(R_ball * R_ball - d_ball * d_ball));
    if (std::fabs(y - 25) < R_flat) h = std::min(h, -0.2);
    return h;
  };
  REQUIRE(r.map.faces.size() == 1);
  const FaceErrorMap& m = r.map.faces[0];
  int reached = 0, uncut = 0;
  for (int j = 0; j < m.nv; ++j)
    for (int i = 0; i < m.nu; ++i) {
      const Eigen::Vector3d q = part.faces[0].surface().point(m.u(i), m.v(j));
      const double e = expected(q.y());
      const std::size_t k = m.index(i, j);
      // Samples within a z-map cell of a cut's edge depend on the grid (error_map.hpp).
      if (std::fabs(std::fabs(q.y() - 10) - R_ball) < 0.2 || std::fabs(std::fabs(q.y() - 25) - R_flat) < 0.2) continue;
      if (std::isfinite(e)) {
        REQUIRE(m.status[k] == ErrorCellStatus::reached);
        CHECK(m.error[k] == doctest::Approx(e).epsilon(1e-6).scale(1e-6));
        ++reached;
      } else {
        CHECK(m.status[k] == ErrorCellStatus::not_reached);
        ++uncut;
      }
    }
  CHECK(reached > 1000);
  CHECK(uncut > 1000);
  CHECK(r.map.max_overcut.error == doctest::Approx(-0.2).epsilon(1e-9));
  // The most material is left at the rim of the ball's cut, 0.1 + R (not attained).
  CHECK(r.map.max_undercut.error <= 0.1 + R_ball + 1e-9);
  CHECK(r.map.max_undercut.error > 0.1 + R_ball - 0.01);
  // Per step, each pass with its own cutter: the ball's steps leave 0.1 mm,
  // the flat's cut 0.2 mm in.
  int ball_steps = 0, flat_steps = 0;
  for (const StepPrediction& s : r.steps) {
    if (s.status != StepStatus::evaluated) continue;  // onto and off the plate
    if (s.pass == 0) {
      CHECK(s.error.undercut.error == doctest::Approx(0.1).epsilon(1e-9));
      ++ball_steps;
    } else {
      CHECK(s.error.overcut.error == doctest::Approx(-0.2).epsilon(1e-9));
      ++flat_steps;
    }
  }
  CHECK(ball_steps == 2);
  CHECK(flat_steps == 2);
  // Each tool's pass stands alone: no scallop is measured between them.
  CHECK(r.scallops.empty());
  // prediction.json says which tool cut which pass, and reads back.
  const Prediction p = make_prediction(part, r, options, "plate.json", "two.nc");
  const nlohmann::json doc = nlohmann::json::parse(prediction_to_json_text(p));
  REQUIRE(doc["tools"].size() == 2);
  CHECK(doc["tools"][0]["number"] == 1);
  CHECK(doc["tools"][1]["tool"]["name"] == "FL10");
  CHECK(doc["pass_tools"] == nlohmann::json::array({0, 1}));
  CHECK(doc["tool"]["name"] == "B6");
  const Prediction back = parse_prediction_json(prediction_to_json_text(p), "p.json");
  REQUIRE(back.tools.size() == 2);
  CHECK(back.tools[1].number == 2);
  CHECK(back.tools[1].tool.diameter == 10);
  CHECK(back.pass_tools == std::vector<int>{0, 1});
  nlohmann::json bad = doc;
  bad["pass_tools"][1] = 2;
  CHECK_THROWS_WITH_AS(parse_prediction_json(bad.dump(), "bad.json"),
                       doctest::Contains("bad.json: pass_tools[1]: expected an index into tools (0 to 1)"), InputError);
  // A one-tool prediction writes neither member.
  const PathPrediction single =
      predict_path(part, Cutter(kBall), parse_gcode("G0 X-10 Y10 Z5\nZ0.1\nG1 X50\n", "one.nc"), options);
  const nlohmann::json one = nlohmann::json::parse(prediction_to_json_text(make_prediction(part, single, options, "p", "t")));
  CHECK_FALSE(one.contains("tools"));
  CHECK_FALSE(one.contains("pass_tools"));
}

TEST_CASE("path tools: a rapid is checked with the tool that travels it") {
  // The slope z = 0.2 x. A rapid along y at x = 0 with its tip 0.3 mm up
  // clears it with a 6 mm ball (the sphere's bottom rises faster than the
  // slope: 0.3 + 3 - sqrt(9 - d^2) - 0.2 d > 0 for every d), but a 10 mm
  // flat end mill's bottom reaches out to x = 5, where the slope is at 1.0.
  // The deepest overcut along the normal (-0.2, 0, 1) / sqrt(1.04) is where
  // the vertical gap (0.2 x - 0.3) / n_z equals the distance (5 - x) / n_x to
  // the rim: x = 5.06 / 1.04, depth (5 - x) sqrt(1.04) / 0.2.
  Part part;
  part.faces.emplace_back("slope", make_plane({-10, 0, -2}, {20, 0, 4}, {0, 40, 0}));
  const std::string rapid_pass =
      "G0 X0 Y-10 Z5\n"  // from the change position: unchecked
      "Z0.3\n"           // down, beyond the part in y
      "Y50\n"            // along the slope
      "Z5\n"
      "X-8 Y-10\n"       // beside the part
      "Z-1.5\n"
      "G1 Y50 F500\n"    // a cut (0.1 mm above the slope for the ball), so the program has one
      "G0 Z5\n";         // up beyond the part
  const Toolpath path = parse_gcode("G21 G90\nT1 M6\n" + rapid_pass + "T2 M6\n" + rapid_pass, "rapids.nc");
  const PathTools tools = tools_for_path(path, std::nullopt, "", table_of({{1, kBall}, {2, kFlat}}), "table.json");
  PathPredictionOptions options;
  options.resolution = 0.25;
  const PathPrediction r = predict_path(part, tools, path, options);
  REQUIRE(r.rapids.gouges.size() == 1);
  const RapidGouge& g = r.rapids.gouges[0];
  CHECK(g.line == 14);  // the flat's "Y50"
  const double x = 5.06 / 1.04;
  CHECK(g.depth == doctest::Approx((5 - x) * std::sqrt(1.04) / 0.2).epsilon(1e-5));
  CHECK(g.at.x() == doctest::Approx(x).epsilon(1e-4));
  CHECK(r.rapids.checked + r.rapids.unchecked == path.rapids.size());
  // The same program with the ball for both: no rapid gouge.
  const PathPrediction all_ball =
      predict_path(part, tools_for_path(path, std::nullopt, "", table_of({{1, kBall}, {2, kBall}}), "t.json"), path, options);
  CHECK(all_ball.rapids.gouges.empty());
}
