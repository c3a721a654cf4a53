// furrow predict PART [--tool T.json] --toolpath P --out prediction.json [--map errors.png]
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "stage/prediction_options.hpp"
#include "cli/terminal_progress.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/cutter/path_tools.hpp"
#include "io/machining/toolpath_file.hpp"
#include "partition/classification.hpp"
#include "partition/regions_file.hpp"
#include "stage/predict_stage.hpp"
#include "base/text_fields.hpp"

namespace furrow::cli {

namespace {

std::string um(double mm) { return fixed(mm * 1000, 2) + " um"; }

// Rapid gouges: each one, since a rapid into the part is a crash, not a
// tolerance question (docs/formats.md "prediction.json", `rapids`).
// "x, y, z" with 3 decimals, never "-0.000" (a coordinate a hair below zero).
std::string point3(const Eigen::Vector3d& v) {
  std::string out;
  for (int a = 0; a < 3; ++a) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v[a]);
    std::string s = buf;
    if (s == "-0.000") s = "0.000";
    out += (a ? ", " : "") + s;
  }
  return out;
}

void print_rapids(std::ostream& out, const Prediction& p) {
  const RapidsRecord& r = p.rapids;
  if (r.checked + r.unchecked == 0) return;
  out << "rapids: " << r.checked << " checked against the part" << (r.has_stock ? " and the stock" : "");
  if (r.unchecked) out << ", " << r.unchecked << " unchecked (not in the part frame: G28, G53, M6, unknown start)";
  out << "; rapid gouges: " << r.gouges.size() << "\n";
  for (const RapidGougeRecord& g : r.gouges) {
    char buf[200];
    if (g.kind == "part")
      std::snprintf(buf, sizeof buf, "  RAPID GOUGE line %d: cutter %.4f mm into the part at (", g.line, g.depth);
    else
      std::snprintf(buf, sizeof buf, "  RAPID GOUGE line %d: tip %.4f mm below the stock top at (", g.line, g.depth);
    out << buf << point3(g.at.xyz) << ")" << (g.kind == "part" ? " on " + g.at.face : std::string()) << "\n";
  }
}

void print_summary(std::ostream& out, const Prediction& p) {
  const PredictionSummary& s = p.summary;
  if (p.tools.empty()) {
    out << "tool " << p.tool.name << " (" << to_string(p.tool.type) << ", diameter " << p.tool.diameter
        << " mm), tolerance " << um(p.tolerance) << "\n";
  } else {
    out << "tools (the program changes tools), tolerance " << um(p.tolerance) << ":\n";
    for (std::size_t k = 0; k < p.tools.size(); ++k) {
      const ToolSpec& t = p.tools[k].tool;
      const auto passes = std::count(p.pass_tools.begin(), p.pass_tools.end(), static_cast<int>(k));
      out << "  T" << p.tools[k].number << " " << t.name << " (" << to_string(t.type) << ", diameter " << t.diameter
          << " mm): " << passes << (passes == 1 ? " pass" : " passes") << "\n";
    }
  }
  out << "path: " << s.path_points << " points, " << s.steps << " moves (" << s.steps_evaluated << " evaluated";
  if (s.points_in_air) out << ", " << s.points_in_air << " points in the air";
  if (s.points_without_contact) out << ", " << s.points_without_contact << " points without contact";
  out << ")\n";
  if (s.points_below_surface)
    out << "  " << s.points_below_surface << " tips below the cutter-location surface (lowest " << um(s.lowest_gap)
        << ")\n";
  out << "along the passes (per step): " << describe_step_errors(s) << "\n";
  out << "z-map: " << p.zmap.nx << " x " << p.zmap.ny << " nodes at " << p.zmap.resolution << " mm, "
      << p.zmap.moves << " moves\n";
  auto extreme = [&](const char* what, const ErrorAt& e) {
    out << what;
    if (!e.found) {
      out << " none (nothing reached)\n";
      return;
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, " %s at (%.3f, %.3f, %.3f) on %s\n", um(e.error).c_str(), e.at.xyz.x(), e.at.xyz.y(),
                  e.at.xyz.z(), e.at.face.c_str());
    out << buf;
  };
  extreme("max undercut:", s.max_undercut);
  extreme("max overcut: ", s.max_overcut);
  out << "between passes (" << p.scallops.size() << " pass pairs): cusp " << um(s.max_cusp)
      << ", ridge with the furrows along the passes " << um(s.max_scallop) << "\n";
  out << "gouge sites (overcut beyond " << um(p.gouge_threshold) << "): " << s.gouge_sites << "\n";
  std::vector<const GougeSiteRecord*> deepest;
  for (const GougeSiteRecord& g : p.gouge_sites) deepest.push_back(&g);
  std::stable_sort(deepest.begin(), deepest.end(),
                   [](const GougeSiteRecord* a, const GougeSiteRecord* b) { return a->depth > b->depth; });
  if (deepest.size() > 10) deepest.resize(10);
  for (const GougeSiteRecord* site : deepest) {
    const GougeSiteRecord& g = *site;
    char buf[200];
    std::snprintf(buf, sizeof buf, "  #%d on %s: depth %s, area %.3f mm^2, deepest at (%.3f, %.3f, %.3f)\n", g.id,
                  g.face.c_str(), um(g.depth).c_str(), g.area, g.deepest.xyz.x(), g.deepest.xyz.y(), g.deepest.xyz.z());
    out << buf;
  }
  if (p.gouge_sites.size() > deepest.size())
    out << "  ... and " << p.gouge_sites.size() - deepest.size() << " shallower sites (all in the prediction file)\n";
  out << "contact points with local gouging: " << s.local_gouge_points << "\n";
  print_rapids(out, p);
  if (p.has_regions) {
    out << "by region (" << p.regions_file << "):\n";
    for (const RegionErrorRecord& r : p.regions) {
      char buf[200];
      if (r.reached == 0) {
        std::snprintf(buf, sizeof buf, "  region %d (%s, %s): not reached\n", r.region, r.curvature_class.c_str(),
                      r.face.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "  region %d (%s, %s): mean %s, max undercut %s, max overcut %s\n", r.region,
                      r.curvature_class.c_str(), r.face.c_str(), um(r.mean).c_str(), um(r.max_undercut.error).c_str(),
                      um(r.max_overcut.error).c_str());
      }
      out << buf;
    }
  }
}

int run_predict(Args& args) {
  const auto tool_path = args.option("tool");
  const auto table_path = args.option("tools");
  const std::string toolpath_path = args.required_option("toolpath");
  const std::string out_path = args.required_option("out");
  const auto map_path = args.option("map");
  const auto regions = args.option("regions");
  PathPredictionOptions options;
  read_option_flags(args, prediction_option_table(), options);
  if (!(options.gouge_threshold > 0)) options.gouge_threshold = 2 * options.tolerance;
  const double scale_um = args.positive_or("map-scale", 2000 * options.tolerance);
  ToolpathReadOptions read_options;
  read_options.units = args.option_or("units", "mm");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  // Only APT CL data names its cutter (CUTTER/): any other path needs --tool,
  // said before any file is read.
  const std::string path_ext = lower_extension(toolpath_path);
  if (!tool_path && !table_path && path_ext != ".cl" && path_ext != ".apt" && path_ext != ".cls")
    args.fail("--tool or --tools is required (only an APT CL path, .cl .apt .cls, names its own cutter with CUTTER/)");
  if (table_path && lower_extension(*table_path) != ".json")
    args.fail("--tools " + *table_path + ": expected a tool table (.json)");
  if (lower_extension(out_path) != ".json") args.fail("--out " + out_path + ": expected a .json file name");
  if (map_path && lower_extension(*map_path) != ".png") args.fail("--map " + *map_path + ": expected a .png file name");
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  if (tool_path) outputs.add_input(*tool_path, "tool");
  std::optional<std::vector<ToolTableEntry>> table;
  if (table_path) {
    outputs.add_input(*table_path, "tool table");
    table = read_tool_table(*table_path);
    for (const ToolTableEntry& e : *table)
      if (!e.file.empty()) outputs.add_input(e.file, "tool");
  }
  outputs.add_input(toolpath_path, "tool path");
  if (regions) outputs.add_input(*regions, "regions");
  outputs.will_write(out_path);
  if (map_path) outputs.will_write(*map_path);

  const Part part = read_part(part_path);
  std::optional<RegionMap> region_map;
  if (regions) {
    region_map = read_regions(*regions);
    region_map->check_belongs_to(part, *regions, part_path);
  }
  const Toolpath path = read_toolpath(toolpath_path, read_options);
  // An APT path names its cutter (CUTTER/): it is the tool when --tool is
  // not given, and a --tool that contradicts it is refused. A program that
  // changes tools takes them from the table.
  const PathTools tools =
      tools_for_path(path, tool_path ? std::optional<ToolSpec>(read_tool_file(*tool_path)) : std::nullopt,
                     tool_path.value_or(""), table, table_path.value_or(""));
  TerminalProgress progress;
  const PredictedPath predicted = naming_inputs(part_path + " with " + toolpath_path, [&] {
    return predict_stage(part, tools, path, options, {part_path, toolpath_path, regions.value_or("")},
                         region_map ? &*region_map : nullptr,
                         [&](const std::string& stage, std::size_t done, std::size_t total) {
                           progress.update(stage, done, total);
                         });
  });
  progress.finish();
  if (map_path) outputs.file(*map_path, prediction_map_png(part, predicted, options, scale_um / 1000));
  outputs.file(out_path, predicted.json);
  outputs.publish(out_path);
  print_summary(std::cout, predicted.record);
  std::cout << "wrote " << out_path << (map_path ? " and " + *map_path : std::string()) << "\n";
  // A rapid into the part or the stock is a crash: it fails like a gouge
  // (`furrow gouge`); cutting moves' gouge sites leave the exit code alone.
  return predicted.record.rapids.gouges.empty() ? kExitOk : kExitFail;
}

std::string prediction_options_help() { return option_help_lines(describe(prediction_option_table())); }

}  // namespace

const Command kPredictCommand = {
    "predict", "machining error of a tool path: per step, z-map error map, scallops, gouges",
    "usage: furrow predict PART [--tool TOOL.json] [--tools TABLE.json] --toolpath PATH\n"
    "                      --out PREDICTION.json\n"
    "                      [--map ERRORS.png] [--regions REGIONS.json] [--tolerance MM]\n"
    "                      [--gouge-threshold MM]\n"
    "                      [--resolution MM] [--cell MM] [--map-scale UM] [--units mm|inch]\n"
    "                      [--stock XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX]\n"
    "\n"
    "Predicts the error a 3-axis finishing path leaves on PART (sign: + material\n"
    "left, - overcut), from the swept cutter geometry itself:\n"
    "  - per move, exactly, along the design curve between its two contact points\n"
    "    (largest undercut and overcut and where they are); a move whose search\n"
    "    stops at its iteration cap is counted and marked as not converged;\n"
    "  - over the whole part, by a z-map of every move: an error map per face,\n"
    "    the ridge between adjacent passes, and gouge sites (connected areas of\n"
    "    overcut beyond the threshold) with depth, area and extent;\n"
    "  - between adjacent passes, the cusp of the two passes' cutters alone, the\n"
    "    figure a side step is chosen for, apart from the furrows along them;\n"
    "  - contact points where the cutter is more curved than the part (local\n"
    "    gouges, in every tangent direction);\n"
    "  - rapids (G0, APT RAPID): the cutter swept along each one must stay clear\n"
    "    of the part (and, with --stock, above the stock top); one that does not\n"
    "    is a rapid gouge, with its line and deepest point, and the exit code is 1.\n"
    "    G28/G53 and rapids from an unknown position are counted as unchecked.\n"
    "PATH is G-code or APT CL data (.cl .apt .cls) (tool tips; mapped back to\n"
    "contact points on PART) or CSV\n"
    "(x,y,z tips, or x,y,z,nx,ny,nz contact points, optionally with face,u,v).\n"
    "The prediction (docs/formats.md \"prediction.json\") stores the error per\n"
    "face on a (u,v) grid of cells for later stages.\n"
    "\n"
    "  --tool FILE           tool JSON (ball, flat or bull); required unless PATH is\n"
    "                        APT with a CUTTER/, which it must then match, or --tools\n"
    "                        is given\n"
    "  --tools FILE          tool table for a program that changes tools (T n M6):\n"
    "                        {\"T1\": tool or tool file, ...}; each pass is predicted\n"
    "                        with the tool loaded when it is cut (--tool: the one in\n"
    "                        the spindle before the first change)\n"
    "  --toolpath FILE       tool path, G-code, APT CL or CSV (required)\n"
    "  --out FILE            prediction to write (.json, required)\n"
    "  --map FILE            also draw the error map per face (.png, colour scale in um),\n"
    "                        with the largest furrow along a pass (F), cusp (C) and\n"
    "                        ridge (R) between passes marked and given under it\n"
    "  --regions FILE        regions.json of furrow partition for PART: error summary\n"
    "                        (mean, largest undercut and overcut) per region\n"
    "  --map-scale UM        colour saturation of the PNG in um (default 2 x tolerance)\n"
    "  --units U             units of CSV paths and of G-code before G20/G21 (default mm)\n"
    "\n"
    "Prediction options (a job file's \"prediction\" members, docs/options.md):\n",
    run_predict, prediction_options_help};

}  // namespace furrow::cli
