#include "planning/edge_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/point_search.hpp"

namespace furrow {

struct EdgeDistance::Tree {
  std::vector<Eigen::Vector3d> midpoints;
  std::unique_ptr<PointSearch> search;
};

EdgeDistance::EdgeDistance() = default;
EdgeDistance::~EdgeDistance() = default;
EdgeDistance::EdgeDistance(EdgeDistance&&) noexcept = default;
EdgeDistance& EdgeDistance::operator=(EdgeDistance&&) noexcept = default;

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

void EdgeDistance::add_polyline(const std::vector<Eigen::Vector3d>& points, bool closed) {
  if (points.size() < 2) throw std::invalid_argument("EdgeDistance: a polyline needs 2 points");
  if (tree_) throw std::logic_error("EdgeDistance: add_polyline after build");
  for (std::size_t k = 0; k + 1 < points.size(); ++k) segments_.push_back({points[k], points[k + 1]});
  if (closed) segments_.push_back({points.back(), points.front()});
}

void EdgeDistance::build(double piece_length) {
  if (!(piece_length > 0)) throw std::invalid_argument("EdgeDistance: piece length must be positive");
  piece_length_ = piece_length;
  tree_ = std::make_unique<Tree>();
  for (const Segment& s : segments_) {
    const double len = (s.b - s.a).norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / piece_length)));
    for (int k = 0; k < pieces; ++k) {
      const Eigen::Vector3d a = s.a + (s.b - s.a) * (static_cast<double>(k) / pieces);
      const Eigen::Vector3d b = k + 1 == pieces ? s.b : Eigen::Vector3d(s.a + (s.b - s.a) * (static_cast<double>(k + 1) / pieces));
      pieces_.push_back({a, b});
      tree_->midpoints.push_back(0.5 * (a + b));
    }
  }
  if (!pieces_.empty()) tree_->search = std::make_unique<PointSearch>(std::move(tree_->midpoints));
}

double EdgeDistance::distance(const Eigen::Vector3d& p, double reach) const {
  if (!tree_) throw std::logic_error("EdgeDistance: distance before build");
  if (pieces_.empty()) return std::numeric_limits<double>::infinity();
  // The piece with the nearest midpoint bounds the answer from above; a
  // piece nearer than that (or than reach) has its midpoint within that
  // distance + half a piece. So only the pieces around the nearest one are
  // measured, however long the edges within reach are.
  const PointNeighbour nearest = tree_->search->nearest(p);
  if (nearest.index >= pieces_.size() || nearest.distance > reach + 0.5 * piece_length_)
    return std::numeric_limits<double>::infinity();
  double best = point_segment_distance(p, pieces_[nearest.index].a, pieces_[nearest.index].b);
  const double radius = std::min(reach, best) + 0.5 * piece_length_;
  for (const PointNeighbour& n : tree_->search->within(p, radius)) {
    const Segment& s = pieces_[n.index];
    best = std::min(best, point_segment_distance(p, s.a, s.b));
  }
  return best <= reach ? best : std::numeric_limits<double>::infinity();
}

}  // namespace furrow
