#pragma once
// Single-linkage clusters of points: two points belong to the same cluster
// when a chain of points, each within `distance` of the next, joins them.
// Used to group predicted local-gouge contact points into sites and measured
// overcuts into unexplained clusters (gouge_confirmation.hpp).
//
// Exact single linkage in double precision (distance <= `distance`
// joins), so the result depends on the points only: points are binned in
// cells of side distance / sqrt(3), whose members all join, and nearby
// cells join through their closest pairs; a scan's dense overcut clusters
// (tens of thousands of points within a few mm of each other) cost about
// one pair check per pair of cells. Deterministic: members in increasing
// index order, clusters ordered by their smallest member.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace furrow {

// Indices into `points` per cluster. `distance` [mm] must be >= 0 (0: only
// coincident points join).
std::vector<std::vector<std::size_t>> distance_clusters(const std::vector<Eigen::Vector3d>& points,
                                                        double distance);

}  // namespace furrow
