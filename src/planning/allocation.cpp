#include "planning/allocation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace furrow {

double allocation_weight(const RegionDemand& d, double mean_risk_all, const AllocationWeights& w) {
  double weight = d.area * (1 + w.curvature * d.curvature_spread * std::sqrt(d.area));
  if (mean_risk_all > 0) weight *= 1 + w.risk * d.mean_risk / mean_risk_all;
  return weight;
}

Allocation allocate_points(const std::vector<RegionDemand>& demands, long budget, int min_per_region,
                           const AllocationWeights& weights) {
  if (budget < 0 || min_per_region < 0) throw std::invalid_argument("allocate_points: negative budget or floor");
  const std::size_t n = demands.size();
  double area_all = 0, risk_all = 0;
  for (const RegionDemand& d : demands) {
    if (!std::isfinite(d.area) || d.area < 0 || !std::isfinite(d.curvature_spread) || d.curvature_spread < 0 ||
        !std::isfinite(d.mean_risk) || d.mean_risk < 0 || d.gouge_points < 0)
      throw std::invalid_argument("allocate_points: demands must be finite and non-negative");
    if (!d.samplable) continue;
    area_all += d.area;
    risk_all += d.area * d.mean_risk;
  }
  const double mean_risk_all = area_all > 0 ? risk_all / area_all : 0;

  Allocation a;
  a.budget = budget;
  a.counts.assign(n, 0);
  a.weights.assign(n, 0);
  a.at_floor.assign(n, false);
  std::vector<long> floor(n, 0);
  long floors = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (!demands[r].samplable) continue;
    a.weights[r] = allocation_weight(demands[r], mean_risk_all, weights);
    floor[r] = static_cast<long>(min_per_region) + demands[r].gouge_points;
    floors += floor[r];
  }
  if (floors >= budget) {
    for (std::size_t r = 0; r < n; ++r) {
      a.counts[r] = static_cast<int>(floor[r]);
      a.at_floor[r] = demands[r].samplable;
    }
    a.total = floors;
    a.floors_exceed_budget = floors > budget;
    return a;
  }
  // Water filling: pin the regions whose share is below their floor.
  std::vector<bool> pinned(n, false);
  for (std::size_t r = 0; r < n; ++r) pinned[r] = !demands[r].samplable;
  std::vector<double> share(n, 0);
  for (;;) {
    long pool = budget;
    double weight_sum = 0;
    for (std::size_t r = 0; r < n; ++r) {
      if (pinned[r]) pool -= floor[r];
      else weight_sum += a.weights[r];
    }
    bool changed = false;
    for (std::size_t r = 0; r < n; ++r) {
      if (pinned[r]) continue;
      share[r] = weight_sum > 0 ? pool * a.weights[r] / weight_sum : 0;
      if (share[r] < floor[r]) {
        pinned[r] = true;
        changed = true;
      }
    }
    if (!changed) break;
  }
  // Largest remainders over the free regions.
  long assigned = 0;
  std::vector<std::size_t> free;
  for (std::size_t r = 0; r < n; ++r) {
    if (pinned[r]) {
      a.counts[r] = static_cast<int>(floor[r]);
      a.at_floor[r] = demands[r].samplable;
    } else {
      a.counts[r] = static_cast<int>(std::floor(share[r]));
      free.push_back(r);
    }
    assigned += a.counts[r];
  }
  std::stable_sort(free.begin(), free.end(), [&](std::size_t x, std::size_t y) {
    return share[x] - std::floor(share[x]) > share[y] - std::floor(share[y]);
  });
  for (std::size_t k = 0; assigned < budget && k < free.size(); ++k, ++assigned) ++a.counts[free[k]];
  a.total = assigned;
  return a;
}

}  // namespace furrow
