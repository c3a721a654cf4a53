// Tool tables (io/machining/tool_file.hpp): which cutter each T number of a program
// is, written inline or as tool files beside the table, and every way a
// table can be wrong, each named by file and key.
#include <doctest/doctest.h>

#include <string>

#include "base/error.hpp"
#include "io/machining/tool_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

std::string error_of(const std::string& text, const std::string& folder = "") {
  try {
    parse_tool_table_json(text, "table.json", folder);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("tool table: inline tools and tool files beside the table, by tool number") {
  const std::string dir = test::scratch_dir("tool-table");
  test::write_text(dir + "/ball6.json", "{\"name\": \"B6\", \"type\": \"ball\", \"diameter\": 6}\n");
  test::write_text(dir + "/table.json",
                   "{\"T12\": \"ball6.json\",\n"
                   " \"T3\": {\"name\": \"FL12\", \"type\": \"flat\", \"diameter\": 12},\n"
                   " \"t7\": {\"name\": \"BN10\", \"type\": \"bull\", \"diameter\": 0.5, \"corner_radius\": 0.125,"
                   " \"units\": \"inch\"}}\n");
  const std::vector<ToolTableEntry> table = read_tool_table(dir + "/table.json");
  REQUIRE(table.size() == 3);
  CHECK(table[0].number == 3);
  CHECK(table[0].tool.name == "FL12");
  CHECK(table[0].tool.type == ToolType::flat);
  CHECK(table[0].file.empty());
  CHECK(table[1].number == 7);
  CHECK(table[1].tool.diameter == doctest::Approx(12.7).epsilon(1e-12));
  CHECK(table[1].tool.corner_radius == doctest::Approx(3.175).epsilon(1e-12));
  CHECK(table[2].number == 12);
  CHECK(table[2].tool.name == "B6");
  CHECK(table[2].tool.corner_radius == 3);
  CHECK(table[2].file == dir + "/ball6.json");
  // Bare numbers are keys too, and mix with T keys: "5" is tool 5.
  const std::vector<ToolTableEntry> bare =
      parse_tool_table_json("{\"5\": \"ball6.json\", \"T2\": {\"name\": \"F4\", \"type\": \"flat\", \"diameter\": 4}}",
                            "bare.json", dir);
  REQUIRE(bare.size() == 2);
  CHECK(bare[0].number == 2);
  CHECK(bare[0].tool.name == "F4");
  CHECK(bare[1].number == 5);
  CHECK(bare[1].tool.name == "B6");
  // A tool file the table names is read with its own name in errors.
  test::write_text(dir + "/bad.json", "{\"T1\": \"missing.json\"}\n");
  CHECK_THROWS_WITH_AS(read_tool_table(dir + "/bad.json"), doctest::Contains((dir + "/missing.json").c_str()), InputError);
}

TEST_CASE("tool table: bad tables are refused, naming the file and the key") {
  const std::string tool = "{\"name\": \"B6\", \"type\": \"ball\", \"diameter\": 6}";
  CHECK(error_of("[" + tool + "]").find("table.json: expected a tool table") == 0);
  CHECK(error_of("{}").find("table.json: the tool table is empty") == 0);
  CHECK(error_of("{\"X1\": " + tool + "}").find("table.json: \"X1\": expected a tool number") == 0);
  CHECK(error_of("{\"T0\": " + tool + "}").find("table.json: \"T0\": expected a tool number") == 0);
  CHECK(error_of("{\"T\": " + tool + "}").find("table.json: \"T\": expected a tool number") == 0);
  CHECK(error_of("{\"T1.5\": " + tool + "}").find("table.json: \"T1.5\": expected a tool number") == 0);
  CHECK(error_of("{\"T99999999\": " + tool + "}").find("table.json: \"T99999999\": expected a tool number") == 0);
  CHECK(error_of("{\"T7\": " + tool + ", \"T07\": " + tool + "}").find("table.json: T7: tool 7 is given twice (also T07)") ==
        0);
  // One number under two spellings (the keys are read in sorted order).
  CHECK(error_of("{\"1\": " + tool + ", \"T1\": " + tool + "}").find("table.json: T1: tool 1 is given twice (also 1)") == 0);
  CHECK(error_of("{\"T02\": " + tool + ", \"2\": " + tool + "}").find("table.json: T02: tool 2 is given twice (also 2)") ==
        0);
  CHECK(error_of("{\"t1\": " + tool + ", \"001\": " + tool + "}").find("table.json: t1: tool 1 is given twice (also 001)") ==
        0);
  CHECK(error_of("{\"0\": " + tool + "}").find("table.json: \"0\": expected a tool number") == 0);
  CHECK(error_of("{\"-1\": " + tool + "}").find("table.json: \"-1\": expected a tool number") == 0);
  CHECK(error_of("{\"1000001\": " + tool + "}").find("table.json: \"1000001\": expected a tool number") == 0);
  CHECK(error_of("{\"\": " + tool + "}").find("table.json: \"\": expected a tool number") == 0);
  CHECK(error_of("{\"1 \": " + tool + "}").find("table.json: \"1 \": expected a tool number") == 0);
  // The same key twice: a JSON parser keeps one of them without a word.
  CHECK(error_of("{\"T7\": " + tool + ", \"T7\": " + tool + "}")
            .find("table.json: member \"T7\" is given twice in one object") == 0);
  CHECK(error_of("{\"T7\": 6}").find("table.json: T7: expected a tool (a JSON object) or the name of a tool file") == 0);
  CHECK(error_of("{\"T7\": \"\"}").find("table.json: T7: empty tool file name") == 0);
  CHECK(error_of("{\"T7\": {\"name\": \"B6\", \"type\": \"ball\", \"diameter\": -6}}").find("table.json: T7.diameter") ==
        0);
  CHECK(error_of("{\"T7\": {\"name\": \"B6\", \"type\": \"ball\", \"diameter\": 6, \"dia\": 6}}").find("table.json: T7") ==
        0);
}

TEST_CASE("JSON files: a member given twice in one object is refused wherever it is") {
  // Not only tables: a tool whose diameter is written twice has no one diameter.
  CHECK_THROWS_WITH_AS(parse_tool_json("{\"name\": \"B\", \"type\": \"ball\", \"diameter\": 6, \"diameter\": 8}", "t.json"),
                       doctest::Contains("t.json: member \"diameter\" is given twice in one object"), InputError);
  // The same name in different objects is fine.
  CHECK(parse_tool_library_json("[{\"name\": \"A\", \"type\": \"ball\", \"diameter\": 6},"
                                " {\"name\": \"B\", \"type\": \"ball\", \"diameter\": 8}]",
                                "lib.json")
            .size() == 2);
}

TEST_CASE("tool table: the example table names the example tools beside it") {
  const std::vector<ToolTableEntry> table = read_tool_table(test::source_path("examples/tools/table.json"));
  REQUIRE(table.size() == 3);
  CHECK(table[0].tool.type == ToolType::ball);
  CHECK(table[1].tool.corner_radius == 2);
  CHECK(table[2].tool.type == ToolType::flat);
  CHECK(table[2].tool.diameter == 8);
}
