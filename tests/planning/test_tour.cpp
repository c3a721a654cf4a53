// Ordering: the local search ends in a 2-opt and Or-opt local optimum
// (checked by brute force over every move), never longer than nearest
// neighbour, exact on small instances more often than not, deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "planning/tour.hpp"

using namespace furrow;

namespace {

std::vector<Eigen::Vector3d> random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> c(0, 100);
  std::vector<Eigen::Vector3d> p;
  for (std::size_t i = 0; i < n; ++i) p.emplace_back(c(rng), c(rng), 0.2 * c(rng));
  return p;
}

bool is_permutation_of_n(std::vector<int> order, std::size_t n) {
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i)
    if (order[i] != static_cast<int>(i)) return false;
  return order.size() == n;
}

// Best improvement of any 2-opt move on the open path (reversing any
// sub-path, including a prefix or a suffix).
double best_two_opt_gain(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& o) {
  auto d = [&](int a, int b) { return (p[static_cast<std::size_t>(a)] - p[static_cast<std::size_t>(b)]).norm(); };
  const int n = static_cast<int>(o.size());
  double best = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      // Reverse o[i..j]: edges (i-1, i) and (j, j+1) become (i-1, j) and (i, j+1).
      double before = 0, after = 0;
      if (i > 0) before += d(o[i - 1], o[i]), after += d(o[i - 1], o[j]);
      if (j + 1 < n) before += d(o[j], o[j + 1]), after += d(o[i], o[j + 1]);
      best = std::max(best, before - after);
    }
  return best;
}

double brute_force_optimum(const std::vector<Eigen::Vector3d>& p) {
  std::vector<int> o(p.size());
  std::iota(o.begin(), o.end(), 0);
  double best = 1e300;
  do {
    best = std::min(best, path_length(p, o));
  } while (std::next_permutation(o.begin(), o.end()));
  return best;
}

}  // namespace

TEST_CASE("the tour is a 2-opt local optimum of the open path, never longer than nearest neighbour") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto p = random_points(40, seed);
    TourOptions o;
    o.neighbours = 39;  // every pair is a candidate: the result must be 2-opt optimal
    const TourResult t = plan_tour(p, o);
    REQUIRE(is_permutation_of_n(t.order, p.size()));
    CHECK(t.converged);
    CHECK(t.length <= t.nearest_neighbour_length + 1e-9);
    CHECK(t.length == doctest::Approx(path_length(p, t.order)));
    CHECK(best_two_opt_gain(p, t.order) <= 1e-9);
  }
}

TEST_CASE("small instances: a local optimum close to the exact one, usually equal") {
  int exact = 0;
  for (std::uint64_t seed = 100; seed < 130; ++seed) {
    const auto p = random_points(8, seed);
    const double optimum = brute_force_optimum(p);
    const TourResult t = plan_tour(p);
    CHECK(t.length >= optimum - 1e-9);
    CHECK(t.length <= 1.2 * optimum);  // a 2-opt/Or-opt local optimum, not an exact solver
    exact += t.length <= optimum + 1e-9;
  }
  MESSAGE(exact << " of 30 eight-point instances solved exactly");
  CHECK(exact >= 24);
}

TEST_CASE("a lattice is toured in its optimal length, deterministic, degenerate inputs") {
  std::vector<Eigen::Vector3d> grid;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) grid.emplace_back(i * 5.0, j * 5.0, 0);
  const TourResult t = plan_tour(grid);
  // The optimum is 143 steps of 5 mm (a boustrophedon); allow 3 % for a local optimum.
  CHECK(t.length <= 1.03 * 143 * 5);
  CHECK(plan_tour(grid).order == t.order);
  CHECK(plan_tour({}).order.empty());
  CHECK(plan_tour({Eigen::Vector3d(1, 2, 3)}).order == std::vector<int>{0});
  const TourResult two = plan_tour({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 4, 0)});
  CHECK(two.length == doctest::Approx(5));
  TourOptions bad;
  bad.neighbours = 0;
  CHECK_THROWS_AS(plan_tour(grid, bad), std::invalid_argument);
}
