#pragma once
// coverage.png: what a plan measures, on the part in the four views of
// plan.png (render/part_views.hpp): every region filled by its coverage
// state (planning/plan_coverage.hpp) - covered green, reachable but not
// planned amber, too narrow for the ball violet, out of the probe's reach
// red; outside every region grey - with the planned points, and the covered
// share of the area in the title. A CMM programmer sees at a glance which
// part of the surface the programs leave out and why (docs/cmm.md
// "Coverage").
//
// PNG bytes from render/png.hpp; deterministic for the same plan.
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"
#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "render/colour_scale.hpp"

namespace furrow {

// The colour of each state in the figure.
Rgb coverage_colour(CoverageState state);

// Precondition: `map` is the one the plan was made on (region ids index
// coverage.regions by RegionCoverage::region).
std::vector<unsigned char> coverage_image_png(const Part& part, const RegionMap& map, const PlanResult& result,
                                              const PlanCoverage& coverage);

}  // namespace furrow
