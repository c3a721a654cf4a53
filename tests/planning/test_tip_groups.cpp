// Ordering by tip: one run per group (the fewest group changes there can
// be), each run the ordinary tour of its points, runs joined end to start.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "planning/tip_groups.hpp"

using namespace furrow;

TEST_CASE("grouped tour: fewest changes, each run as short as its own tour") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(0, 100);
  std::vector<Eigen::Vector3d> positions;
  std::vector<int> group;
  for (int k = 0; k < 120; ++k) {
    positions.emplace_back(coord(rng), coord(rng), coord(rng) / 10);
    group.push_back(static_cast<int>(rng() % 4) * 3);  // groups 0, 3, 6, 9, interleaved
  }
  const TourResult t = grouped_tour(positions, group);
  // A permutation.
  std::vector<int> sorted = t.order;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < 120; ++k) CHECK(sorted[static_cast<std::size_t>(k)] == k);
  // As many changes as groups less one: each group is visited in one run.
  CHECK(group_changes(group, t.order) == 3);
  // Runs in order of first appearance, each as long as plan_tour of its points.
  std::vector<int> first_seen;
  for (int g : group)
    if (std::find(first_seen.begin(), first_seen.end(), g) == first_seen.end()) first_seen.push_back(g);
  std::size_t at = 0;
  double joins = 0;
  for (int g : first_seen) {
    std::vector<Eigen::Vector3d> sub;
    for (std::size_t k = 0; k < group.size(); ++k)
      if (group[k] == g) sub.push_back(positions[k]);
    const double own = plan_tour(sub).length;
    std::vector<int> run;
    for (; at < t.order.size() && group[static_cast<std::size_t>(t.order[at])] == g; ++at) run.push_back(t.order[at]);
    CHECK(run.size() == sub.size());
    CHECK(path_length(positions, run) == doctest::Approx(own).epsilon(1e-12));
    if (at > run.size())
      joins += (positions[static_cast<std::size_t>(run.front())] -
                positions[static_cast<std::size_t>(t.order[at - run.size() - 1])]).norm();
  }
  double runs = 0;
  for (std::size_t k = 1; k < t.order.size(); ++k)
    if (group[static_cast<std::size_t>(t.order[k])] == group[static_cast<std::size_t>(t.order[k - 1])])
      runs += (positions[static_cast<std::size_t>(t.order[k])] - positions[static_cast<std::size_t>(t.order[k - 1])]).norm();
  CHECK(t.length == doctest::Approx(runs + joins).epsilon(1e-12));
  CHECK(t.length == doctest::Approx(path_length(positions, t.order)).epsilon(1e-12));
}

TEST_CASE("grouped tour: a run is reversed when its far end is nearer the previous run's end") {
  // Group 0 along x from 0 to 10 (its tour ends at 0 or 10); group 1 at
  // x 11..20: whichever end group 0 finishes at, group 1 must start at the
  // nearer of its ends.
  std::vector<Eigen::Vector3d> positions;
  std::vector<int> group;
  for (int k = 0; k <= 10; ++k) positions.emplace_back(k, 0, 0), group.push_back(0);
  for (int k = 11; k <= 20; ++k) positions.emplace_back(k, 0, 0), group.push_back(1);
  const TourResult t = grouped_tour(positions, group);
  const Eigen::Vector3d end0 = positions[static_cast<std::size_t>(t.order[10])];
  const Eigen::Vector3d start1 = positions[static_cast<std::size_t>(t.order[11])];
  const double other = std::min((positions[11] - end0).norm(), (positions[20] - end0).norm());
  CHECK((start1 - end0).norm() == other);
  CHECK_THROWS_AS(grouped_tour(positions, {0, 1}), std::invalid_argument);
}
