#pragma once
// Regions merged across faces in the report (docs/report.md "Regions"): a
// fillet chain or a blend split over several faces is one surface to the
// reader, so next to the per-region table the report lists every region
// group of the regions file (partition/region_groups.hpp) that joins more
// than one region, with the deviations of all its points together.
//
// Only evaluated points enter the statistics, as for a region; a point
// counts as out of tolerance when it is evaluated and outside the zone.
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/comparison_document.hpp"
#include "partition/region_map.hpp"

namespace furrow {

struct MergedSurface {
  const RegionGroup* group = nullptr;  // into the map given
  DeviationStatistics deviations;
  std::size_t out_of_tolerance = 0;
};

// Groups of more than one region, in group order; empty without a map.
std::vector<MergedSurface> merged_surfaces(const ComparisonDocument& doc, const RegionMap* map);

}  // namespace furrow
