#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/machining/tool_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

TEST_CASE("tool JSON: ball, flat and bull-nose read with their corner radius") {
  const ToolSpec ball = parse_tool_json(R"({"name":"B6","type":"ball","diameter":6})", "t.json");
  CHECK(ball.type == ToolType::ball);
  CHECK(ball.diameter == 6);
  CHECK(ball.corner_radius == 3);
  const ToolSpec flat = parse_tool_json(R"({"name":"F8","type":"flat","diameter":8})", "t.json");
  CHECK(flat.corner_radius == 0);
  const ToolSpec bull =
      parse_tool_json(R"({"name":"T","type":"bull","diameter":10,"corner_radius":2})", "t.json");
  CHECK(bull.type == ToolType::bull);
  CHECK(bull.corner_radius == 2);
  // Inch: a quarter-inch ball, its corner radius given with rounding.
  const ToolSpec inch = parse_tool_json(
      R"({"name":"B1/4","type":"ball","diameter":0.25,"corner_radius":0.125,"units":"inch"})", "t.json");
  CHECK(inch.diameter == doctest::Approx(6.35));
  CHECK(inch.corner_radius == inch.diameter / 2);
}

TEST_CASE("tool JSON and libraries round-trip through the writer") {
  const std::string dir = test::scratch_dir("tool-roundtrip");
  const std::vector<ToolSpec> library = read_tool_library(test::source_path("examples/tools/library.json"));
  REQUIRE(library.size() >= 20);
  write_tool_library(library, dir + "/lib.json");
  const std::vector<ToolSpec> again = read_tool_library(dir + "/lib.json");
  REQUIRE(again.size() == library.size());
  for (std::size_t i = 0; i < library.size(); ++i) {
    CHECK(again[i].name == library[i].name);
    CHECK(again[i].type == library[i].type);
    CHECK(again[i].diameter == library[i].diameter);
    CHECK(again[i].corner_radius == library[i].corner_radius);
  }
  CHECK(test::slurp(dir + "/lib.json") == tool_library_to_json_text(again));
  write_tool_file(library[3], dir + "/one.json");
  const ToolSpec one = read_tool_file(dir + "/one.json");
  CHECK(one.name == library[3].name);
  for (const char* file : {"ball_d6.json", "bull_d10_r2.json", "flat_d8.json", "ball_d20.json"})
    CHECK_NOTHROW(read_tool_file(test::source_path(std::string("examples/tools/") + file)));
}

TEST_CASE("bad tool files: one message naming the file and the field") {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"name":"x","type":"bull","diameter":6,"corner_radius":4})",
       "t.json: corner_radius: 4 exceeds the tool radius 3 (diameter / 2)"},
      {R"({"name":"x","type":"ball","diameter":-6})", "t.json: diameter: must be positive, got -6"},
      {R"({"name":"x","type":"bull","diameter":6,"corner_radius":-1})",
       "t.json: corner_radius: must not be negative, got -1"},
      {R"({"name":"x","type":"taper","diameter":6})", "t.json: type: unknown tool type \"taper\""},
      {R"({"name":"x","type":"bull","diameter":6})", "t.json: corner_radius: missing"},
      {R"({"name":"x","type":"bull","diameter":6,"corner_radius":0})", "use type \"flat\""},
      {R"({"name":"x","type":"bull","diameter":6,"corner_radius":3})", "use type \"ball\""},
      {R"({"name":"x","type":"ball","diameter":6,"corner_radius":2})", "a ball end mill's corner radius is diameter / 2 = 3"},
      {R"({"name":"x","type":"flat","diameter":6,"corner_radius":1})", "a flat end mill has corner radius 0"},
      {R"({"name":"x","type":"ball","diameter":6,"corner_raduis":3})", "t.json: corner_raduis: unknown member"},
      {R"({"name":"","type":"ball","diameter":6})", "t.json: name: must not be empty"},
      {R"({"type":"ball","diameter":6})", "t.json: name: missing"},
      {R"({"name":"x","type":"ball","diameter":"6"})", "t.json: diameter: expected a number"},
      {R"({"name":"x","type":"ball","diameter":6,"units":"furlong"})", "t.json: units: unknown units"},
      {R"([{"name":"x","type":"ball","diameter":6}])", "expected one tool (a JSON object), found an array"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    CHECK_THROWS_WITH_AS(parse_tool_json(c.text, "t.json"), doctest::Contains(c.expected), InputError);
  }
  CHECK_THROWS_WITH_AS(parse_tool_library_json("[]", "lib.json"), doctest::Contains("lib.json: the tool library is empty"), InputError);
  CHECK_THROWS_WITH_AS(parse_tool_library_json(R"({"name":"x"})", "lib.json"), doctest::Contains("found one object"), InputError);
  CHECK_THROWS_WITH_AS(
      parse_tool_library_json(R"([{"name":"a","type":"ball","diameter":2},{"name":"a","type":"flat","diameter":3}])", "lib.json"),
      doctest::Contains("lib.json: [1].name: duplicate tool name \"a\""), InputError);
  CHECK_THROWS_WITH_AS(
      parse_tool_library_json(R"([{"name":"a","type":"ball","diameter":2},{"name":"b","type":"bull","diameter":3,"corner_radius":2}])", "lib.json"),
      doctest::Contains("lib.json: [1].corner_radius: 2 exceeds the tool radius 1.5"), InputError);
  ToolSpec bad{"w", ToolType::bull, 4, 5};
  CHECK_THROWS_AS(tool_to_json_text(bad), InputError);
}
