#pragma once
// Exact nearest-neighbour and radius queries over a fixed set of 3D points,
// in double precision (a k-d tree; nanoflann stays inside point_search.cpp).
//
// Why double and why one owner: the search used to store float copies, so a
// finite point beyond float range (a blunder 1e39 mm away, or an inch file
// whose values overflow after conversion) became inf and aborted the process
// inside the tree. Here every coordinate stays a double, and a non-finite
// point is refused when the set is built, never met inside a query.
//
// Two points more than about 1e154 apart (sqrt of the largest double) count
// as infinitely far from each other: their squared distance overflows, and
// such a neighbour is never returned.
//
// Results are deterministic: neighbours come sorted by distance, ties by
// index, so the same points give the same answer on every run and thread.
// Queries are const and may run from several threads at once.
#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace furrow {

struct PointNeighbour {
  std::size_t index = 0;  // into the points the search was built from
  double distance = 0;    // Euclidean, in the points' unit
};

class PointSearch {
 public:
  // Builds the tree over `points` (copied). Throws std::invalid_argument when
  // a coordinate is not finite: callers validate user data first and name
  // the file; reaching this is a programming error.
  explicit PointSearch(std::vector<Eigen::Vector3d> points);
  ~PointSearch();
  // A moved-from search may only be destroyed or assigned to.
  PointSearch(PointSearch&&) noexcept;
  PointSearch& operator=(PointSearch&&) noexcept;

  std::size_t size() const;
  const Eigen::Vector3d& point(std::size_t i) const;

  // The k points nearest to q (fewer when the set is smaller), nearest first.
  // Empty for an empty set or a non-finite q.
  std::vector<PointNeighbour> nearest(const Eigen::Vector3d& q, std::size_t k) const;
  // The nearest point; index == size() and distance = +inf when there is none.
  PointNeighbour nearest(const Eigen::Vector3d& q) const;
  // Every point at distance <= radius from q, nearest first.
  std::vector<PointNeighbour> within(const Eigen::Vector3d& q, double radius) const;

 private:
  // The points live in the tree, on the heap, because nanoflann keeps a
  // reference to them: moving a PointSearch moves only the pointer.
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace furrow
