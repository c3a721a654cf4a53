#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "geometry/trim.hpp"

using namespace furrow;

namespace {

UvLoop square(double x0, double y0, double x1, double y1, bool clockwise) {
  UvLoop l = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (clockwise) std::reverse(l.begin(), l.end());
  return l;
}

UvLoop circle(double cx, double cy, double r, int n) {
  UvLoop l;
  for (int k = 0; k < n; ++k)
    l.emplace_back(cx + r * std::cos(2 * M_PI * k / n), cy + r * std::sin(2 * M_PI * k / n));
  return l;
}

// Brute force even-odd test over all edges (no banding) as the oracle.
bool brute_contains(const std::vector<UvLoop>& loops, const Eigen::Vector2d& p) {
  bool inside = false;
  for (const auto& l : loops)
    for (std::size_t k = 0; k < l.size(); ++k) {
      const auto& a = l[k];
      const auto& b = l[(k + 1) % l.size()];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()) > p.x())
        inside = !inside;
    }
  return inside;
}

}  // namespace

TEST_CASE("an empty trim keeps everything") {
  Trim t;
  CHECK(t.contains({0.3, -7}));
  CHECK(std::isinf(t.distance_to_boundary({0, 0})));
}

TEST_CASE("outer loop with a hole: points in the hole are outside, orientation does not matter") {
  for (bool cw_outer : {false, true}) {
    for (bool cw_hole : {false, true}) {
      Trim t({square(0, 0, 1, 1, cw_outer), square(0.4, 0.4, 0.6, 0.6, cw_hole)});
      CHECK(t.contains({0.2, 0.2}));
      CHECK_FALSE(t.contains({0.5, 0.5}));
      CHECK_FALSE(t.contains({1.5, 0.5}));
      CHECK_FALSE(t.contains({0.5, -0.1}));
      CHECK(t.distance_to_boundary({0.5, 0.5}) == doctest::Approx(0.1));
      CHECK(t.distance_to_boundary({0.2, 0.5}) == doctest::Approx(0.2));
    }
  }
}

TEST_CASE("banded test agrees with the brute-force crossing count on many loops") {
  std::vector<UvLoop> loops = {circle(0.5, 0.5, 0.45, 300), circle(0.3, 0.5, 0.1, 80),
                               circle(0.7, 0.6, 0.12, 50), circle(0.7, 0.6, 0.05, 40)};
  Trim t(loops);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(-0.1, 1.1);
  int inside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector2d p(unit(rng), unit(rng));
    const bool expected = brute_contains(loops, p);
    CHECK(t.contains(p) == expected);
    inside += expected;
  }
  CHECK(inside > 5000);  // the sample really exercises both answers
}

TEST_CASE("bad trim loops are rejected with the field named") {
  CHECK_THROWS_WITH_AS(Trim({{{0, 0}, {1, 0}}}, "faces[0].trim"),
                       doctest::Contains("faces[0].trim[0]"), InputError);
  CHECK_THROWS_AS(Trim({{{0, 0}, {1, 0}, {std::nan(""), 1}}}), InputError);
}

TEST_CASE("edge_near finds the nearest loop edge within the distance, as brute force does") {
  std::vector<UvLoop> loops = {circle(0.5, 0.5, 0.45, 300), circle(0.3, 0.5, 0.1, 80), circle(0.7, 0.6, 0.12, 50)};
  const Trim t(loops);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-0.1, 1.1);
  int near = 0;
  for (int k = 0; k < 5000; ++k) {
    const Eigen::Vector2d p(unit(rng), unit(rng));
    const double exact = t.distance_to_boundary(p);  // all edges, no bands
    for (const double max_distance : {1e-3, 0.02}) {
      const auto e = t.edge_near(p, max_distance);
      REQUIRE(e.has_value() == (exact <= max_distance));
      if (!e) continue;
      ++near;
      CHECK(e->distance == doctest::Approx(exact).epsilon(1e-12));
      CHECK((e->point - p).norm() == doctest::Approx(exact).epsilon(1e-12));
      CHECK(e->tangent.norm() == doctest::Approx(1).epsilon(1e-12));
      CHECK(t.distance_to_boundary(e->point) < 1e-12);  // the point is on a loop
    }
  }
  CHECK(near > 200);
  // On a vertex-free stretch of a square loop the tangent is the edge's.
  const Trim square({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  const auto e = square.edge_near({0.4, 1e-12}, 1e-9);
  REQUIRE(e.has_value());
  CHECK(std::abs(e->tangent.x()) == doctest::Approx(1));
  CHECK_FALSE(Trim().edge_near({0.5, 0.5}, 1).has_value());
}
