#pragma once
// The nearest-neighbour open path through a set of points: the start of the
// probe tour (tour.hpp), which local search then shortens.
//
// Rule: start at point 0; the next point is always the nearest one not yet
// visited, by squared Euclidean distance computed as dx*dx + dy*dy + dz*dz
// (in that order, in double precision); equal distances go to the smallest
// index. The result is exactly what the obvious O(n^2) scan gives, which is
// what the tests compare it with.
//
// Why not that scan: it is n^2 / 2 distance evaluations, 5e9 at 100,000
// points. Each step here is one query of a k-d tree of the unvisited points
// (unvisited_points.hpp): O(n log n) in all, for the same answer.
//
// The tour no longer starts from this path (greedy_path.hpp is shorter and
// leaves the local search less to do); it is kept as the yardstick the plan
// reports the tour against.
//
// Preconditions: finite coordinates (std::invalid_argument otherwise). Two
// points more than about 1e154 apart are infinitely far from each other
// (the squared distance overflows); such ties also go to the smallest index.
// Empty input: empty path.
#include <Eigen/Core>
#include <vector>

namespace furrow {

std::vector<int> nearest_neighbour_path(const std::vector<Eigen::Vector3d>& points);

}  // namespace furrow
