#pragma once
// The report's region map: the curvature partition (regions.json) on the
// part in four views (top, front, right side, isometric; hidden surfaces
// removed, render/part_views.hpp), each region filled with its class colour
// (the partition's own colours) and shaded, region borders in black, face
// edges in grey, every region's id ("R3") where its interior point is seen,
// and a legend of the classes present.
//
// Drawn from the map's data (region_at), not from the partition's cell
// arrays, so `furrow report` can draw it from the files.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// Precondition: `map` belongs to `part` (RegionMap::check_belongs_to).
// Deterministic PNG bytes.
std::vector<unsigned char> region_map_png(const std::string& title, const Part& part, const RegionMap& map);

}  // namespace furrow
