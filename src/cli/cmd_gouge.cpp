// furrow gouge PART --tool T.json [--points cc.csv | --grid N] --out gouge.json
// [--map gouge.png]: local gouge check of one tool at contact points.
#include <unistd.h>

#include <iostream>

#include "cli/commands.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/gouge/gouge_map.hpp"
#include "machining/gouge/gouge_report.hpp"

namespace furrow::cli {

namespace {

constexpr long kMaxGrid = 250;  // 62 500 points per face: the JSON lists every one

int run_gouge(Args& args) {
  const std::string tool_path = args.required_option("tool");
  const auto points_path = args.option("points");
  const auto grid_option = args.integer("grid");
  const std::string out_path = args.required_option("out");
  const auto map_path = args.option("map");
  const double tolerance = args.non_negative_or("tolerance", GougeOptions().curvature_tolerance);
  const std::string units = args.option_or("units", "mm");
  const double max_distance = args.positive_or("max-distance", PointSiteOptions().max_distance);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  if (points_path && grid_option) args.fail("give either --points or --grid, not both");
  const long grid = grid_option.value_or(50);
  if (grid < 2 || grid > kMaxGrid)
    args.fail("--grid must be between 2 and " + std::to_string(kMaxGrid) + ", got " + std::to_string(grid));
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(tool_path, "tool");
  if (points_path) outputs.add_input(*points_path, "contact points");
  outputs.will_write(out_path);
  if (map_path) outputs.will_write(*map_path);

  const Part part = read_part(part_path);
  const Cutter cutter(read_tool_file(tool_path));
  PointSiteOptions site_options;
  site_options.max_distance = max_distance;
  const std::vector<ContactSite> sites = load_contact_sites(
      part, points_path.value_or(""), units, static_cast<int>(grid), site_options);

  GougeScanOptions options;
  options.gouge.curvature_tolerance = tolerance;
  // Every point gets its exact largest excess (the margin where it is
  // negative); the quick path would give only a bound, and evaluating the
  // surface costs far more than the comparison anyway.
  options.gouge.quick_accept = false;
  const bool show_progress = ::isatty(2) && sites.size() > 50000;
  const auto progress = [&](std::size_t done, std::size_t total) {
    if (show_progress) std::cerr << "\rgouge: " << (100 * done / total) << "%" << std::flush;
  };
  const std::vector<GougePoint> points = scan_gouges(part, cutter, sites, options, progress);
  if (show_progress) std::cerr << "\n";

  const SiteSource source{points_path ? 0 : static_cast<int>(grid), points_path.value_or("")};
  if (map_path) outputs.file(*map_path, gouge_map_png(part, cutter, points, source.grid));
  outputs.file(out_path, gouge_report_json(part, part_path, cutter, points, source, options));
  outputs.publish(out_path);

  std::cout << gouge_summary_text(part, part_path, cutter, points);
  std::cout << "  wrote " << out_path << (map_path ? " and " + *map_path : std::string()) << "\n";
  const GougeSummary summary = summarize_gouges(part, points);
  return summary.gouge + summary.concave_crease > 0 ? kExitFail : kExitOk;
}

}  // namespace

const Command kGougeCommand = {
    "gouge", "local gouge check of a tool at contact points: directions and excess",
    "usage: furrow gouge PART --tool T.json [--points cc.csv | --grid N] --out gouge.json\n"
    "                    [--map gouge.png] [--tolerance K] [--units mm|inch] [--max-distance D]\n"
    "\n"
    "Checks whether the end mill of T.json (tool JSON, docs/formats.md) gouges PART\n"
    "locally at cutter-contact points: in every tangent direction the part's normal\n"
    "curvature is compared with the cutter's (ball, flat and bull-nose; at a border\n"
    "between faces each face over the directions pointing into it). Writes per point\n"
    "the position, normals, part k1/k2, cutter k_max/k_min, the tool tip, the gouging\n"
    "direction ranges (degrees from the cutter's max-curvature direction,\n"
    "counter-clockwise about the normal) and the largest curvature excess.\n"
    "\n"
    "  --tool T.json     the tool (required)\n"
    "  --points cc.csv   contact points x,y,z[,nx,ny,nz] (on the part, within\n"
    "                    --max-distance); n_z < 0 is an error (n_z = 0, a\n"
    "                    wall, is cut with the cutter's side)\n"
    "  --grid N          instead: N x N nodes per face, edges included (default 50,\n"
    "                    at most 250); points facing down are listed as unreachable\n"
    "  --out FILE        the gouge JSON (required)\n"
    "  --map FILE        a PNG map of gouge-prone areas over each face's uv domain\n"
    "  --tolerance K     curvature excess that counts as a gouge, 1/mm (default 1e-6;\n"
    "                    touching is not gouging)\n"
    "  --units U         units of the --points file: mm (default) or inch\n"
    "  --max-distance D  how far a contact point may lie from the part, mm (default 0.01)\n"
    "\n"
    "Exit status 1 when some point gouges (the outputs are written), 2 for bad input.\n",
    run_gouge};

}  // namespace furrow::cli
