#pragma once
// The order in which the CMM visits the points: a short open path through
// all of them (an open travelling-salesman path; the program starts at the
// first point and ends at the last).
//
// Construction: greedy edges (greedy_path.hpp), then local search to a
// 2-opt and Or-opt local optimum:
//   2-opt   replace edges (a, b), (c, d) by (a, c), (b, d), reversing b..c;
//   Or-opt  move a run of 1 to 3 consecutive points, possibly reversed, to
//           between two other consecutive points.
// Both look only at candidate moves whose new edge joins a point to one of
// its `neighbours` nearest points (k-d tree) or to a path end, the standard
// way to make them run in near-linear time (Johnson & McGeoch), and only at
// those where that new edge is shorter than what the move removes there: a
// 2-opt move's new edge at a shorter than the edge it replaces at a (else
// the move is left to its other end), an Or-opt move's new edge at the run
// shorter than the run's removal gain. The open path is handled as a closed
// tour through a dummy point at distance 0 from every point, cut at the
// dummy at the end, so the path's ends are free to move too.
//
// The nearest-neighbour path from point 0 (nearest_neighbour_path.hpp) is
// the yardstick the plan reports; the result is never longer (should the
// greedy start end longer, the search is run from it too and the shorter
// result kept).
//
// Why it is near-linear: the tour is an array with each point's position, a
// 2-opt move reverses the shorter side of the cycle in place, and an Or-opt
// move is done as two or three such reversals, so no move copies the tour.
// Points whose tour edges changed are queued for another look (don't-look
// bits); the search ends only after a full sweep in which no point finds an
// improving move, so the result is a true local optimum of those moves.
// 100,000 points take a few seconds (bench/bench_planning).
//
// Cost: Euclidean distance between the given positions (the probe centres
// at contact), the same for both directions. The moves the CMM actually
// makes (straight, or over the clearance plane) are longer where the straight
// segment is blocked; moves.hpp measures those.
//
// Deterministic: ties in the neighbour lists and in the construction are
// broken by index, and the search examines points in a fixed order (the
// neighbour lists are built in parallel, each list by itself). The work is
// capped; the result says whether the search converged.
#include <Eigen/Core>
#include <vector>

namespace furrow {

struct TourOptions {
  int neighbours = 10;       // candidate list length per point
  // Work cap in sweeps: at most max_passes * (n + 1) examinations of a point
  // (one examination tries every 2-opt and Or-opt move around the point).
  int max_passes = 1000;
  double min_gain = 1e-9;    // [mm] a move must shorten the path by more
  bool two_opt = true;
  bool or_opt = true;
};

struct TourResult {
  std::vector<int> order;          // point indices in visiting order
  double nearest_neighbour_length = 0;  // of the nearest-neighbour path, the yardstick [mm]
  double start_length = 0;         // of the path the search started from (greedy) [mm]
  double length = 0;               // after local search [mm]
  int passes = 0;                  // work done: examinations / (n + 1), rounded up
  bool converged = true;           // false when max_passes stopped the search
};

// Throws std::invalid_argument for invalid options (neighbours < 1,
// max_passes < 0, min_gain negative or NaN) or a non-finite position.
// Empty input: empty order; 1 or 2 points: the nearest-neighbour path,
// which is then optimal. Both moves off: the greedy path (or
// the nearest-neighbour one, when shorter).
TourResult plan_tour(const std::vector<Eigen::Vector3d>& positions, const TourOptions& options = {});

// Open path length of `order` through `positions`.
double path_length(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& order);

}  // namespace furrow
