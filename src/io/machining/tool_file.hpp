#pragma once
// Tool files (docs/architecture.md "Files", docs/formats.md "Tool JSON"): one end mill
// as a JSON object, a shop's tool library as a JSON array of them.
//
//   {"name": "BN10R2", "type": "bull", "diameter": 10, "corner_radius": 2}
//
// This is plain data: the geometry (cutter location, curvatures, envelope)
// lives in machining/cutter/cutter.hpp, which builds a Cutter from a ToolSpec. The
// reader validates everything a user can get wrong and throws InputError
// naming the file and the field ("tools.json: [3].corner_radius: 6 exceeds
// the tool radius 5 (diameter / 2)"): unknown members (a typo would otherwise
// be silently ignored), a type other than ball/flat/bull, non-positive
// diameter, negative corner radius, a corner radius that contradicts the
// type, duplicate names in a library. Lengths are millimetres unless the
// tool says "units": "inch"; the writer always writes millimetres.
#include <string>
#include <vector>

namespace furrow {

// The three end-mill families of docs/architecture.md "Cutter geometry". The list is
// open: a tapered (APT) cutter would be a fourth value with its half-angle.
enum class ToolType { ball, flat, bull };

const char* to_string(ToolType type);

struct ToolSpec {
  std::string name;
  ToolType type = ToolType::ball;
  double diameter = 0;       // [mm], > 0
  double corner_radius = 0;  // [mm]; ball: diameter / 2, flat: 0, bull: strictly between
};

// Throws InputError naming `where` (e.g. "tools.json: [2]") when the spec is
// inconsistent: empty name, non-finite or non-positive diameter, negative
// corner radius, corner radius above diameter / 2, or one that does not match
// the type (a ball's is diameter / 2, a flat's is 0, a bull's strictly
// between).
void validate_tool(const ToolSpec& tool, const std::string& where);

// One tool (a JSON object). `name` stands for the source in messages.
ToolSpec parse_tool_json(const std::string& text, const std::string& name);
ToolSpec read_tool_file(const std::string& path);

// A library: a non-empty JSON array of tools with distinct names, in file
// order.
std::vector<ToolSpec> parse_tool_library_json(const std::string& text, const std::string& name);
std::vector<ToolSpec> read_tool_library(const std::string& path);

// A tool table: which cutter each tool number of a program is (G-code
// `T n M6`, io/machining/gcode_reader.hpp). A JSON object from "T<n>", "t<n>" or
// "<n>" (n a whole number from 1 to 1000000, leading zeros allowed; T0 is
// the empty spindle) to a tool, either an
// object as above or the name of a tool file, relative to the table's
// folder:
//
//   {"T1": {"name": "FL12", "type": "flat", "diameter": 12}, "T7": "ball6.json"}
//
// Entries come back by tool number. Errors name the table and the key
// ("table.json: T7.diameter: ..."), or the tool file a key names; two keys
// of one number ("T7" and "7", "T7" and "T07") are refused naming both.
struct ToolTableEntry {
  int number = 0;
  ToolSpec tool;
  std::string file;  // the tool file it names; empty for a tool written in the table
};
std::vector<ToolTableEntry> parse_tool_table_json(const std::string& text, const std::string& name,
                                                  const std::string& folder);
std::vector<ToolTableEntry> read_tool_table(const std::string& path);

// Deterministic writers (millimetres; corner_radius always written).
std::string tool_to_json_text(const ToolSpec& tool);
std::string tool_library_to_json_text(const std::vector<ToolSpec>& tools);
void write_tool_file(const ToolSpec& tool, const std::string& path);
void write_tool_library(const std::vector<ToolSpec>& tools, const std::string& path);

}  // namespace furrow
