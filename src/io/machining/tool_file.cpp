#include "io/machining/tool_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/limits.hpp"
#include "base/atomic_file.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

std::string number_text(double x) { return general(x, 12); }

constexpr double kBallRadiusRelativeTolerance = 1e-9;

ToolType parse_type(const json& value, const std::string& where) {
  const std::string text = jf::string(value, where);
  if (text == "ball") return ToolType::ball;
  if (text == "flat") return ToolType::flat;
  if (text == "bull") return ToolType::bull;
  throw InputError(where + ": unknown tool type " + quote_field(text) + " (expected \"ball\", \"flat\" or \"bull\")");
}

ToolSpec parse_tool(const json& jtool, const std::string& where) {
  const JsonCursor o(jtool, where);
  o.only({"name", "type", "diameter", "corner_radius", "units"}, "docs/formats.md \"Tool JSON\"");
  const double scale = o.has("units") ? units_to_mm(o.string("units"), o.path("units")) : 1.0;

  ToolSpec tool;
  tool.name = o.string("name");
  tool.type = parse_type(o.raw("type"), o.path("type"));
  tool.diameter = scale * o.positive("diameter");
  const double radius = 0.5 * tool.diameter;

  const std::string r_where = o.path("corner_radius");
  const json* jr = o.has("corner_radius") ? &o.raw("corner_radius") : nullptr;
  if (!jr && tool.type == ToolType::bull)
    throw InputError(r_where + ": missing (a bull-nose tool needs its corner radius)");
  if (jr) {
    tool.corner_radius = scale * jf::number(*jr, r_where);
    // A ball's corner radius is exactly diameter / 2; a file may say so with a
    // little rounding (e.g. 3.175 for a 1/4" ball converted from inch).
    if (tool.type == ToolType::ball &&
        std::abs(tool.corner_radius - radius) <= kBallRadiusRelativeTolerance * radius)
      tool.corner_radius = radius;
  } else {
    tool.corner_radius = tool.type == ToolType::ball ? radius : 0.0;
  }
  validate_tool(tool, where);
  return tool;
}

json tool_json(const ToolSpec& tool) {
  json j;
  j["name"] = tool.name;
  j["type"] = to_string(tool.type);
  j["diameter"] = jf::finite(tool.diameter, "diameter");
  j["corner_radius"] = jf::finite(tool.corner_radius, "corner_radius");
  return j;
}

}  // namespace

const char* to_string(ToolType type) {
  switch (type) {
    case ToolType::ball: return "ball";
    case ToolType::flat: return "flat";
    case ToolType::bull: return "bull";
  }
  return "?";
}

void validate_tool(const ToolSpec& tool, const std::string& where) {
  if (tool.name.empty()) throw InputError(jf::child(where, "name") + ": must not be empty");
  if (!std::isfinite(tool.diameter))  // e.g. 1e307 inch, beyond a double in mm
    throw InputError(jf::child(where, "diameter") + ": not a finite number of millimetres");
  if (!(tool.diameter > 0))
    throw InputError(jf::child(where, "diameter") + ": must be positive, got " +
                     number_text(tool.diameter));
  // Physical range (docs/formats.md "Limits"): a micro-tool to a 10 m cutter.
  if (tool.diameter < limits::kMinToolDiameterMm || tool.diameter > limits::kMaxToolDiameterMm)
    throw InputError(jf::child(where, "diameter") + ": " + number_text(tool.diameter) +
                     " mm is outside the tool diameter range " +
                     number_text(limits::kMinToolDiameterMm) + " to " +
                     number_text(limits::kMaxToolDiameterMm) + " mm");
  const std::string r_where = jf::child(where, "corner_radius");
  const double radius = 0.5 * tool.diameter, r = tool.corner_radius;
  if (!std::isfinite(r) || r < 0)
    throw InputError(r_where + ": must not be negative, got " + number_text(r));
  if (r > 0 && r < limits::kMinCornerRadiusMm)
    throw InputError(r_where + ": " + number_text(r) + " mm is below the smallest corner radius " +
                     number_text(limits::kMinCornerRadiusMm) + " mm (use 0, a flat end mill)");
  if (r > radius)
    throw InputError(r_where + ": " + number_text(r) + " exceeds the tool radius " +
                     number_text(radius) + " (diameter / 2)");
  switch (tool.type) {
    case ToolType::ball:
      if (r != radius)
        throw InputError(r_where + ": a ball end mill's corner radius is diameter / 2 = " +
                         number_text(radius) + ", got " + number_text(r));
      break;
    case ToolType::flat:
      if (r != 0)
        throw InputError(r_where + ": a flat end mill has corner radius 0, got " +
                         number_text(r) + " (use type \"bull\")");
      break;
    case ToolType::bull:
      if (!(r > 0 && r < radius))
        throw InputError(r_where + ": a bull-nose needs 0 < corner_radius < diameter / 2 = " +
                         number_text(radius) + ", got " + number_text(r) +
                         (r == 0 ? " (use type \"flat\")" : " (use type \"ball\")"));
      break;
  }
}

ToolSpec parse_tool_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  if (doc.is_array())
    throw InputError(root + " expected one tool (a JSON object), found an array (a tool library?)");
  return parse_tool(doc, root);
}

ToolSpec read_tool_file(const std::string& path) {
  return parse_tool_json(jf::read_text(path), path);
}

std::vector<ToolSpec> parse_tool_library_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  if (doc.is_object())
    throw InputError(root + " expected a tool library (a JSON array of tools), found one object");
  jf::array(doc, root);
  if (doc.empty()) throw InputError(root + " the tool library is empty");
  std::vector<ToolSpec> tools;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    const std::string where = name + ": [" + std::to_string(i) + "]";
    ToolSpec tool = parse_tool(doc[i], where);
    for (std::size_t k = 0; k < tools.size(); ++k)
      if (tools[k].name == tool.name)
        throw InputError(jf::child(where, "name") + ": duplicate tool name " + quote_field(tool.name) + " (also [" + std::to_string(k) + "])");
    tools.push_back(std::move(tool));
  }
  return tools;
}

std::vector<ToolSpec> read_tool_library(const std::string& path) {
  return parse_tool_library_json(jf::read_text(path), path);
}

std::vector<ToolTableEntry> parse_tool_table_json(const std::string& text, const std::string& name,
                                                  const std::string& folder) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  if (!doc.is_object())
    throw InputError(root + " expected a tool table (a JSON object from \"T1\", \"T2\", ... to tools)");
  if (doc.empty()) throw InputError(root + " the tool table is empty");
  std::vector<ToolTableEntry> table;
  std::map<long, std::string> keys;  // tool number -> its key as written
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string& key = it.key();
    // "T7", "t7", "7" and "T07" all name tool 7 (docs/formats.md "Tool table").
    const std::size_t first = !key.empty() && (key[0] == 'T' || key[0] == 't') ? 1 : 0;
    const bool digits = key.size() > first && key.size() - first <= 8 &&
                        key.find_first_not_of("0123456789", first) == std::string::npos;
    const long number = digits ? std::stol(key.substr(first)) : -1;
    if (number < 1 || number > 1000000)
      throw InputError(name + ": " + quote_field(key) +
                       ": expected a tool number \"T1\" to \"T1000000\" (or \"1\" to \"1000000\") as the key");
    const std::string where = name + ": " + key;
    if (const auto twice = keys.find(number); twice != keys.end())
      throw InputError(where + ": tool " + std::to_string(number) + " is given twice (also " + twice->second + ")");
    ToolTableEntry entry;
    entry.number = static_cast<int>(number);
    if (it.value().is_string()) {
      const std::string file = it.value().get<std::string>();
      if (file.empty()) throw InputError(where + ": empty tool file name");
      const std::filesystem::path p(file);
      entry.file = p.is_absolute() || folder.empty() ? file : (std::filesystem::path(folder) / p).string();
      entry.tool = read_tool_file(entry.file);
    } else if (it.value().is_object()) {
      entry.tool = parse_tool(it.value(), where);
    } else {
      throw InputError(where + ": expected a tool (a JSON object) or the name of a tool file");
    }
    table.push_back(std::move(entry));
    keys.emplace(number, key);
  }
  std::vector<std::size_t> order(table.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return table[a].number < table[b].number; });
  std::vector<ToolTableEntry> sorted;
  for (std::size_t k : order) sorted.push_back(std::move(table[k]));
  return sorted;
}

std::vector<ToolTableEntry> read_tool_table(const std::string& path) {
  return parse_tool_table_json(jf::read_text(path), path, std::filesystem::path(path).parent_path().string());
}

std::string tool_to_json_text(const ToolSpec& tool) {
  validate_tool(tool, "tool");
  return jf::to_text(tool_json(tool));
}

std::string tool_library_to_json_text(const std::vector<ToolSpec>& tools) {
  json doc = json::array();
  for (std::size_t i = 0; i < tools.size(); ++i) {
    validate_tool(tools[i], "tools[" + std::to_string(i) + "]");
    doc.push_back(tool_json(tools[i]));
  }
  return jf::to_text(doc);
}

void write_tool_file(const ToolSpec& tool, const std::string& path) {
  write_file_atomically(path, tool_to_json_text(tool));
}

void write_tool_library(const std::vector<ToolSpec>& tools, const std::string& path) {
  write_file_atomically(path, tool_library_to_json_text(tools));
}

}  // namespace furrow
