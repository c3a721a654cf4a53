#pragma once
// Trimming of a face in its (u,v) parameter domain.
//
// A trim is a set of closed polygons (loops) in (u,v); the first vertex is not
// repeated at the end. The kept region is the set of points enclosed by an odd
// number of loops (even-odd rule): an outer loop keeps its inside, a hole loop
// inside it removes its inside again, an island inside a hole adds back — and
// the loops' orientation does not matter, so files from any CAD system agree.
// An empty trim keeps the whole parameter rectangle.
//
// The test is ours and fast: every loop edge is put into one of a fixed number
// of horizontal (v) bands once, so a query crosses only the edges of its band.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace furrow {

using UvLoop = std::vector<Eigen::Vector2d>;

class Trim {
 public:
  Trim() = default;
  // Throws InputError naming `field` for a loop with fewer than 3 vertices or a
  // non-finite coordinate.
  explicit Trim(std::vector<UvLoop> loops, const std::string& field = "trim");

  bool empty() const { return loops_.empty(); }
  const std::vector<UvLoop>& loops() const { return loops_; }

  // True when (u,v) is kept by the trim (always true for an empty trim).
  // Points exactly on a loop edge count as inside or outside depending on the
  // half-open crossing rule; callers that need a margin use distance_to_boundary.
  bool contains(const Eigen::Vector2d& uv) const;

  // Euclidean (u,v) distance to the nearest loop edge; +infinity for an empty trim.
  double distance_to_boundary(const Eigen::Vector2d& uv) const;

  // The nearest point of a loop edge when one lies within `max_distance`
  // (u,v units) of uv: the point, the distance and the edge's unit direction
  // in (u,v). Only the bands near uv are searched, so this is cheap for the
  // small distances that decide "is this point on the trim curve".
  struct EdgePoint {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    Eigen::Vector2d tangent = Eigen::Vector2d::UnitX();
    double distance = 0;
  };
  std::optional<EdgePoint> edge_near(const Eigen::Vector2d& uv, double max_distance) const;

 private:
  struct Edge {
    Eigen::Vector2d a, b;
  };
  void build_bands();

  std::vector<UvLoop> loops_;
  double v_min_ = 0, v_max_ = 0, band_height_ = 1;
  std::vector<std::vector<Edge>> bands_;
};

}  // namespace furrow
