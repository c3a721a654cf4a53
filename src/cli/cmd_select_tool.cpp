// furrow select-tool PART --library tools.json [--points cc.csv | --grid N]
// [--out FILE]: the largest gouge-free tool of a library, per point and for
// the whole surface.
#include <unistd.h>

#include <iostream>

#include "cli/commands.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/gouge/tool_selection_report.hpp"

namespace furrow::cli {

namespace {

constexpr long kMaxGrid = 200;  // every site checks every tool, with interference

int run_select_tool(Args& args) {
  const std::string library_path = args.required_option("library");
  const auto points_path = args.option("points");
  const auto grid_option = args.integer("grid");
  const auto out_path = args.option("out");
  const double tolerance = args.non_negative_or("tolerance", GougeOptions().curvature_tolerance);
  const bool local_only = args.flag("local-only");
  const bool share_flag = args.flag("share-interference");
  const bool no_share = args.flag("no-share-interference");
  const std::string units = args.option_or("units", "mm");
  const double max_distance = args.positive_or("max-distance", PointSiteOptions().max_distance);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  if (points_path && grid_option) args.fail("give either --points or --grid, not both");
  if (share_flag && no_share) args.fail("give either --share-interference or --no-share-interference, not both");
  const long grid = grid_option.value_or(30);
  if (grid < 2 || grid > kMaxGrid)
    args.fail("--grid must be between 2 and " + std::to_string(kMaxGrid) + ", got " + std::to_string(grid));
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(library_path, "tool library");
  if (points_path) outputs.add_input(*points_path, "contact points");
  if (out_path) {
    outputs.will_write(*out_path);
  }

  const Part part = read_part(part_path);
  std::vector<Cutter> library;
  for (const ToolSpec& spec : read_tool_library(library_path)) library.emplace_back(spec);
  PointSiteOptions site_options;
  site_options.max_distance = max_distance;
  const std::vector<ContactSite> sites = load_contact_sites(
      part, points_path.value_or(""), units, static_cast<int>(grid), site_options);

  ToolSelectionOptions options;
  options.scan.gouge.curvature_tolerance = tolerance;
  options.check_interference = !local_only;
  options.share_interference = !no_share;
  const bool show_progress = ::isatty(2) && sites.size() * library.size() > 20000;
  const auto progress = [&](std::size_t done, std::size_t total) {
    if (show_progress) std::cerr << "\rselect-tool: " << (100 * done / total) << "%" << std::flush;
  };
  const ToolSelection selection = select_tools(part, library, sites, options, progress);
  if (show_progress) std::cerr << "\n";

  if (out_path) {
    const SiteSource source{points_path ? 0 : static_cast<int>(grid), points_path.value_or("")};
    outputs.file(*out_path, tool_selection_json(part, part_path, library_path, selection, source, options));
    outputs.publish();
  }
  std::cout << tool_selection_text(part, part_path, selection);
  if (out_path) std::cout << "  wrote " << *out_path << "\n";
  return selection.whole_surface >= 0 ? kExitOk : kExitFail;
}

}  // namespace

const Command kSelectToolCommand = {
    "select-tool", "largest gouge-free tool of a library, per point and for the surface",
    "usage: furrow select-tool PART --library tools.json [--points cc.csv | --grid N]\n"
    "                          [--out FILE] [--tolerance K] [--local-only]\n"
    "                          [--no-share-interference]\n"
    "                          [--units mm|inch] [--max-distance D]\n"
    "\n"
    "Checks every tool of the library (a JSON array of tools, docs/formats.md) at the\n"
    "contact points and reports per point the largest tool (largest radius, then\n"
    "largest corner radius) that does not gouge, and the largest tool that is\n"
    "gouge-free at every point. A tool gouges at a point when the part is more\n"
    "curved than the cutter in some tangent direction, or when the cutter located\n"
    "there cuts into the part elsewhere (a flat end mill in a narrow trough). Where\n"
    "even the smallest tool gouges, the curvature the design would need is given.\n"
    "\n"
    "  --library FILE    the tool library (required)\n"
    "  --points cc.csv   contact points x,y,z[,nx,ny,nz] (see furrow gouge)\n"
    "  --grid N          instead: N x N nodes per face (default 30, at most 200)\n"
    "  --out FILE        the selection as JSON (a summary is always printed)\n"
    "  --tolerance K     curvature excess that counts as a gouge, 1/mm (default 1e-6)\n"
    "  --local-only      skip the interference check away from the contact\n"
    "  --no-share-interference  search for every tool; by default a tool inside a\n"
    "                    clear tool (no wider flat bottom, no larger corner) is\n"
    "                    clear without its own interference search: several times\n"
    "                    faster, the same results (docs/tool_selection.md);\n"
    "                    --share-interference, the default, is accepted too\n"
    "  --units U         units of the --points file: mm (default) or inch\n"
    "  --max-distance D  how far a contact point may lie from the part, mm (default 0.01)\n"
    "\n"
    "Exit status 1 when no tool of the library is gouge-free everywhere.\n",
    run_select_tool};

}  // namespace furrow::cli
