// Accessibility of probe points with a vertical stylus: each failure mode on
// a part whose answer follows from elementary geometry, and the sphere
// tracing against brute-force sampling.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "planning/accessibility.hpp"
#include "plan_fixtures.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {


AccessOptions options_with_plane(double clearance_z) {
  AccessOptions o;
  o.approach = 3;
  o.retract = 3;
  o.clearance_z = clearance_z;
  return o;
}

// A floor z = 0 (40 x 40 mm) under a downward-facing ceiling at height h
// over x in [0, 20].
Part floor_with_ceiling(double h) {
  Part part;
  part.faces.emplace_back("floor", make_plane({0, 0, 0}, {40, 0, 0}, {0, 40, 0}));
  part.faces.emplace_back("ceiling", make_plane({0, 0, h}, {0, 40, 0}, {20, 0, 0}));
  return part;
}

}  // namespace

TEST_CASE("a point on a plane is accessible, a steep normal is refused by the tilt limit") {
  const Part plane = one_face(make_plane({0, 0, 0}, {100, 0, 0}, {0, 100, 0}));
  const ClosestPointFinder finder(plane);
  const ProbeGeometry probe{1, 0.5, 20};
  const AccessResult ok = check_access(finder, {50, 50, 0}, {0, 0, 1}, probe, options_with_plane(5));
  CHECK(ok.ok());
  CHECK(ok.tilt == doctest::Approx(0));
  const double a = 80 * kPi / 180;
  const AccessResult steep = check_access(finder, {50, 50, 0}, {std::sin(a), 0, std::cos(a)}, probe, options_with_plane(5));
  CHECK(steep.problem == AccessProblem::tilt);
  CHECK(steep.tilt == doctest::Approx(a));
}

TEST_CASE("a groove narrower than the ball: the ball would touch the rims") {
  const Part part = groove_part(1.0);
  const ClosestPointFinder finder(part);
  // Ball radius 2 at the bottom (0, 10, -1): centre (0, 10, 1), nearest part
  // points are the rims (+-1, 10, 0) at sqrt(2).
  const AccessResult big = check_access(finder, {0, 10, -1}, {0, 0, 1}, {2, 1, 20}, options_with_plane(10));
  CHECK(big.problem == AccessProblem::ball);
  CHECK(big.distance == doctest::Approx(std::sqrt(2.0)).epsilon(1e-9));
  // A ball of radius 0.5 fits: the bottom is reachable.
  CHECK(check_access(finder, {0, 10, -1}, {0, 0, 1}, {0.5, 0.25, 20}, options_with_plane(10)).ok());
}

TEST_CASE("shaft, approach path and vertical access under a ceiling") {
  const ProbeGeometry probe{1, 0.5, 20};
  {
    // Ceiling at 10: ball (centre z 1) and approach (to z 4) are clear; the
    // shaft (up to z 21) comes within its radius 0.5 of the ceiling at z 9.5.
    const Part part = floor_with_ceiling(10);
    const ClosestPointFinder finder(part);
    const AccessResult r = check_access(finder, {10, 20, 0}, {0, 0, 1}, probe, options_with_plane(13));
    CHECK(r.problem == AccessProblem::stylus);
    CHECK(r.where.z() == doctest::Approx(9.5).epsilon(0.002));
    // Beside the ceiling everything is clear.
    CHECK(check_access(finder, {30, 20, 0}, {0, 0, 1}, probe, options_with_plane(13)).ok());
  }
  {
    // Ceiling at 30: above the shaft's top (21); coming down from the
    // clearance plane (z 33) the ball hits it at z 29.
    const Part part = floor_with_ceiling(30);
    const ClosestPointFinder finder(part);
    const AccessResult r = check_access(finder, {10, 20, 0}, {0, 0, 1}, probe, options_with_plane(33));
    CHECK(r.problem == AccessProblem::vertical_access);
    CHECK(r.where.z() == doctest::Approx(29).epsilon(0.001));
  }
  {
    // Ceiling at 4.5: the ball at contact clears it (3.5 > 1), its approach
    // path to z 4 does not (0.5 < 1), first at z 3.5.
    const Part part = floor_with_ceiling(4.5);
    const ClosestPointFinder finder(part);
    const AccessResult r = check_access(finder, {10, 20, 0}, {0, 0, 1}, probe, options_with_plane(8));
    CHECK(r.problem == AccessProblem::approach_path);
    CHECK(r.where.z() == doctest::Approx(3.5).epsilon(0.005));
  }
}

TEST_CASE("sphere tracing finds the first contact that dense sampling finds") {
  // Obstacle: a sphere of radius 10 at the origin. Segments from outside.
  const Part ball = one_face(make_sphere(10, -kPi, kPi, -kPi / 2, kPi / 2));
  const ClosestPointFinder finder(ball);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> c(-25, 25);
  int hits = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Eigen::Vector3d a(c(rng), c(rng), c(rng)), b(c(rng), c(rng), c(rng));
    if (a.norm() < 13) a *= 13 / a.norm();
    const double radius = 2;
    const auto found = first_contact(finder, a, b, radius, 1e-9, 0.01, 100000);
    // Oracle: distance to the sphere is | |q| - 10 |; first t with < radius.
    const double length = (b - a).norm();
    double first = -1;
    for (int k = 0; k <= 200000; ++k) {
      const double t = length * k / 200000;
      const Eigen::Vector3d q = a + (b - a) * (t / length);
      if (std::abs(q.norm() - 10) < radius) {
        first = t;
        break;
      }
    }
    if (first < 0) {
      CHECK_FALSE(found.has_value());
    } else {
      ++hits;
      REQUIRE(found.has_value());
      CHECK(found->t >= first - 1e-3);
      CHECK(found->t <= first + 0.01);
    }
  }
  CHECK(hits > 10);
}
