#include "machining/cutter/path_tools.hpp"

#include <algorithm>
#include <map>

#include "base/error.hpp"

namespace furrow {

namespace {

// The line of the first change that loads `number`, for messages.
int change_line(const Toolpath& path, int number) {
  for (const ToolChange& c : path.tool_changes)
    if (c.tool == number) return c.line;
  return 0;
}

std::string where(const Toolpath& path, int line) { return path.source + ":" + std::to_string(line); }

}  // namespace

PathTools single_tool(const Cutter& cutter, const Toolpath& path) {
  PathTools out;
  out.cutters.push_back(cutter);
  out.numbers.push_back(0);
  out.of_pass.assign(path.passes.size(), 0);
  out.of_rapid.assign(path.rapids.size(), 0);
  return out;
}

PathTools tools_for_path(const Toolpath& path, const std::optional<ToolSpec>& tool, const std::string& tool_source,
                         const std::optional<std::vector<ToolTableEntry>>& given_table, const std::string& given_source) {
  std::optional<std::vector<ToolTableEntry>> table = given_table;
  std::string table_source = given_source;
  if (path.defined_tools.size() > 1) {
    // The file defines its cutters (APT): they are its table.
    if (given_table)
      throw InputError(given_source + ": " + path.source + " defines its own cutters (CUTTER/ at lines " +
                       std::to_string(path.defined_tools[0].line) + " and " + std::to_string(path.defined_tools[1].line) +
                       "): a tool table does not apply to it");
    if (tool) tool_for_path(tool, tool_source, path);  // must be the file's first cutter
    table.emplace();
    for (std::size_t k = 0; k < path.defined_tools.size(); ++k)
      table->push_back({static_cast<int>(k + 1), path.defined_tools[k].tool, ""});
    table_source = path.source;
  }
  if (!table) {
    int first = 0;
    for (const ToolpathPass& pass : path.passes) {
      if (pass.tool == 0) continue;
      if (first == 0) first = pass.tool;
      if (pass.tool != first)
        throw InputError(path.source + ": the program changes tools (T" + std::to_string(first) + " at line " +
                         std::to_string(change_line(path, first)) + ", T" + std::to_string(pass.tool) + " at line " +
                         std::to_string(change_line(path, pass.tool)) +
                         "): give a tool table (--tools) saying which cutter each tool number is");
    }
    return single_tool(Cutter(tool_for_path(tool, tool_source, path)), path);
  }

  PathTools out;
  std::map<int, const ToolSpec*> by_number;
  for (const ToolTableEntry& e : *table) by_number.emplace(e.number, &e.tool);
  std::map<int, int> index;  // tool number -> cutter
  auto cutter_for = [&](int number, int line) {
    const auto found = index.find(number);
    if (found != index.end()) return found->second;
    if (number == 0) {
      // Before any change: the single tool (or an APT file's CUTTER/).
      if (!tool && !path.tool)
        throw InputError(where(path, line) + ": a cut before the first tool change (T n M6): the file does not say "
                                             "which tool is in the spindle (load one first, or give --tool)");
      out.cutters.emplace_back(tool_for_path(tool, tool_source, path));
    } else {
      const auto entry = by_number.find(number);
      if (entry == by_number.end())
        throw InputError(table_source + ": no tool T" + std::to_string(number) + ", which " +
                         where(path, change_line(path, number)) + " loads");
      out.cutters.emplace_back(*entry->second);
    }
    out.numbers.push_back(number);
    index[number] = static_cast<int>(out.cutters.size() - 1);
    return index[number];
  };
  for (const ToolpathPass& pass : path.passes) out.of_pass.push_back(cutter_for(pass.tool, pass.points.front().line));
  for (const RapidMove& rapid : path.rapids)
    out.of_rapid.push_back(rapid.tool == 0 && !index.count(0) ? out.of_pass.front() : cutter_for(rapid.tool, rapid.line));
  return out;
}

}  // namespace furrow
