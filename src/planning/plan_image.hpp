#pragma once
// plan.png: the plan on the part in four views (top, front, right side,
// isometric; hidden surfaces removed, render/part_views.hpp): every face's
// regions filled by curvature class (convex orange, concave blue, saddle
// green, planar sand; outside every region grey) and shaded, region borders,
// the tour through the points in execution order (dark blue where the probe
// goes straight, light blue where it goes over the clearance plane), the
// points (black where the view sees them, a grey ring where the part hides
// them), points that were moved (orange ring), placed on a predicted gouge
// site (magenta square) and dropped (red cross), the first point (green)
// and the last (red). A vertical stylus sees what the top view shows; a
// probe head also reaches what the other views show.
//
// PNG bytes from render/png.hpp; deterministic for the same plan.
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"
#include "planning/probe_planner.hpp"
#include "render/part_views.hpp"

namespace furrow {

std::vector<unsigned char> plan_image_png(const Part& part, const RegionMap& map, const PlanResult& result);
// The same on the part's panels made beforehand (render/part_views.hpp
// part_view_panels of the part the plan was made on): the same bytes.
std::vector<unsigned char> plan_image_png(const RegionMap& map, const PlanResult& result, PartViewPanels views);

}  // namespace furrow
