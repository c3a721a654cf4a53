#pragma once
// The report's region map: the curvature partition (regions.json) seen from
// above (x, y in mm, looking down -z), each region filled with its class
// colour (colour_scale.hpp: the partition's own colours), region borders in
// black and every region's id ("R3") at its interior point, with a legend
// of the classes present. Surfaces overlapping in the view are painted
// bottom to top, so what a vertical probe would see is on top.
//
// Drawn from the map's data (region_at, border loops), not from the
// partition's cell arrays, so `furrow report` can draw it from the files.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// Precondition: `map` belongs to `part` (RegionMap::check_belongs_to).
// Deterministic PNG bytes.
std::vector<unsigned char> region_map_png(const std::string& title, const Part& part, const RegionMap& map);

}  // namespace furrow
