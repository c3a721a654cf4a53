#pragma once
// Distance from a point on the part to the nearest edge of a region: the
// border polylines of the region (uv cell-edge loops evaluated on the
// surface, regions.json) and the trim loops of its face.
//
// Border clearance is measured on the surface (geodesic distance), and the
// straight-line distance computed here is never longer than the geodesic
// one: a point whose 3-D distance to every edge is at least `b` is at least
// `b` from the edges along the surface too. The test is therefore
// conservative; it gives away a little room only where the surface folds
// back within `b` of a point (curvature radius comparable with `b`).
//
// Edges are cut into pieces no longer than a given length and the piece
// midpoints go into a k-d tree (geometry/point_search.hpp); a query takes
// the piece with the nearest midpoint, then looks at the pieces whose
// midpoints lie within the distance to it (or reach, if smaller) + half a
// piece length and measures the exact point-segment distance, so the answer
// is exact, not a sampled approximation.
//
// Units: mm. Thread safety: distance() is const and may run concurrently.
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace furrow {

class EdgeDistance {
 public:
  EdgeDistance();
  ~EdgeDistance();
  EdgeDistance(EdgeDistance&&) noexcept;
  EdgeDistance& operator=(EdgeDistance&&) noexcept;

  // A polyline of at least 2 points; `closed` joins the last to the first.
  void add_polyline(const std::vector<Eigen::Vector3d>& points, bool closed);
  // Splits the edges into pieces of at most `piece_length` (> 0) and builds
  // the search tree. Call once, after every add_polyline.
  void build(double piece_length);

  bool empty() const { return segments_.empty(); }
  std::size_t segment_count() const { return segments_.size(); }

  // Distance to the nearest edge when it is at most `reach` (> 0); +infinity
  // when no edge is that close (or there are no edges).
  double distance(const Eigen::Vector3d& p, double reach) const;

 private:
  struct Segment {
    Eigen::Vector3d a, b;
  };
  struct Tree;
  std::vector<Segment> segments_;
  std::vector<Segment> pieces_;
  double piece_length_ = 0;
  std::unique_ptr<Tree> tree_;
};

// Distance from p to the segment [a, b].
double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace furrow
