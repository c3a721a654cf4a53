// The area warp: uniform density in the unit square -> density in (u, v)
// proportional to the given one (analytic CDFs as oracle).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "planning/area_warp.hpp"

using namespace furrow;

TEST_CASE("a constant density gives the affine map onto the box") {
  const AreaWarp w(Eigen::AlignedBox2d(Eigen::Vector2d(1, 2), Eigen::Vector2d(3, 6)), 7, [](double, double) { return 2.5; });
  const Eigen::Vector2d p = w.map({0.25, 0.5});
  CHECK(p.x() == doctest::Approx(1.5).epsilon(1e-14));
  CHECK(p.y() == doctest::Approx(4.0).epsilon(1e-14));
  CHECK(w.map({0, 0}).isApprox(Eigen::Vector2d(1, 2)));
}

TEST_CASE("a density linear in u is inverted exactly on its piecewise-constant cells") {
  // Density u on [0, 1] sampled at cell centres (k + 1/2) / n: the CDF at
  // node k is sum_{i<k} (i + 1/2) / (n^2 / 2) = k^2 / n^2, so s = (k/n)^2
  // maps to u = k/n exactly, and v (density constant in v) is affine.
  constexpr int n = 10;
  const AreaWarp w(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), n,
                   [](double u, double) { return u; });
  for (int k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k * k) / (n * n);
    const Eigen::Vector2d p = w.map({s, 0.3});
    CHECK(p.x() == doctest::Approx(static_cast<double>(k) / n).epsilon(1e-12));
    CHECK(p.y() == doctest::Approx(0.3).epsilon(1e-12));
  }
}

TEST_CASE("columns of zero density are never chosen, a zero density is refused") {
  const AreaWarp w(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), 4,
                   [](double u, double) { return u < 0.5 ? 0.0 : 1.0; });
  for (int k = 0; k < 50; ++k) CHECK(w.map({k / 50.0, 0.5}).x() >= 0.5);
  CHECK_THROWS_AS(AreaWarp(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), 4,
                           [](double, double) { return 0.0; }),
                  std::invalid_argument);
  CHECK_THROWS_AS(AreaWarp(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), 4,
                           [](double, double) { return -1.0; }),
                  std::invalid_argument);
}
