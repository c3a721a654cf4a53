#pragma once
// Which face the part rests on in the next setup (docs/cmm.md "Setups").
//
// Greedy: each further setup takes the stable planar face (part_setup.hpp)
// on which the probe reaches the most area of the regions the earlier
// setups left short of their minimum. Greedy because the exact choice of
// k faces out of m is a maximum-coverage problem (NP-hard in general), and
// because it is how a programmer works: plan the first setup, then turn
// the part so that the most of what is left faces the probe; its area is
// at least (1 - 1/e) of the best k setups' for the estimate it maximises.
//
// The estimate, per candidate: the part moved into that setup, and for each
// region still short, its deepest point (the region's interior point, from
// the partition) checked with the setup's probe - every qualified tip, or
// with --tips auto every orientation of the head's grid - by the planner's
// own access checks, the fixture plane included. The region's whole area
// counts when that point is reachable. Only the chosen setup is then
// planned in full, so a setup costs one plan plus these checks, not one plan
// per candidate.
//
// Deterministic: candidates in resting_candidates() order; ties keep the first.
#include <vector>

#include "planning/part_setup.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

struct SetupScore {
  RestingFace face;
  double reachable_area = 0;  // of the regions still short [mm^2]
  int reachable_regions = 0;
};

// The area of the regions with `wanted[id]` whose interior point the probe of
// `options` reaches with the part moved into `setup` (`options.access.fixture_z`
// is set from the setup here).
SetupScore score_setup(const Part& part, const RegionMap& map, const PlannerOptions& options,
                       const RestingFace& face, const std::vector<char>& wanted);

// The best of the stable planar faces not in `used`, or nullopt when none
// reaches any wanted region. `scores` (if not null) gets every candidate's score.
std::optional<SetupScore> best_next_setup(const Part& part, const RegionMap& map, const PlannerOptions& options,
                                          const std::vector<char>& wanted, const std::vector<int>& used,
                                          std::vector<SetupScore>* scores = nullptr);

}  // namespace furrow
