#pragma once
// Painting a part by its curvature regions (render/part_views.hpp): the
// class colour of the region a surface point lies in (render/colour_scale.hpp,
// the colours every figure uses), keyed by the region's id so the figure
// draws the borders between regions; grey outside every region.
//
// Two sources, one look: a RegionMap (what regions.json holds; the report
// and the plan draw from it) and a PartitionResult's labelled cells (what
// `furrow partition` has in hand, exactly the cells it labelled).
#include <vector>

#include "partition/partition.hpp"
#include "partition/region_map.hpp"
#include "render/part_views.hpp"

namespace furrow {

// Precondition: `map` belongs to the part drawn (RegionMap::check_belongs_to).
// The painter refers to `map`, which must outlive it.
SurfacePainter region_map_painter(const RegionMap& map);
// Trimmed cells light grey, degenerate cells dark grey. Refers to `result`.
SurfacePainter partition_cells_painter(const PartitionResult& result);

// Legend entries of the classes that occur in `map`, in class order.
std::vector<LegendEntry> class_legend(const RegionMap& map);
// "R<id>" at every region's interior point, keyed by its id.
std::vector<ViewLabel> region_labels(const RegionMap& map);

}  // namespace furrow
