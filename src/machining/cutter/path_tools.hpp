#pragma once
// Which cutter cuts each pass of a tool path, and which one travels each
// rapid: the tool changes of a G-code program (`T n M6`, Toolpath::
// tool_changes) resolved against a tool table (io/machining/tool_file.hpp), or the
// one tool of a program that does not change tools.
//
// Why a program that changes tools needs a table: the prediction of a pass
// cut with a 12 mm flat end mill, computed as if a 6 mm ball had cut it, is
// a prediction of a part nobody machines. So a program that loads two or
// more different tool numbers is refused without a table, naming the first
// two changes; and a table that lacks a number the program loads is
// refused, naming the line that loads it.
//
// The rules, in full:
// - With a table, every pass cut with a loaded tool n uses the table's
//   tool n. Passes before the first change (tool 0) use the single tool
//   (`--tool`) when one is given, and are refused otherwise (naming the
//   first such line): the file does not say what is in the spindle.
// - Without a table, every pass uses the single tool (required), or the
//   cutter an APT file defines (io/machining/apt_reader.hpp tool_for_path); the
//   program may load one tool number, any number of times.
// - An APT file that defines several cutters (CUTTER/ with another
//   geometry changes the tool, io/machining/apt_reader.hpp) is its own table: each
//   pass is cut with the cutter defined last before it. A tool table is
//   then refused, and a single tool, when given, must be the file's first
//   cutter (as for a file with one).
// - A rapid moves the tool loaded when it runs; a rapid before the first
//   change moves the first tool the program cuts with (posts load the first
//   tool before any motion, so this is the one in the spindle when a file
//   is run from the top).
#include <optional>
#include <string>
#include <vector>

#include "io/machining/tool_file.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/cutter.hpp"

namespace furrow {

struct PathTools {
  std::vector<Cutter> cutters;  // distinct tools, in order of first use (at least one)
  std::vector<int> numbers;     // tool number of each cutter; 0: the program's single tool
  std::vector<int> of_pass;     // index into cutters, per pass of the path
  std::vector<int> of_rapid;    // index into cutters, per rapid of the path

  bool changes_tools() const { return cutters.size() > 1; }
};

// Every pass and rapid with `cutter`.
PathTools single_tool(const Cutter& cutter, const Toolpath& path);

// The rules above. `tool` and `table` may each be absent; `tool_source` and
// `table_source` name them in messages. Throws InputError as described.
PathTools tools_for_path(const Toolpath& path, const std::optional<ToolSpec>& tool, const std::string& tool_source,
                         const std::optional<std::vector<ToolTableEntry>>& table, const std::string& table_source);

}  // namespace furrow
