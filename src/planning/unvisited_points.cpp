#include "planning/unvisited_points.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace furrow {

namespace {

// Squared distance in the one evaluation order the contract names; the box
// bound below uses the same order, so bound <= distance holds after
// rounding too (each step is monotone), and pruning never loses the answer.
double squared_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

UnvisitedPoints::UnvisitedPoints(const std::vector<Eigen::Vector3d>& p)
    : p_(p), visited_(p.size(), false), leaf_of_(p.size(), -1) {
  for (const Eigen::Vector3d& x : p)
    if (!x.allFinite()) throw std::invalid_argument("UnvisitedPoints: a coordinate is not finite");
  if (p.size() >= static_cast<std::size_t>(kNone)) throw std::invalid_argument("UnvisitedPoints: too many points");
  perm_.resize(p.size());
  std::iota(perm_.begin(), perm_.end(), 0);
  nodes_.reserve(2 * p.size() / kLeafSize + 2);
  build(0, static_cast<int>(p.size()), -1);
}

void UnvisitedPoints::visit(int i) {
  if (visited_[static_cast<std::size_t>(i)]) return;
  visited_[static_cast<std::size_t>(i)] = true;
  for (int v = leaf_of_[static_cast<std::size_t>(i)]; v >= 0; v = nodes_[static_cast<std::size_t>(v)].parent) {
    Node& node = nodes_[static_cast<std::size_t>(v)];
    --node.alive;
    if (node.left < 0) {
      node.min_alive = kNone;
      for (int k = node.begin; k < node.end; ++k) {
        const int j = perm_[static_cast<std::size_t>(k)];
        if (!visited_[static_cast<std::size_t>(j)]) node.min_alive = std::min(node.min_alive, j);
      }
    } else {
      node.min_alive = std::min(nodes_[static_cast<std::size_t>(node.left)].min_alive,
                                nodes_[static_cast<std::size_t>(node.right)].min_alive);
    }
  }
}

int UnvisitedPoints::nearest(const Eigen::Vector3d& q) {
  best_d_ = std::numeric_limits<double>::infinity();
  best_i_ = kNone;
  if (!nodes_.empty()) search(0, q);
  return best_i_;
}

int UnvisitedPoints::build(int begin, int end, int parent) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  Node node;
  node.begin = begin;
  node.end = end;
  node.parent = parent;
  node.alive = end - begin;
  for (int a = 0; a < 3; ++a) {
    node.lo[a] = std::numeric_limits<double>::infinity();
    node.hi[a] = -std::numeric_limits<double>::infinity();
  }
  for (int k = begin; k < end; ++k) {
    const Eigen::Vector3d& x = p_[static_cast<std::size_t>(perm_[static_cast<std::size_t>(k)])];
    for (int a = 0; a < 3; ++a) {
      node.lo[a] = std::min(node.lo[a], x[a]);
      node.hi[a] = std::max(node.hi[a], x[a]);
    }
    node.min_alive = std::min(node.min_alive, perm_[static_cast<std::size_t>(k)]);
  }
  if (end - begin <= kLeafSize) {
    for (int k = begin; k < end; ++k) leaf_of_[static_cast<std::size_t>(perm_[static_cast<std::size_t>(k)])] = id;
  } else {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (node.hi[a] - node.lo[a] > node.hi[axis] - node.lo[axis]) axis = a;
    // Median split under a total order (coordinate, then index), so the
    // halves do not depend on the library's partitioning.
    const int mid = begin + (end - begin) / 2;
    std::nth_element(perm_.begin() + begin, perm_.begin() + mid, perm_.begin() + end, [&](int i, int j) {
      const double ci = p_[static_cast<std::size_t>(i)][axis], cj = p_[static_cast<std::size_t>(j)][axis];
      return ci < cj || (ci == cj && i < j);
    });
    node.left = build(begin, mid, id);
    node.right = build(mid, end, id);
  }
  nodes_[static_cast<std::size_t>(id)] = node;
  return id;
}

double UnvisitedPoints::box_bound(const Node& node, const Eigen::Vector3d& q) const {
  double g[3];
  for (int a = 0; a < 3; ++a) g[a] = std::max({node.lo[a] - q[a], q[a] - node.hi[a], 0.0});
  return g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
}

void UnvisitedPoints::search(int v, const Eigen::Vector3d& q) {
  const Node& node = nodes_[static_cast<std::size_t>(v)];
  if (node.alive == 0) return;
  const double bound = box_bound(node, q);
  if (bound > best_d_ || (bound == best_d_ && node.min_alive > best_i_)) return;
  if (node.left < 0) {
    for (int k = node.begin; k < node.end; ++k) {
      const int j = perm_[static_cast<std::size_t>(k)];
      if (visited_[static_cast<std::size_t>(j)]) continue;
      const double d = squared_distance(p_[static_cast<std::size_t>(j)], q);
      if (d < best_d_ || (d == best_d_ && j < best_i_)) {
        best_d_ = d;
        best_i_ = j;
      }
    }
    return;
  }
  // Nearer box first: it usually holds the answer and prunes the other.
  const double bl = box_bound(nodes_[static_cast<std::size_t>(node.left)], q);
  const double br = box_bound(nodes_[static_cast<std::size_t>(node.right)], q);
  const int first = bl <= br ? node.left : node.right;
  const int second = bl <= br ? node.right : node.left;
  search(first, q);
  search(second, q);
}

}  // namespace furrow
