#pragma once
// What a region is like, from its cells: area, class purity, extent,
// centroid, curvature statistics and a point deep inside it.
//
// Integrals use each cell's area (area element times du dv, midpoint rule),
// never cell counts, so areas converge quadratically with the grid and the
// regions of a face add up to the face's valid area. Sums run sequentially
// in raster order: deterministic to the bit.
//
// The interior point is the centre of the region's cell farthest (in cells,
// Euclidean; cv::distanceTransform) from any cell outside the region: where a
// label is drawn and where a first probe point is safely inside.
#include <vector>

#include "partition/curvature_field.hpp"
#include "partition/region_labels.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// One Region per label with id = label + first_id and face = face_index;
// fills area, absorbed_area, cells, merged_components, curvature_class,
// xyz_box (cell centres; callers extend it with border points), centroid,
// interior point and K/H/k1/k2 stats. Borders and neighbours are left empty.
// Preconditions: labels, cell_class and field share the grid.
std::vector<Region> region_statistics(const RegionLabels& labels,
                                      const std::vector<unsigned char>& cell_class,
                                      const CurvatureField& field, int face_index, int first_id);

}  // namespace furrow
