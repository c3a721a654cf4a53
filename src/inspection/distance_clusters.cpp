#include "inspection/distance_clusters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "geometry/point_search.hpp"

namespace furrow {

namespace {

std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

void join(std::vector<std::size_t>& parent, std::size_t i, std::size_t j) {
  const std::size_t a = root(parent, i), b = root(parent, j);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

using Cell = std::array<long, 3>;

// Dense sets (a scan's overcuts: thousands of points a few tenths of a mm
// apart, `distance` several mm): cells of side distance / sqrt(3), shrunk
// by a relative 1e-9 so rounding cannot put two points of one cell farther
// apart than `distance`. The points of a cell are all within `distance` of
// each other and join at once; two cells up to 2 apart on each axis join
// when some pair of their points is within `distance`, checked only while
// they are not joined yet (so a dense blob costs about one pair per cell
// pair instead of a neighbour query per point).
void join_by_cells(const std::vector<Eigen::Vector3d>& points, double distance, std::vector<std::size_t>& parent) {
  const double side = distance / std::sqrt(3.0) * (1 - 1e-9);
  std::map<Cell, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    cells[{static_cast<long>(std::floor(p.x() / side)), static_cast<long>(std::floor(p.y() / side)),
           static_cast<long>(std::floor(p.z() / side))}]
        .push_back(i);
  }
  for (const auto& [key, members] : cells)
    for (const std::size_t m : members) join(parent, members.front(), m);
  const double d2 = distance * distance;
  for (const auto& [key, members] : cells)
    for (long a = -2; a <= 2; ++a)
      for (long b = -2; b <= 2; ++b)
        for (long c = -2; c <= 2; ++c) {
          const Cell other{key[0] + a, key[1] + b, key[2] + c};
          if (!(key < other)) continue;  // each pair of cells once
          const auto it = cells.find(other);
          if (it == cells.end()) continue;
          if (root(parent, members.front()) == root(parent, it->second.front())) continue;
          bool linked = false;
          for (std::size_t i = 0; i < members.size() && !linked; ++i)
            for (const std::size_t j : it->second)
              if ((points[members[i]] - points[j]).squaredNorm() <= d2) {
                linked = true;
                break;
              }
          if (linked) join(parent, members.front(), it->second.front());
        }
}

}  // namespace

std::vector<std::vector<std::size_t>> distance_clusters(const std::vector<Eigen::Vector3d>& points,
                                                        double distance) {
  const std::size_t n = points.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  if (n > 1 && distance > 0) {
    join_by_cells(points, distance, parent);
  } else if (n > 1) {
    const PointSearch search(points);
    for (std::size_t i = 0; i < n; ++i)
      for (const PointNeighbour& found : search.within(points[i], distance))
        if (found.index > i) join(parent, i, found.index);
  }
  // Roots are the smallest member of their tree, so map order = first member.
  std::map<std::size_t, std::vector<std::size_t>> by_root;
  for (std::size_t i = 0; i < n; ++i) by_root[root(parent, i)].push_back(i);
  std::vector<std::vector<std::size_t>> clusters;
  for (auto& [r, members] : by_root) clusters.push_back(std::move(members));
  return clusters;
}

}  // namespace furrow
