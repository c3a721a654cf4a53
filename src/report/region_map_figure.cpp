#include "report/region_map_figure.hpp"

#include "partition/region_paint.hpp"
#include "render/part_views.hpp"

namespace furrow {

std::vector<unsigned char> region_map_png(const std::string& title, const Part& part, const RegionMap& map) {
  return part_views_png(draw_part_views(title, part, region_map_painter(map), class_legend(map), region_labels(map)));
}

}  // namespace furrow
