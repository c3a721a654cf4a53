#pragma once
// Which regions of a face touch, and along how long a border [mm].
//
// Two regions are neighbours when a cell of one shares an edge with a cell of
// the other (corners do not count, matching the 4-connectivity of regions).
// The length of a shared cell edge is the mean of the two cells' side lengths
// across it (|Sv| dv for an edge of constant u, |Su| du for constant v): a
// midpoint estimate of the border's length on the surface, good to O(h^2),
// which is all the merge rule ("the neighbour with the longest border") and
// the report need. Sums run in raster order, so results are deterministic.
#include <map>
#include <vector>

#include "partition/curvature_field.hpp"
#include "partition/region_labels.hpp"

namespace furrow {

// Per label: neighbour label -> shared border length [mm]. Cells without a
// region (trimmed, degenerate) border nobody.
// Precondition: labels and field have the same grid.
std::vector<std::map<int, double>> shared_borders(const RegionLabels& labels,
                                                  const CurvatureField& field);

}  // namespace furrow
