// The greedy-edge start of the probe tour. With every pair a candidate the
// greedy rule alone joins all points into one path, which a plain O(n^2)
// implementation of the rule (all pairs sorted, degree and cycle checks by
// walking) must reproduce exactly; with short lists the result is still a
// path through every point, deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <tuple>

#include "planning/greedy_path.hpp"
#include "planning/nearest_neighbour_path.hpp"
#include "planning/tour.hpp"
#include "tour_oracles.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

std::vector<Eigen::Vector3d> random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> c(0, 50);
  std::vector<Eigen::Vector3d> p;
  for (std::size_t i = 0; i < n; ++i) p.emplace_back(c(rng), c(rng), 0.3 * c(rng));
  return p;
}

std::vector<std::vector<int>> all_pairs(std::size_t n) {
  std::vector<std::vector<int>> lists(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j) lists[i].push_back(static_cast<int>(j));
  return lists;
}

// The greedy rule on all pairs, written out plainly.
std::vector<int> plain_greedy(const std::vector<Eigen::Vector3d>& p) {
  const int n = static_cast<int>(p.size());
  std::vector<std::tuple<double, int, int>> edges;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      edges.emplace_back((p[static_cast<std::size_t>(i)] - p[static_cast<std::size_t>(j)]).norm(), i, j);
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(n));
  // Other end of the path that x ends (x has degree <= 1).
  auto other_end = [&](int x) {
    int prev = -1;
    while (true) {
      int next = -1;
      for (int y : adj[static_cast<std::size_t>(x)])
        if (y != prev) next = y;
      if (next < 0) return x;
      prev = x;
      x = next;
    }
  };
  for (const auto& [length, i, j] : edges) {
    (void)length;
    if (adj[static_cast<std::size_t>(i)].size() == 2 || adj[static_cast<std::size_t>(j)].size() == 2) continue;
    if (other_end(i) == j) continue;  // would close a cycle
    adj[static_cast<std::size_t>(i)].push_back(j);
    adj[static_cast<std::size_t>(j)].push_back(i);
  }
  int start = 0;
  while (adj[static_cast<std::size_t>(start)].size() == 2) ++start;  // the end with the smaller index
  std::vector<int> order;
  int prev = -1, x = start;
  while (x >= 0) {
    order.push_back(x);
    int next = -1;
    for (int y : adj[static_cast<std::size_t>(x)])
      if (y != prev) next = y;
    prev = x;
    x = next;
  }
  return order;
}

}  // namespace

TEST_CASE("greedy path: with all pairs as candidates, exactly the plain greedy rule") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto p = random_points(30 * seed, seed);
    const std::vector<int> g = greedy_path(p, all_pairs(p.size()));
    REQUIRE(is_permutation_of_n(g, p.size()));
    CHECK(g == plain_greedy(p));
  }
  // A lattice: many equal lengths, ties by index on both sides.
  std::vector<Eigen::Vector3d> lattice;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 7; ++j) lattice.emplace_back(4.0 * j, 4.0 * i, 0);
  CHECK(greedy_path(lattice, all_pairs(lattice.size())) == plain_greedy(lattice));
}

TEST_CASE("greedy path: short candidate lists still give one path, deterministic, shorter than nearest neighbour") {
  const auto p = random_points(5000, 21);
  // Lists from the oracle's sort: 5 nearest by distance then index.
  std::vector<std::vector<int>> lists(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::vector<std::pair<double, int>> d;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i) d.emplace_back((p[i] - p[j]).norm(), static_cast<int>(j));
    std::partial_sort(d.begin(), d.begin() + 5, d.end());
    for (int k = 0; k < 5; ++k) lists[i].push_back(d[static_cast<std::size_t>(k)].second);
  }
  const std::vector<int> g = greedy_path(p, lists);
  REQUIRE(is_permutation_of_n(g, p.size()));
  CHECK(greedy_path(p, lists) == g);
  // Greedy beats nearest neighbour on uniform points (about 16 % against
  // 25 % above the optimum, Johnson & McGeoch).
  CHECK(path_length(p, g) < path_length(p, nearest_neighbour_path(p)));
}

TEST_CASE("greedy path: small and invalid inputs") {
  CHECK(greedy_path({}, {}).empty());
  CHECK(greedy_path({Eigen::Vector3d(1, 1, 1)}, {{}}) == std::vector<int>{0});
  const std::vector<Eigen::Vector3d> same(50, Eigen::Vector3d(2, 2, 2));
  CHECK(is_permutation_of_n(greedy_path(same, all_pairs(50)), 50));
  CHECK_THROWS_AS(greedy_path(random_points(3, 1), {{1}, {0}}), std::invalid_argument);
  CHECK_THROWS_AS(greedy_path(random_points(3, 1), {{1}, {0}, {2}}), std::invalid_argument);
}
