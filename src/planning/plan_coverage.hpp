#pragma once
// Coverage of a probe plan: for every region and face of the part, how many
// points it needs, how many the plan holds, and — where it falls short — why
// (docs/cmm.md "Coverage").
//
// A region needs `min_per_region` points (the allocation floor): fewer and a
// fit over it cannot show a form error, and the comparison would say nothing
// about it. A plan with a region below its minimum is incomplete: `furrow
// plan` exits 1 unless told to accept it, and the regions travel with the
// plan (plan.json `uncovered_regions`) so that no verdict later says PASS
// over a region that was never measured.
//
// The reason names the cause in the planner's order: the region cannot hold
// a point at the border clearance nor, narrow, under the ball-contact rule
// (the largest ball that would fit named); fewer admissible points fit than were
// allocated; points were dropped because the probe cannot reach them (each
// access problem counted). Pure function of the plan result: no geometry.
#include <string>
#include <vector>

#include "planning/probe_planner.hpp"

namespace furrow {

struct RegionCoverage {
  int region = 0;
  int face = 0;
  int required = 0;   // the plan's minimum per region
  int allocated = 0;  // by the allocation rule
  int planned = 0;    // in the plan
  int dropped = 0;    // not reachable by the probe
  bool covered = true;
  std::string reason;  // why it is short, for people; "" when covered
};

struct FaceCoverage {
  int face = 0;
  int regions = 0, regions_covered = 0;
  int allocated = 0, planned = 0, dropped = 0;
};

struct PlanCoverage {
  std::vector<RegionCoverage> regions;  // in the plan result's region order
  std::vector<FaceCoverage> faces;      // faces holding at least one region, by face index
  int regions_covered = 0;
  long allocated = 0, planned = 0, dropped = 0;

  bool complete() const { return regions_covered == static_cast<int>(regions.size()); }
  std::vector<RegionCoverage> uncovered() const;
  // One line per uncovered region ("region 7 (face 3): 0 of 5 points: ..."),
  // at most `max_lines`, then "... and N more".
  std::string describe_uncovered(std::size_t max_lines = 10) const;
};

// `min_per_region` >= 0: the minimum the plan was made with.
PlanCoverage plan_coverage(const PlanResult& result, int min_per_region);

}  // namespace furrow
