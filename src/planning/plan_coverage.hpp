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
//
// By area, each region counts whole under one state: covered (its minimum
// planned); unreachable (no ball position measures it - too narrow - or
// points were dropped because the probe cannot reach them, which is what
// left it short); or reachable but not planned (the probe reaches what was
// tried, but too few admissible points fit or the allocation gave too few).
#include <string>
#include <utility>
#include <vector>

#include "planning/probe_planner.hpp"

namespace furrow {

// Why a region is short, by what an operator would change: the probe or the
// setup (unreachable) or the plan's parameters (reachable, not planned).
enum class CoverageState { covered, reachable_unplanned, unreachable_narrow, unreachable_access };
const char* to_string(CoverageState state);

struct RegionCoverage {
  int region = 0;
  int face = 0;
  double area = 0;  // [mm^2]
  CoverageState state = CoverageState::covered;
  // unreachable_access: the access problem that dropped most of its points.
  AccessProblem access = AccessProblem::none;
  int required = 0;   // the plan's minimum per region
  int allocated = 0;  // by the allocation rule
  int planned = 0;    // in the plan
  int dropped = 0;    // not reachable by the probe
  bool covered = true;
  std::string reason;  // why it is short, for people; "" when covered
  int setup = 0;       // combine_coverage: the setup this state comes from (1, 2, ...); 0 otherwise
};

struct FaceCoverage {
  int face = 0;
  int regions = 0, regions_covered = 0;
  int allocated = 0, planned = 0, dropped = 0;
};

// The part's area by coverage state [mm^2]; the unreachable area also by
// access problem (to_string(AccessProblem) as key), in a fixed order.
struct CoverageArea {
  double total = 0, covered = 0, reachable_unplanned = 0, unreachable_narrow = 0, unreachable_access = 0;
  std::vector<std::pair<AccessProblem, double>> by_access_problem;  // AccessProblem order, non-zero only
  double share_covered() const { return total > 0 ? covered / total : 0.0; }
};

struct PlanCoverage {
  std::vector<RegionCoverage> regions;  // in the plan result's region order
  std::vector<FaceCoverage> faces;      // faces holding at least one region, by face index
  int regions_covered = 0;
  long allocated = 0, planned = 0, dropped = 0;
  CoverageArea area;

  bool complete() const { return regions_covered == static_cast<int>(regions.size()); }
  std::vector<RegionCoverage> uncovered() const;
  // One line per uncovered region ("region 7 (face 3): 0 of 5 points: ..."),
  // at most `max_lines`, then "... and N more".
  std::string describe_uncovered(std::size_t max_lines = 10) const;
};

// `min_per_region` >= 0: the minimum the plan was made with. Regions the
// plan leaves to another setup (RegionPlanSummary::elsewhere) are not in it.
PlanCoverage plan_coverage(const PlanResult& result, int min_per_region);

// The part's coverage over several setups (docs/cmm.md "Setups"), setup 1
// first: each region with its state in the last setup that planned it (a
// later setup plans only what the earlier ones left short), `setup` set
// and, with more than one setup, its reason prefixed "setup k: "; areas
// from those states, so each region's area counts once; point counts
// summed over the setups.
PlanCoverage combine_coverage(const std::vector<PlanCoverage>& setups);

}  // namespace furrow
