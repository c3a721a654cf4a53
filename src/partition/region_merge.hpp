#pragma once
// Merging regions that are too small to matter into their neighbours.
//
// A metrologist plans and reports per region, so a speck of a few cells (a
// ripple, an inflection line crossing the tolerance band) must not become a
// region of its own. Rule : the smallest region below `min_area`
// joins the neighbour with which it shares the longest border
// (region_adjacency.hpp; ties go to the lower label), the merged region keeps
// the neighbour's class, and this repeats until every region is at least
// `min_area` or has no neighbour left on its face (a region isolated by
// trimmed or degenerate cells stays, whatever its size). Merging never
// crosses faces: it works on one face's labels.
//
// Areas are sums of cell areas (the area element, not cell counts), so the
// total area of the face is conserved; the merged labels are renumbered in
// raster order (region_labels.hpp) and remain deterministic.
#include "partition/curvature_field.hpp"
#include "partition/region_labels.hpp"

namespace furrow {

struct MergeReport {
  int initial_regions = 0;
  int merges = 0;           // regions absorbed by a neighbour
  int isolated_small = 0;   // regions below min_area left alone: no neighbour
};

// Preconditions: labels and field share the grid; min_area >= 0 [mm^2].
MergeReport merge_small_regions(RegionLabels& labels, const CurvatureField& field,
                                double min_area);

}  // namespace furrow
