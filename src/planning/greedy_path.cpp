#include "planning/greedy_path.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "geometry/point_search.hpp"
#include "planning/unvisited_points.hpp"

namespace furrow {

namespace {

struct Edge {
  double length;
  int a, b;  // a < b
};

int find_root(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}

}  // namespace

std::vector<int> greedy_path(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::vector<int>>& neighbours) {
  const int n = static_cast<int>(points.size());
  if (neighbours.size() != points.size()) throw std::invalid_argument("greedy_path: one neighbour list per point");
  for (const Eigen::Vector3d& x : points)
    if (!x.allFinite()) throw std::invalid_argument("greedy_path: a coordinate is not finite");
  std::vector<int> order;
  if (n == 0) return order;

  // Kept edges: up to two per point (-1 = free).
  std::vector<int> link(2 * static_cast<std::size_t>(n), -1);
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto degree = [&](int x) {
    return (link[2 * static_cast<std::size_t>(x)] >= 0) + (link[2 * static_cast<std::size_t>(x) + 1] >= 0);
  };
  auto attach = [&](int x, int y) {
    link[2 * static_cast<std::size_t>(x) + (link[2 * static_cast<std::size_t>(x)] >= 0)] = y;
  };
  // Takes candidate edges shortest first; returns how many were kept.
  auto take = [&](std::vector<Edge>& edges) {
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
      return std::tie(x.length, x.a, x.b) < std::tie(y.length, y.a, y.b);
    });
    int kept = 0;
    for (const Edge& e : edges) {
      if (e.a == e.b || degree(e.a) == 2 || degree(e.b) == 2) continue;
      const int ra = find_root(parent, e.a), rb = find_root(parent, e.b);
      if (ra == rb) continue;
      parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
      attach(e.a, e.b);
      attach(e.b, e.a);
      ++kept;
    }
    return kept;
  };
  auto edge = [&](int i, int j) {
    return Edge{(points[static_cast<std::size_t>(i)] - points[static_cast<std::size_t>(j)]).norm(), std::min(i, j),
                std::max(i, j)};
  };

  std::vector<Edge> edges;
  for (int i = 0; i < n; ++i)
    for (const int j : neighbours[static_cast<std::size_t>(i)]) {
      if (j < 0 || j >= n || j == i) throw std::invalid_argument("greedy_path: bad neighbour index");
      edges.push_back(edge(i, j));  // a pair listed from both sides comes twice: the second is refused
    }
  take(edges);

  // The same rule among the fragments' ends only, with each end's nearest
  // ends as candidates, while it still joins fragments: the ends of greedy
  // fragments lie far from each other's lists, and joining them by the
  // nearest-end walk alone leaves long jumps.
  constexpr int kEndNeighbours = 8;
  for (;;) {
    std::vector<int> loose;
    for (int i = 0; i < n; ++i)
      if (degree(i) < 2) loose.push_back(i);
    if (loose.size() <= 2) break;
    std::vector<Eigen::Vector3d> at;
    for (const int i : loose) at.push_back(points[static_cast<std::size_t>(i)]);
    const PointSearch search(at);
    edges.clear();
    for (std::size_t k = 0; k < loose.size(); ++k)
      for (const PointNeighbour& m : search.nearest(at[k], kEndNeighbours + 1))
        if (m.index != k) edges.push_back(edge(loose[k], loose[m.index]));
    // About two ends per fragment: stop when a round joins less than a
    // tenth of the fragments (the walk below finishes), so the rounds stay
    // few whatever the point set.
    if (take(edges) * 20 < static_cast<int>(loose.size())) break;
  }

  // Fragment ends (degree < 2), indexed for the nearest-end walk.
  std::vector<int> ends;
  for (int i = 0; i < n; ++i)
    if (degree(i) < 2) ends.push_back(i);
  std::vector<int> slot(static_cast<std::size_t>(n), -1);
  std::vector<Eigen::Vector3d> end_points;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    slot[static_cast<std::size_t>(ends[k])] = static_cast<int>(k);
    end_points.push_back(points[static_cast<std::size_t>(ends[k])]);
  }
  UnvisitedPoints open_ends(end_points);
  order.reserve(static_cast<std::size_t>(n));
  int start = ends.empty() ? UnvisitedPoints::kNone : 0;  // ends are in index order
  while (start != UnvisitedPoints::kNone) {
    // Walk the fragment from this end to the other.
    int previous = -1, x = ends[static_cast<std::size_t>(start)];
    open_ends.visit(start);
    for (;;) {
      order.push_back(x);
      const int l0 = link[2 * static_cast<std::size_t>(x)], l1 = link[2 * static_cast<std::size_t>(x) + 1];
      const int next = l0 >= 0 && l0 != previous ? l0 : (l1 >= 0 && l1 != previous ? l1 : -1);
      if (next < 0) break;
      previous = x;
      x = next;
    }
    open_ends.visit(slot[static_cast<std::size_t>(x)]);
    start = open_ends.nearest(points[static_cast<std::size_t>(x)]);
  }
  if (order.size() != points.size()) throw std::logic_error("greedy_path: the fragments do not cover the points");
  return order;
}

}  // namespace furrow
