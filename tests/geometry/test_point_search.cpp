// PointSearch against brute force: every query answered exactly, ties broken
// by index, and points far beyond float range handled as ordinary points.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "geometry/point_search.hpp"

using namespace furrow;

namespace {

std::vector<PointNeighbour> brute_force(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& q) {
  std::vector<PointNeighbour> all;
  for (std::size_t i = 0; i < pts.size(); ++i) all.push_back({i, (pts[i] - q).norm()});
  std::sort(all.begin(), all.end(), [](const PointNeighbour& a, const PointNeighbour& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
  return all;
}

std::vector<Eigen::Vector3d> random_points(std::size_t n, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<Eigen::Vector3d> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

}  // namespace

TEST_CASE("point search: k nearest and radius queries equal brute force") {
  const std::vector<Eigen::Vector3d> pts = random_points(2000, 7, 50);
  const PointSearch search(pts);
  REQUIRE(search.size() == pts.size());
  const std::vector<Eigen::Vector3d> queries = random_points(200, 8, 60);
  for (const Eigen::Vector3d& q : queries) {
    const std::vector<PointNeighbour> expected = brute_force(pts, q);
    for (std::size_t k : {std::size_t(1), std::size_t(7), std::size_t(30)}) {
      const std::vector<PointNeighbour> got = search.nearest(q, k);
      REQUIRE(got.size() == k);
      for (std::size_t m = 0; m < k; ++m) {
        CHECK(got[m].index == expected[m].index);
        CHECK(got[m].distance == doctest::Approx(expected[m].distance).epsilon(1e-15));
      }
    }
    const double radius = 9.0;
    std::vector<std::size_t> inside;
    for (const PointNeighbour& e : expected)
      if (e.distance <= radius) inside.push_back(e.index);
    const std::vector<PointNeighbour> within = search.within(q, radius);
    REQUIRE(within.size() == inside.size());
    for (std::size_t m = 0; m < inside.size(); ++m) CHECK(within[m].index == inside[m]);
  }
}

TEST_CASE("point search: exact ties come back by index, a point at the radius is inside") {
  // Six points at distance exactly 1 from the origin (exact in binary).
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {3, 0, 0}};
  const PointSearch search(pts);
  const std::vector<PointNeighbour> four = search.nearest(Eigen::Vector3d::Zero(), 4);
  REQUIRE(four.size() == 4);
  for (std::size_t m = 0; m < 4; ++m) {
    CHECK(four[m].index == m);
    CHECK(four[m].distance == 1.0);
  }
  CHECK(search.within(Eigen::Vector3d::Zero(), 1.0).size() == 6);
  CHECK(search.within(Eigen::Vector3d::Zero(), 0.999999).empty());
}

TEST_CASE("point search: far points beyond float range are ordinary points") {
  std::vector<Eigen::Vector3d> pts = random_points(100, 3, 10);
  pts.push_back({1e39, 0, 0});   // beyond float range
  pts.push_back({0, -1e300, 0});  // near the largest double
  const PointSearch search(pts);
  CHECK(search.nearest(Eigen::Vector3d(1e39, 1, 0)).index == 100);
  CHECK(search.nearest(Eigen::Vector3d(0, -1e300, 0)).index == 101);
  CHECK(search.nearest(Eigen::Vector3d(0, -1e300, 0)).distance == 0.0);
  // A query near the cloud never returns the far points.
  CHECK(search.nearest(Eigen::Vector3d(0, 0, 0)).index < 100);
  // Beyond sqrt(DBL_MAX) apart, squared distances overflow: such points
  // count as infinitely far and are not returned (the documented contract).
  CHECK(search.nearest(Eigen::Vector3d(1e308, 0, 0), 102).empty());
  CHECK(search.nearest(Eigen::Vector3d(1e150, 0, 0), 102).size() == 101);  // all but the 1e300 one
}

TEST_CASE("point search: non-finite input") {
  CHECK_THROWS_AS(PointSearch({{0, 0, 0}, {std::nan(""), 0, 0}}), std::invalid_argument);
  CHECK_THROWS_AS(PointSearch({{std::numeric_limits<double>::infinity(), 0, 0}}), std::invalid_argument);
  const PointSearch search({{0, 0, 0}, {1, 1, 1}});
  CHECK(search.nearest(Eigen::Vector3d(std::nan(""), 0, 0), 1).empty());
  CHECK(search.within(Eigen::Vector3d(0, std::numeric_limits<double>::infinity(), 0), 1).empty());
  const PointSearch empty(std::vector<Eigen::Vector3d>{});
  CHECK(empty.nearest(Eigen::Vector3d::Zero()).index == 0);
  CHECK(std::isinf(empty.nearest(Eigen::Vector3d::Zero()).distance));
}

TEST_CASE("point search: a moved search answers like the original") {
  const std::vector<Eigen::Vector3d> pts = random_points(300, 11, 5);
  PointSearch a(pts);
  const PointNeighbour before = a.nearest(Eigen::Vector3d(1, 2, 3));
  PointSearch b(std::move(a));
  CHECK(b.nearest(Eigen::Vector3d(1, 2, 3)).index == before.index);
  CHECK(b.size() == 300);
}
