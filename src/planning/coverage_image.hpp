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
#include "render/part_views.hpp"

namespace furrow {

// The colour of each state in the figure.
Rgb coverage_colour(CoverageState state);

// Precondition: `map` is the one the plan was made on (region ids index
// coverage.regions by RegionCoverage::region).
std::vector<unsigned char> coverage_image_png(const Part& part, const RegionMap& map, const PlanResult& result,
                                              const PlanCoverage& coverage);
// The same on the part's panels made beforehand (render/part_views.hpp
// part_view_panels of the part the plan was made on): the same bytes.
std::vector<unsigned char> coverage_image_png(const RegionMap& map, const PlanResult& result,
                                              const PlanCoverage& coverage, PartViewPanels views);

// The colour of the regions covered in setup k (1, 2, ...).
Rgb setup_colour(int setup);

// The top-level coverage.png of a plan over several setups (docs/cmm.md
// "Setups"): the part as imported, each covered region in the colour of the
// setup that covers it (combine_coverage's `setup`), the others by state;
// `points` are every setup's points taken back to the part frame.
std::vector<unsigned char> setups_coverage_image_png(const Part& part, const RegionMap& map,
                                                     const PlanCoverage& combined,
                                                     const std::vector<Eigen::Vector3d>& points);
// The same on the part's panels made beforehand: the same bytes.
std::vector<unsigned char> setups_coverage_image_png(const RegionMap& map, const PlanCoverage& combined,
                                                     const std::vector<Eigen::Vector3d>& points,
                                                     PartViewPanels views);

}  // namespace furrow
