// furrow toolpath PART --tool T.json --tolerance E --scallop H [--direction u|v|plane:ANGLE] --out path.nc
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "cli/terminal_progress.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "stage/toolpath_options.hpp"
#include "stage/toolpath_stage.hpp"

namespace furrow::cli {

namespace {

void print_summary(std::ostream& out, const ContactPlan& plan, const ContactPlanOptions& o) {
  double shortest = INFINITY, longest = 0, total = 0;
  std::size_t steps = 0;
  for (const PlannedPass& p : plan.passes)
    for (std::size_t k = 1; k < p.points.size(); ++k) {
      const double len = (p.points[k].at.point - p.points[k - 1].at.point).norm();
      shortest = std::min(shortest, len), longest = std::max(longest, len), total += len;
      ++steps;
    }
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%zu passes, %zu contact points, %zu steps (%s rule, tolerance %.4g mm, scallop %.4g mm)\n",
                plan.passes.size(), plan.points, steps, to_string(o.forward.rule), o.forward.tolerance, o.scallop);
  out << "direction " << to_string(plan.direction) << ": " << buf;
  if (steps) {
    std::snprintf(buf, sizeof buf, "step length: shortest %.4f mm, mean %.4f mm, longest %.4f mm\n", shortest,
                  total / steps, longest);
    out << buf;
  }
  if (plan.capped_searches)
    out << "note: " << plan.capped_searches << " step searches stopped at their iteration cap\n";
}

int run_toolpath(Args& args) {
  const std::string tool_path = args.required_option("tool");
  const std::string out_path = args.required_option("out");
  const auto contacts_option = args.option("contacts");
  ToolpathGeneration generation;
  read_option_flags(args, toolpath_option_table(), generation);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  std::string contacts_path = contacts_option.value_or(
      (std::filesystem::path(out_path).parent_path() / std::filesystem::path(out_path).stem()).string() + ".csv");
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(tool_path, "tool");
  outputs.will_write(out_path);
  outputs.will_write(contacts_path);

  const Part part = read_part(part_path);
  const Cutter cutter(read_tool_file(tool_path));
  TerminalProgress progress;
  const GeneratedToolpath path = naming_inputs(part_path + " with " + tool_path, [&] {
    return generate_toolpath(part, part_path, cutter, generation, [&](std::size_t d, std::size_t t) {
      progress.update("planning passes", d, t);
    });
  });
  progress.finish();
  outputs.file(contacts_path, path.contacts_csv);
  outputs.file(out_path, path.gcode);
  outputs.publish(out_path);
  print_summary(std::cout, path.plan, generation.contacts);
  std::cout << "wrote " << out_path << " (tool tips) and " << contacts_path << " (contact points)\n";
  return kExitOk;
}

std::string toolpath_options_help() { return option_help_lines(describe(toolpath_option_table())); }

}  // namespace

const Command kToolpathCommand = {
    "toolpath", "plan a finishing path: contact points from a tolerance and a scallop height",
    "usage: furrow toolpath PART --tool TOOL.json --out PATH.nc [--contacts FILE.csv]\n"
    "                       [tool-path options]\n"
    "\n"
    "Plans a 3-axis finishing path over PART: passes side by side, each next pass\n"
    "placed from the previous one so that the scallop between them stays at the\n"
    "target height, and contact points along each pass so that every step's\n"
    "largest machining error, computed exactly from the swept cutter, equals the\n"
    "tolerance (the last step of a pass may be shorter). Writes the tool tips as\n"
    "G-code and the contact points (with normals, face and u,v) as CSV.\n"
    "\n"
    "  --tool FILE        tool JSON (ball, flat or bull; required)\n"
    "  --out FILE         G-code to write (required)\n"
    "  --contacts FILE    contact-point CSV (default: PATH with .csv)\n"
    "\n"
    "Tool-path options (a job file's \"toolpath\": {\"generate\": ...} members,\n"
    "docs/options.md):\n",
    run_toolpath, toolpath_options_help};

}  // namespace furrow::cli
