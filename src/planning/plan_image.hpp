#pragma once
// plan.png: the plan seen from above (looking down -z, the way a vertical
// stylus comes in): every face's regions filled by curvature class (convex
// orange, concave blue, saddle green, planar sand; outside every region
// grey), region borders, the tour through the points in execution order
// (dark blue where the probe goes straight, light blue where it goes over
// the clearance plane), the points (black), points that were moved (orange
// ring), placed on a predicted gouge site (magenta square) and dropped (red
// cross), the first point (green) and the last (red).
// Surfaces overlapping in the view are painted bottom to top.
//
// PNG bytes from render/png.hpp; deterministic for the same plan.
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

std::vector<unsigned char> plan_image_png(const Part& part, const RegionMap& map, const PlanResult& result);

}  // namespace furrow
