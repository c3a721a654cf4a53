// furrow toolpath PART --tool T.json --tolerance E --scallop H [--direction u|v|plane:ANGLE] --out path.nc
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/terminal_progress.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "io/tool_file.hpp"
#include "stage/toolpath_stage.hpp"

namespace furrow::cli {

namespace {

StepRule parse_rule(const std::string& text, Args& args) {
  if (text == "exact") return StepRule::exact;
  if (text == "chord") return StepRule::chord;
  if (text == "circular-arc") return StepRule::circular_arc;
  args.fail("--rule \"" + text + "\": expected exact, chord or circular-arc");
}

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
  ContactPlanOptions options;
  options.forward.tolerance = args.positive_or("tolerance", 0.01);
  options.scallop = args.positive_or("scallop", 0.005);
  options.forward.max_step = args.non_negative_or("max-step", 0);
  const std::string direction_text = args.option_or("direction", "u");
  const std::string rule_text = args.option_or("rule", "exact");
  ToolpathWriteOptions write;
  write.clearance = args.positive_or("clearance", 5.0);
  write.feed = args.positive_or("feed", 1000);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  const PassDirectionSpec direction = parse_pass_direction(direction_text, "--direction");
  options.forward.rule = parse_rule(rule_text, args);
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
    return generate_toolpath(part, part_path, cutter, {direction, options, write}, [&](std::size_t d, std::size_t t) {
      progress.update("planning passes", d, t);
    });
  });
  progress.finish();
  outputs.file(contacts_path, path.contacts_csv);
  outputs.file(out_path, path.gcode);
  outputs.publish(out_path);
  print_summary(std::cout, path.plan, options);
  std::cout << "wrote " << out_path << " (tool tips) and " << contacts_path << " (contact points)\n";
  return kExitOk;
}

}  // namespace

const Command kToolpathCommand = {
    "toolpath", "plan a finishing path: contact points from a tolerance and a scallop height",
    "usage: furrow toolpath PART --tool TOOL.json --out PATH.nc [--tolerance MM] [--scallop MM]\n"
    "                       [--direction u|v|plane:ANGLE] [--rule exact|chord|circular-arc]\n"
    "                       [--max-step MM] [--contacts FILE.csv] [--clearance MM] [--feed MM/MIN]\n"
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
    "  --tolerance MM     largest error per step (default 0.01)\n"
    "  --scallop MM       target scallop height between passes (default 0.005)\n"
    "  --direction D      u or v: iso-parametric passes (v or u fixed); plane:ANGLE:\n"
    "                     vertical sections at ANGLE degrees from +x (default u)\n"
    "  --rule R           exact (default); chord: chord deviation = tolerance;\n"
    "                     circular-arc: osculating-circle estimate (for comparison)\n"
    "  --max-step MM      longest step (chord; default: no limit)\n"
    "  --contacts FILE    contact-point CSV (default: PATH with .csv)\n"
    "  --clearance MM     rapid height above the highest tip (default 5)\n"
    "  --feed MM/MIN      feed rate written on the first cut (default 1000)\n",
    run_toolpath};

}  // namespace furrow::cli
