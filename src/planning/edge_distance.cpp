#include "planning/edge_distance.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace furrow {

struct EdgeDistance::Tree {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
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
      const Eigen::Vector3d m = 0.5 * (a + b);
      tree_->cloud->push_back(pcl::PointXYZ(static_cast<float>(m.x()), static_cast<float>(m.y()), static_cast<float>(m.z())));
    }
  }
  if (!pieces_.empty()) tree_->tree.setInputCloud(tree_->cloud);
}

double EdgeDistance::distance(const Eigen::Vector3d& p, double reach) const {
  if (!tree_) throw std::logic_error("EdgeDistance: distance before build");
  if (pieces_.empty()) return std::numeric_limits<double>::infinity();
  // Midpoints are stored in float: widen the search by their rounding.
  const double slack = 1e-5 * (1.0 + p.cwiseAbs().maxCoeff());
  const double radius = reach + 0.5 * piece_length_ + slack;
  std::vector<int> index;
  std::vector<float> squared;
  const pcl::PointXYZ q(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
  tree_->tree.radiusSearch(q, radius, index, squared);
  double best = std::numeric_limits<double>::infinity();
  for (int i : index) {
    const Segment& s = pieces_[static_cast<std::size_t>(i)];
    best = std::min(best, point_segment_distance(p, s.a, s.b));
  }
  return best <= reach ? best : std::numeric_limits<double>::infinity();
}

}  // namespace furrow
