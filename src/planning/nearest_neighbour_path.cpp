#include "planning/nearest_neighbour_path.hpp"

#include "planning/unvisited_points.hpp"

namespace furrow {

std::vector<int> nearest_neighbour_path(const std::vector<Eigen::Vector3d>& points) {
  std::vector<int> order;
  UnvisitedPoints tree(points);  // refuses non-finite points
  if (points.empty()) return order;
  order.reserve(points.size());
  int current = 0;
  for (;;) {
    order.push_back(current);
    tree.visit(current);
    const int next = tree.nearest(points[static_cast<std::size_t>(current)]);
    if (next == UnvisitedPoints::kNone) break;
    current = next;
  }
  return order;
}

}  // namespace furrow
