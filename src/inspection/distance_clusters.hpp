#pragma once
// Single-linkage clusters of points: two points belong to the same cluster
// when a chain of points, each within `distance` of the next, joins them.
// Used to group predicted local-gouge contact points into sites and measured
// overcuts into unexplained clusters (gouge_confirmation.hpp).
//
// Neighbours come from the exact double-precision k-d tree of
// geometry/point_search.hpp, so the result depends on the points only. Deterministic: members in increasing index order, clusters
// ordered by their smallest member.
#include <Eigen/Core>
#include <vector>

namespace furrow {

// Indices into `points` per cluster. `distance` [mm] must be >= 0 (0: only
// coincident points join).
std::vector<std::vector<std::size_t>> distance_clusters(const std::vector<Eigen::Vector3d>& points,
                                                        double distance);

}  // namespace furrow
