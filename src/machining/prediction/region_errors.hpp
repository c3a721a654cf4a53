#pragma once
// The error map (error_map.hpp) summarised per region of a partition: for
// every region, the mean error over its reached samples and its largest
// undercut and overcut with where they are.
//
// Regions come from the partition module, which machining does not depend
// on (docs/architecture.md "Module order"): the caller passes how to find a sample's
// region (RegionMap::region_at in `furrow predict`) and fills in the region
// classes. Extremes are the best samples, not refined.
#include <functional>
#include <optional>
#include <vector>

#include "machining/prediction/prediction.hpp"

namespace furrow {

using RegionLookup = std::function<std::optional<int>(int face, double u, double v)>;

// One record per region id 0..region_count-1 (regions without a reached
// sample have found == false extremes). Region lookups run in parallel
// (`lookup` must be safe to call concurrently); sums run in raster order.
std::vector<RegionErrorRecord> errors_by_region(const Part& part, const ErrorMap& map, std::size_t region_count,
                                                const RegionLookup& lookup);

}  // namespace furrow
