#include "inspection/distance_clusters.hpp"

#include <map>
#include <numeric>

#include "geometry/point_search.hpp"

namespace furrow {

namespace {

std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::vector<std::size_t>> distance_clusters(const std::vector<Eigen::Vector3d>& points,
                                                        double distance) {
  const std::size_t n = points.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  if (n > 1) {
    const PointSearch search(points);
    for (std::size_t i = 0; i < n; ++i) {
      for (const PointNeighbour& found : search.within(points[i], distance)) {
        const std::size_t j = found.index;
        if (j <= i) continue;
        const std::size_t a = root(parent, i), b = root(parent, j);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // Roots are the smallest member of their tree, so map order = first member.
  std::map<std::size_t, std::vector<std::size_t>> by_root;
  for (std::size_t i = 0; i < n; ++i) by_root[root(parent, i)].push_back(i);
  std::vector<std::vector<std::size_t>> clusters;
  for (auto& [r, members] : by_root) clusters.push_back(std::move(members));
  return clusters;
}

}  // namespace furrow
