#pragma once
// The order in which the CMM visits the points: a short open path through
// all of them (an open travelling-salesman path; the program starts at the
// first point and ends at the last).
//
// Construction: nearest neighbour from point 0 (exact, O(n^2)), then local
// search to a 2-opt and Or-opt local optimum:
//   2-opt   replace edges (a, b), (c, d) by (a, c), (b, d), reversing b..c;
//   Or-opt  move a run of 1 to 3 consecutive points, possibly reversed, to
//           between two other consecutive points.
// Both look only at candidate moves whose new edge joins a point to one of
// its `neighbours` nearest points (k-d tree), the standard way to make them
// run in near-linear time (Johnson & McGeoch). The open path is handled as a
// closed tour through a dummy point at distance 0 from every point, cut at
// the dummy at the end, so the path's ends are free to move too.
//
// Cost: Euclidean distance between the given positions (the probe centres
// at contact), the same for both directions. The moves the CMM actually
// makes (straight, or over the clearance plane) are longer where the straight
// segment is blocked; moves.hpp measures those.
//
// Deterministic: ties in the neighbour lists are broken by index, and the
// search scans points in a fixed order. The number of improvement passes is
// capped; the result says whether the search converged.
#include <Eigen/Core>
#include <vector>

namespace furrow {

struct TourOptions {
  int neighbours = 10;       // candidate list length per point
  int max_passes = 1000;     // improvement sweeps over all points
  double min_gain = 1e-9;    // [mm] a move must shorten the path by more
  bool two_opt = true;
  bool or_opt = true;
};

struct TourResult {
  std::vector<int> order;          // point indices in visiting order
  double nearest_neighbour_length = 0;  // open path length after construction [mm]
  double length = 0;               // after local search [mm]
  int passes = 0;
  bool converged = true;           // false when max_passes stopped the search
};

// Throws std::invalid_argument for invalid options. Empty input: empty order.
TourResult plan_tour(const std::vector<Eigen::Vector3d>& positions, const TourOptions& options = {});

// Open path length of `order` through `positions`.
double path_length(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& order);

}  // namespace furrow
