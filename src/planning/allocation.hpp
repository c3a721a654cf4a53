#pragma once
// How many probe points each region gets (docs/cmm.md "Allocation").
//
// The rule, for a budget T (from --points, or --density in points per cm^2
// times the sampled area of the regions / 100):
//
//   weight    w_r = A_r * (1 + c_k * s_r * sqrt(A_r)) * (1 + c_e * e_r / e_mean)
//   floor     m_r = min_per_region + g_r
//   count     n_r = max(m_r, lambda * w_r) rounded, lambda such that sum n_r = T
//
// A_r is the region's area [mm^2]; s_r its curvature spread (area-weighted
// standard deviation of the principal curvatures, 1/mm), so s_r * sqrt(A_r)
// is how much the surface's bending changes across the region (a sphere cap
// or a plane: 0, needs only its share by area; a saddle band whose bending
// varies needs more points to capture its form); e_r is the region's mean
// predicted |error| and e_mean the area-weighted mean over all regions (only
// with a prediction: a region at the average risk gets twice the points of a
// riskless one of the same size); g_r counts the gouge sites' points in the
// region, which come on top of the minimum coverage. c_k = c_e = 1 by
// default.
//
// lambda is found by water filling: regions whose proportional share falls
// below their floor get the floor and leave the pool; the rest of the budget
// is shared among the others in proportion to w_r, rounded by largest
// remainders (ties to the lower region index), so the counts add up to T
// exactly. When T is below the sum of the floors, every region gets its
// floor and the total exceeds T (reported). Regions that cannot hold a
// point at all (marked not samplable) get 0 and are left out of the pool.
#include <cstddef>
#include <vector>

namespace furrow {

struct RegionDemand {
  double area = 0;              // mm^2, > 0 for a samplable region
  double curvature_spread = 0;  // 1/mm
  double mean_risk = 0;         // mm (0 without a prediction)
  int gouge_points = 0;         // reserved for gouge sites in the region
  bool samplable = true;
};

struct AllocationWeights {
  double curvature = 1;  // c_k
  double risk = 1;       // c_e (ignored when every mean_risk is 0)
};

struct Allocation {
  std::vector<int> counts;    // per region, same order as the demands
  std::vector<double> weights;
  std::vector<bool> at_floor;  // the region got its floor, not a proportional share
  long total = 0;
  long budget = 0;
  bool floors_exceed_budget = false;
};

double allocation_weight(const RegionDemand& demand, double mean_risk_all, const AllocationWeights& w);

// Throws std::invalid_argument for a negative budget or floor, or a
// non-finite demand.
Allocation allocate_points(const std::vector<RegionDemand>& demands, long budget, int min_per_region,
                           const AllocationWeights& weights = {});

}  // namespace furrow
