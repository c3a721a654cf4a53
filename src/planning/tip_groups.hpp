#pragma once
// Visiting order for points measured with different tips of an indexable
// head (docs/cmm.md "Indexable heads"): changing the tip costs far more
// than travel (the probe rises to the clearance plane, the head turns and
// settles), so the order first makes the fewest tip changes - one run of
// points per tip, each tip used once - and then keeps the travel short
// within each run with the ordinary tour (tour.hpp).
//
// Runs follow the order in which their tips first appear in `group`; each
// run is the open tour of its points, reversed when that puts its first
// point nearer the previous run's last one. The result's lengths are of
// the whole order (path_length over all positions, runs joined);
// nearest_neighbour_length adds the runs' yardsticks and the same joins;
// passes add up; converged is that of every run.
//
// Deterministic. Throws std::invalid_argument as plan_tour does, or when
// `group` has another size than `positions`.
#include <Eigen/Core>
#include <vector>

#include "planning/tour.hpp"

namespace furrow {

TourResult grouped_tour(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& group,
                        const TourOptions& options = {});

// Number of group changes between consecutive points of `order`.
int group_changes(const std::vector<int>& group, const std::vector<int>& order);

}  // namespace furrow
