// furrow partition PART --out regions.json [--image regions.png]: split every
// face into convex / concave / saddle / planar regions.
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "stage/partition_options.hpp"
#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/output_set.hpp"
#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "partition/region_image.hpp"
#include "partition/regions_file.hpp"
#include "base/text_fields.hpp"

namespace furrow::cli {

namespace {


void print_summary(std::ostream& out, const std::string& path, const PartitionResult& result) {
  const RegionMap& map = result.map;
  char line[200];
  out << "partition of " << path << ": " << map.faces.size()
      << (map.faces.size() == 1 ? " face, " : " faces, ") << map.regions.size() << " regions\n";
  for (std::size_t f = 0; f < map.faces.size(); ++f) {
    const RegionFace& face = map.faces[f];
    std::snprintf(line, sizeof line,
                  "face %zu \"%s\": grid %dx%d, eps %.3g 1/mm (%s), min area %.4g mm^2, "
                  "area %.4f mm^2\n",
                  f, face.name.c_str(), face.nu, face.nv, face.eps,
                  face.eps_from_user ? "--eps" : "default", face.min_area, face.area);
    out << line;
    for (int id : face.regions) {
      const Region& r = map.regions[static_cast<std::size_t>(id)];
      std::snprintf(line, sizeof line, "  region %3d  %-8s %12.4f mm^2  %5.1f%%  H [%.4g, %.4g] 1/mm\n",
                    r.id, to_string(r.curvature_class), r.area,
                    face.area > 0 ? 100.0 * r.area / face.area : 0.0, r.H.min, r.H.max);
      out << line;
    }
  }
  // Regions merged across faces (docs/partition.md "Regions across faces").
  for (const RegionGroup& g : map.groups) {
    if (g.regions.size() < 2) continue;
    std::string ids;
    for (int id : g.regions) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    std::snprintf(line, sizeof line, "surface S%d  %-8s %12.4f mm^2 on %zu faces: regions ", g.id,
                  to_string(g.curvature_class), g.area, g.faces.size());
    out << line << ids << "\n";
  }
}

int run_partition(Args& args) {
  PartitionOptions options;
  read_option_flags(args, partition_option_table(), options);
  const std::string out_path = args.required_option("out");
  const auto image_path = args.option("image");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();

  check_partition_options(options, "furrow partition: --grid, --spacing");
  if (lower_extension(out_path) != ".json") args.fail("--out " + out_path + ": expected a .json file name");
  if (image_path && lower_extension(*image_path) != ".png")
    args.fail("--image " + *image_path + ": expected a .png file name");
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.will_write(out_path);
  if (image_path) outputs.will_write(*image_path);

  const Part part = read_part(part_path);
  const bool show_progress = ::isatty(2) && part.faces.size() > 1;
  const PartitionResult result = naming_inputs(part_path, [&] {
    return partition_part(part, options, [&](std::size_t done, std::size_t total) {
      if (show_progress) std::cerr << "\rpartition: face " << done << "/" << total << std::flush;
    });
  });
  if (show_progress) std::cerr << "\n";

  if (image_path) {
    const std::vector<unsigned char> png = region_image_png(part, result);
    outputs.file(*image_path, std::string(png.begin(), png.end()));
  }
  outputs.file(out_path, regions_to_json_text(result.map));
  outputs.publish(out_path);

  print_summary(std::cout, part_path, result);
  std::cout << "wrote " << out_path << (image_path ? " and " + *image_path : std::string()) << "\n";
  return kExitOk;
}

std::string partition_options_help() { return option_help_lines(describe(partition_option_table())); }

}  // namespace

const Command kPartitionCommand = {
    "partition", "split faces into convex/concave/saddle/planar regions",
    "usage: furrow partition PART --out REGIONS.json [--image REGIONS.png]\n"
    "                        [--grid NUxNV | --spacing MM] [--eps K] [--min-area MM2]\n"
    "\n"
    "Samples the curvature of every face of PART on a (u,v) grid, classifies each\n"
    "sample as convex, concave, saddle or planar (normal out of the material:\n"
    "convex bulges toward the tool), groups equal neighbours into regions, merges\n"
    "regions smaller than the minimum area into the neighbour sharing the longest\n"
    "border, groups regions of one class on faces that meet tangentially (a fillet\n"
    "chain is one surface) and writes the regions with their areas, curvature\n"
    "statistics, borders (uv and xyz) and groups to REGIONS.json (docs/formats.md,\n"
    "docs/partition.md).\n"
    "\n"
    "  --out FILE       regions file to write (.json, required)\n"
    "  --image FILE     also draw the regions on the part in four views (.png)\n"
    "\n"
    "Partition options (a job file's \"partition\" members, docs/options.md):\n",
    run_partition, partition_options_help};

}  // namespace furrow::cli
