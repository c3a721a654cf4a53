#include "planning/tip_groups.hpp"

#include <algorithm>
#include <stdexcept>

namespace furrow {

TourResult grouped_tour(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& group,
                        const TourOptions& options) {
  if (group.size() != positions.size()) throw std::invalid_argument("grouped_tour: one group per position is needed");
  std::vector<int> groups;  // in order of first appearance
  for (int g : group)
    if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
  TourResult out;
  double joins = 0;
  for (int g : groups) {
    std::vector<int> members;
    std::vector<Eigen::Vector3d> sub;
    for (std::size_t k = 0; k < group.size(); ++k)
      if (group[k] == g) {
        members.push_back(static_cast<int>(k));
        sub.push_back(positions[k]);
      }
    const TourResult run = plan_tour(sub, options);
    std::vector<int> order;
    for (int k : run.order) order.push_back(members[static_cast<std::size_t>(k)]);
    if (!out.order.empty()) {
      const Eigen::Vector3d& last = positions[static_cast<std::size_t>(out.order.back())];
      if ((positions[static_cast<std::size_t>(order.back())] - last).norm() <
          (positions[static_cast<std::size_t>(order.front())] - last).norm())
        std::reverse(order.begin(), order.end());
      joins += (positions[static_cast<std::size_t>(order.front())] - last).norm();
    }
    out.order.insert(out.order.end(), order.begin(), order.end());
    out.nearest_neighbour_length += run.nearest_neighbour_length;
    out.start_length += run.start_length;
    out.passes += run.passes;
    out.converged = out.converged && run.converged;
  }
  out.nearest_neighbour_length += joins;
  out.start_length += joins;
  out.length = path_length(positions, out.order);
  return out;
}

int group_changes(const std::vector<int>& group, const std::vector<int>& order) {
  int changes = 0;
  for (std::size_t k = 1; k < order.size(); ++k)
    changes += group[static_cast<std::size_t>(order[k])] != group[static_cast<std::size_t>(order[k - 1])];
  return changes;
}

}  // namespace furrow
