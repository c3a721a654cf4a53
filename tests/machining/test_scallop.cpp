#include <doctest/doctest.h>

#include <cmath>

#include "machining/prediction/scallop.hpp"

using namespace furrow;

namespace {

// Brute-force oracle: the cusp is the highest point of the lower envelope of
// the two balls' cross-section circles between the two contact points, found
// by scanning the angle from the curvature centre (independent of the closed
// form's algebra). Returns the material left [mm].
double brute_force_scallop(double r, double k, double w) {
  if (k == 0) {
    // Balls centred at x = -w/2 and +w/2, height r above the plane; the
    // machined height at x is min over balls of r - sqrt(r^2 - (x - c)^2).
    double worst = 0;
    for (int i = 0; i <= 200000; ++i) {
      const double x = -w / 2 + w * i / 200000.0;
      const double z1 = r - std::sqrt(std::max(0.0, r * r - (x + w / 2) * (x + w / 2)));
      const double z2 = r - std::sqrt(std::max(0.0, r * r - (x - w / 2) * (x - w / 2)));
      worst = std::max(worst, std::min(z1, z2));
    }
    return worst;
  }
  // Curved: rays from the curvature centre O. Convex: material lies inside
  // the circle of radius rho, and along a ray it ends where the ray enters
  // the first ball. Concave: material lies outside, and the cut reaches as
  // far as the ray's last exit from a ball. The material left is the gap to
  // the circle; its maximum over the rays is the scallop.
  const double rho = 1 / std::fabs(k);
  const bool convex = k < 0;
  const double phi = w / (2 * rho);
  const double a = convex ? rho + r : rho - r;
  const double centres[2][2] = {{-a * std::sin(phi), a * std::cos(phi)}, {a * std::sin(phi), a * std::cos(phi)}};
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double t = -phi + 2 * phi * i / 200000.0;
    const double ux = std::sin(t), uy = std::cos(t);
    double entry = 1e300, exit = -1e300;
    for (const auto& c : centres) {
      const double b = ux * c[0] + uy * c[1];
      const double disc = b * b - (c[0] * c[0] + c[1] * c[1] - r * r);
      if (disc < 0) continue;  // the ray misses this ball
      entry = std::min(entry, b - std::sqrt(disc));
      exit = std::max(exit, b + std::sqrt(disc));
    }
    worst = std::max(worst, convex ? entry - rho : rho - exit);
  }
  return worst;
}

}  // namespace

TEST_CASE("ball scallop on a flat part: the textbook formula and its inverse") {
  const double r = 3.0;
  for (double w : {0.1, 0.5, 1.0, 2.5, 5.9}) {
    const double h = *ball_scallop_height(r, 0.0, w);
    CHECK(h == doctest::Approx(r - std::sqrt(r * r - w * w / 4)).epsilon(1e-14));
    // w = 2 sqrt(2 r h - h^2) inverts it exactly.
    CHECK(2 * std::sqrt(2 * r * h - h * h) == doctest::Approx(w).epsilon(1e-12));
    CHECK(h == doctest::Approx(brute_force_scallop(r, 0.0, w)).epsilon(1e-9).scale(1e-3));
    const SideStepResult s = ball_side_step_for_scallop(r, 0.0, h);
    CHECK(s.converged);
    CHECK(s.side_step == doctest::Approx(w).epsilon(1e-10));
  }
  CHECK_FALSE(ball_scallop_height(r, 0.0, 6.0));  // balls no longer overlap
}

TEST_CASE("ball scallop on convex and concave sections agrees with a brute-force envelope") {
  const double r = 6.0;
  for (double rho : {10.0, 25.4, 80.0}) {
    for (double sign : {-1.0, 1.0}) {
      const double k = sign / rho;
      for (double w : {0.5, 1.5, 3.0}) {
        CAPTURE(rho);
        CAPTURE(sign);
        CAPTURE(w);
        const auto h = ball_scallop_height(r, k, w);
        REQUIRE(h);
        CHECK(*h == doctest::Approx(brute_force_scallop(r, k, w)).epsilon(1e-6).scale(1e-4));
        const SideStepResult s = ball_side_step_for_scallop(r, k, *h);
        CHECK(s.converged);
        CHECK(s.side_step == doctest::Approx(w).epsilon(1e-9));
      }
    }
  }
  // Convex sections make larger scallops than flat, concave smaller, at equal step.
  CHECK(*ball_scallop_height(r, -1 / 25.4, 2.0) > *ball_scallop_height(r, 0, 2.0));
  CHECK(*ball_scallop_height(r, 1 / 25.4, 2.0) < *ball_scallop_height(r, 0, 2.0));
}

TEST_CASE("a concave section tighter than the ball has no scallop: the ball gouges") {
  CHECK_FALSE(ball_scallop_height(6.0, 1 / 5.0, 1.0));
  const SideStepResult s = ball_side_step_for_scallop(6.0, 1 / 5.0, 0.01);
  CHECK_FALSE(s.feasible);
}

TEST_CASE("the small-h estimate is close for small heights and drifts for large ones") {
  const double r = 6.0, k = -1 / 25.4;
  const double exact_small = ball_side_step_for_scallop(r, k, 0.001).side_step;
  CHECK(ball_side_step_estimate(r, k, 0.001) == doctest::Approx(exact_small).epsilon(1e-3).scale(0));
  const double exact_large = ball_side_step_for_scallop(r, k, 0.5).side_step;
  CHECK(std::abs(ball_side_step_estimate(r, k, 0.5) - exact_large) > 1e-2);
}
