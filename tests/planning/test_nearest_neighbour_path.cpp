// The nearest-neighbour construction through the k-d tree of unvisited
// points gives exactly the path of the plain O(n^2) scan (the contract's
// rule, written out here independently), on random, lattice (many equal
// distances), duplicated and degenerate point sets.
#include <doctest/doctest.h>

#include <limits>
#include <random>
#include <stdexcept>

#include "planning/nearest_neighbour_path.hpp"

using namespace furrow;

namespace {

std::vector<int> scan_path(const std::vector<Eigen::Vector3d>& p) {
  const std::size_t n = p.size();
  std::vector<int> order;
  std::vector<bool> used(n, false);
  std::size_t current = 0;
  for (std::size_t step = 0; step < n; ++step) {
    order.push_back(static_cast<int>(current));
    used[current] = true;
    double best = std::numeric_limits<double>::infinity();
    std::size_t next = n;
    for (std::size_t j = 0; j < n; ++j) {
      if (used[j]) continue;
      const double dx = p[j].x() - p[current].x(), dy = p[j].y() - p[current].y(), dz = p[j].z() - p[current].z();
      const double dj = dx * dx + dy * dy + dz * dz;
      if (dj < best || next == n) {  // first unvisited, then strictly nearer: ties keep the smaller index
        best = dj;
        next = j;
      }
    }
    current = next;
  }
  return order;
}

std::vector<Eigen::Vector3d> random_points(std::size_t n, std::uint64_t seed, double scale, double offset) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> c(0, 1);
  std::vector<Eigen::Vector3d> p;
  for (std::size_t i = 0; i < n; ++i)
    p.emplace_back(offset + scale * c(rng), offset + scale * c(rng), offset + 0.1 * scale * c(rng));
  return p;
}

}  // namespace

TEST_CASE("nearest-neighbour path: the same as the O(n^2) scan on random points") {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto p = random_points(500 * seed, seed, 100, 0);
    CHECK(nearest_neighbour_path(p) == scan_path(p));
  }
  // Coordinates near 1e6 mm: the distances lose most of their digits to the
  // offset, the rule still decides the same way.
  const auto far = random_points(2000, 77, 50, 1e6);
  CHECK(nearest_neighbour_path(far) == scan_path(far));
}

TEST_CASE("nearest-neighbour path: ties go to the smallest index, as in the scan") {
  // A lattice in scrambled index order: every step has several equally near
  // candidates.
  std::vector<Eigen::Vector3d> lattice;
  for (int k = 0; k < 900; ++k) {
    const int s = (k * 337) % 900;  // 337 is prime to 900: a permutation
    lattice.emplace_back(2.5 * (s % 30), 2.5 * (s / 30), 0);
  }
  CHECK(nearest_neighbour_path(lattice) == scan_path(lattice));
  // Every point three times, and one point everywhere.
  std::vector<Eigen::Vector3d> tripled;
  for (int copy = 0; copy < 3; ++copy)
    for (const Eigen::Vector3d& x : random_points(300, 5, 10, 0)) tripled.push_back(x);
  CHECK(nearest_neighbour_path(tripled) == scan_path(tripled));
  const std::vector<Eigen::Vector3d> same(1000, Eigen::Vector3d(3, -1, 7));
  std::vector<int> identity(1000);
  for (int i = 0; i < 1000; ++i) identity[static_cast<std::size_t>(i)] = i;
  CHECK(nearest_neighbour_path(same) == identity);
  // Collinear, shuffled.
  std::vector<Eigen::Vector3d> line;
  for (int k = 0; k < 700; ++k) line.emplace_back(((k * 211) % 700) * 0.3, 0, 0);
  CHECK(nearest_neighbour_path(line) == scan_path(line));
}

TEST_CASE("nearest-neighbour path: small and invalid inputs") {
  CHECK(nearest_neighbour_path({}).empty());
  CHECK(nearest_neighbour_path({Eigen::Vector3d(1, 2, 3)}) == std::vector<int>{0});
  const std::vector<Eigen::Vector3d> three{{0, 0, 0}, {10, 0, 0}, {1, 0, 0}};
  CHECK(nearest_neighbour_path(three) == std::vector<int>{0, 2, 1});
  const std::vector<Eigen::Vector3d> bad{{0, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0, 0}};
  CHECK_THROWS_AS(nearest_neighbour_path(bad), std::invalid_argument);
}
