#pragma once
// Which measured points the coarse alignment looks at.
//
// Why not every n-th point: CMM and scanner files come in scan order, and
// every n-th point of 1000 lines of 1000 points is one column of points on a
// line, which fixes no rotation about it. Why not every point: a blunder
// metres (or 1e39 mm) away drags centroids and principal axes off the part.
// Both subsets here are deterministic (the same points give the same
// indices) and refer to the caller's point indices.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace furrow {

// Indices of the finite points within `reach` of the points' coordinate-wise
// median, in index order. With `reach` the part's diagonal (times a margin),
// a point outside cannot lie on the part in any placement as long as at
// least half of the points do.
std::vector<std::size_t> points_near_the_bulk(const std::vector<Eigen::Vector3d>& points, double reach);

// At most `max` of the indices `from`, spread over space: the box of those
// points is cut into cubic cells sized so that about `max` cells hold
// points, the lowest index of each occupied cell is kept, and if more than
// `max` cells are occupied an even stride over them (in index order) is
// taken. Returns `from` itself when it has at most `max` entries.
std::vector<std::size_t> spread_subset(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<std::size_t>& from, std::size_t max);

}  // namespace furrow
