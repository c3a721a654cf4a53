#pragma once
// The greedy-edge open path through a set of points: where the probe tour's
// local search starts (tour.hpp).
//
// Rule: the candidate edges (each point to each of its candidate neighbours,
// `neighbours[i]`) are taken shortest first (ties: smaller first index,
// then smaller second) and kept when both ends still have fewer than two
// kept edges and the edge closes no cycle. What is kept is a set of paths
// (fragments; a point with no kept edge is a fragment of one). The same
// rule then runs again on the fragments' ends alone, each with its 8
// nearest ends as candidates, round after round while a round still joins
// at least a tenth of the fragments. What is left is joined nearest-first:
// from the fragment end with the smallest index, walk to the fragment's
// other end, then on to the nearest end of an unwalked fragment
// (unvisited_points.hpp rule and ties), and so on.
//
// Why greedy and not nearest neighbour: nearest neighbour runs into dead
// ends and leaves long jumps back across the part, which the local search
// then has to undo with long reversals; greedy edges are short almost
// everywhere (Johnson & McGeoch: the better start for 2-opt and Or-opt,
// both in the final length and in the work). O(n k log(n k)) for the sort,
// then a few rounds of O(n) plus a sort of the ends' candidates.
//
// Preconditions: finite coordinates (std::invalid_argument otherwise);
// `neighbours` has one list per point with indices in range and not the
// point itself. Deterministic. Empty input: empty path.
#include <Eigen/Core>
#include <vector>

namespace furrow {

std::vector<int> greedy_path(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::vector<int>>& neighbours);

}  // namespace furrow
