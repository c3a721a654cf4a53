#include "partition/region_image.hpp"

#include <stdexcept>

#include "partition/region_paint.hpp"
#include "render/part_views.hpp"

namespace furrow {

std::vector<unsigned char> region_image_png(const Part& part, const PartitionResult& result) {
  const std::size_t n = part.faces.size();
  if (result.cells.size() != n || result.map.faces.size() != n)
    throw std::logic_error("region image: the partition does not belong to the part");
  std::vector<LegendEntry> legend = class_legend(result.map);
  int degenerate = 0;
  for (const RegionFace& f : result.map.faces) degenerate += f.degenerate_cells;
  if (degenerate > 0) legend.push_back({{110, 110, 110}, "degenerate"});
  const std::string title = "Curvature regions: " + std::to_string(result.map.regions.size()) + " regions on " +
                            std::to_string(n) + (n == 1 ? " face" : " faces");
  return part_views_png(
      draw_part_views(title, part, partition_cells_painter(result), legend, region_labels(result.map)));
}

}  // namespace furrow
