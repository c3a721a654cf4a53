#pragma once
// "Which unvisited point is nearest to q?" over a fixed point set from which
// points are removed one by one: the query behind every nearest-neighbour
// walk of the probe tour (nearest_neighbour_path.hpp, greedy_path.hpp).
//
// Rule: squared Euclidean distance computed as dx*dx + dy*dy + dz*dz (in
// that order, in double precision); equal distances go to the smallest
// index. The answer is exactly that of a scan over the unvisited points.
//
// Why a tree of its own rather than PointSearch (geometry/point_search.hpp):
// that one is static. Here a k-d tree's nodes count their unvisited points
// and keep the smallest unvisited index, so a query descends only into boxes
// that still hold an unvisited point and may hold a nearer one (or an
// equally near one of smaller index), and removal is O(log n): a whole walk
// is O(n log n) on the point sets the planner makes, where the scan is
// O(n^2).
//
// Preconditions: finite coordinates (std::invalid_argument otherwise), fewer
// than INT_MAX points. Two points more than about 1e154 apart are infinitely
// far from each other (the squared distance overflows); such ties also go to
// the smallest index.
#include <Eigen/Core>

#include <limits>
#include <vector>

namespace furrow {

class UnvisitedPoints {
 public:
  static constexpr int kNone = std::numeric_limits<int>::max();

  explicit UnvisitedPoints(const std::vector<Eigen::Vector3d>& points);  // keeps a reference
  // Marks point i visited (again: no effect).
  void visit(int i);
  bool visited(int i) const { return visited_[static_cast<std::size_t>(i)]; }
  // The nearest unvisited point to q; kNone when every point is visited.
  int nearest(const Eigen::Vector3d& q);

 private:
  static constexpr int kLeafSize = 8;
  struct Node {
    double lo[3], hi[3];
    int begin, end;  // range of perm_
    int left = -1, right = -1, parent = -1;
    int alive = 0, min_alive = kNone;
  };
  int build(int begin, int end, int parent);
  double box_bound(const Node& node, const Eigen::Vector3d& q) const;
  void search(int v, const Eigen::Vector3d& q);

  const std::vector<Eigen::Vector3d>& p_;
  std::vector<int> perm_;
  std::vector<bool> visited_;
  std::vector<int> leaf_of_;
  std::vector<Node> nodes_;
  double best_d_ = 0;
  int best_i_ = kNone;
};

}  // namespace furrow
