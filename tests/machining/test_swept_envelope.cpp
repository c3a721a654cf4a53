#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "machining/brute_force_envelope.hpp"
#include "machining/prediction/swept_envelope.hpp"

using namespace furrow;
using furrow::test::brute_force_height;

namespace {

Eigen::Vector3d random_point(std::mt19937& rng, double extent) {
  std::uniform_real_distribution<double> c(-extent, extent);
  return {c(rng), c(rng), c(rng)};
}

}  // namespace

TEST_CASE("swept envelope equals the brute-force lower envelope for ball, bull-nose and flat cutters") {
  std::mt19937 rng(11);
  const Cutter cutters[] = {Cutter("ball", 3, 3), Cutter("bull", 5, 1.5), Cutter("flat", 4, 0),
                            Cutter("ball12.7", 12.7, 12.7)};
  for (const Cutter& cutter : cutters) {
    for (int m = 0; m < 25; ++m) {
      Eigen::Vector3d a = random_point(rng, 6), b = random_point(rng, 6);
      if (m % 10 == 1) b = Eigen::Vector3d(a.x(), a.y(), a.z() + 2);  // plunge up
      if (m % 10 == 2) b = Eigen::Vector3d(a.x(), a.y(), a.z() - 2);  // plunge down
      if (m % 10 == 3) b.z() = a.z();                                 // level move
      if (m % 10 == 4) b = Eigen::Vector3d(a.x(), a.y() + 3, a.z() - 1);  // along y only
      const SweptEnvelope env(cutter, a, b);
      const Eigen::AlignedBox2d box = env.shadow_box();
      std::uniform_real_distribution<double> ux(box.min().x(), box.max().x()), uy(box.min().y(), box.max().y());
      for (int k = 0; k < 60; ++k) {
        const double x = ux(rng), y = uy(rng);
        CAPTURE(cutter.name());
        CAPTURE(m);
        const double exact = env.height_at(x, y);
        const double brute = brute_force_height(cutter, a, b, x, y, 2000);
        if (!std::isfinite(brute)) {
          CHECK_FALSE(std::isfinite(exact));
          continue;
        }
        REQUIRE(std::isfinite(exact));
        // The exact minimum is below every sampled position and above the
        // best sample by at most the sampling error (sub-nanometre here).
        CHECK(exact <= brute + 1e-9);
        CHECK(exact >= brute - 1e-9);
        const EnvelopePoint p = env.evaluate(x, y);
        CHECK(p.converged);
        CHECK(p.z == doctest::Approx(exact).epsilon(1e-12).scale(1));
        // The reported parameter is where the minimum is attained.
        const Eigen::Vector3d t = a + p.s * (b - a);
        const double d = std::hypot(x - t.x(), y - t.y());
        CHECK(d <= cutter.radius() * (1 + 1e-9));
        CHECK(t.z() + cutter.height_at(std::min(d, cutter.radius())) == doctest::Approx(exact).epsilon(1e-9).scale(1));
      }
    }
  }
}

TEST_CASE("swept envelope: row spans are exactly the covered part of a row") {
  std::mt19937 rng(5);
  const Cutter ball("ball", 2.5, 2.5);
  for (int m = 0; m < 30; ++m) {
    const Eigen::Vector3d a = random_point(rng, 5);
    Eigen::Vector3d b = random_point(rng, 5);
    if (m % 6 == 0) b.x() = a.x();  // along y
    if (m % 6 == 1) b.y() = a.y();  // along x
    if (m % 6 == 2) b = a + Eigen::Vector3d(0, 0, 1);
    const SweptEnvelope env(ball, a, b);
    const Eigen::AlignedBox2d box = env.shadow_box();
    for (int r = 0; r <= 40; ++r) {
      const double y = box.min().y() - 0.1 + (box.sizes().y() + 0.2) * r / 40.0;
      double lo = 0, hi = 0;
      const bool any = env.row_span(y, lo, hi);
      int finite = 0, outside_span = 0, uncovered_inside = 0;
      for (int i = 0; i <= 2000; ++i) {
        const double x = box.min().x() - 0.1 + (box.sizes().x() + 0.2) * i / 2000.0;
        const bool covered = std::isfinite(env.height_at(x, y));
        finite += covered;
        if (covered && (!any || x < lo - 1e-9 || x > hi + 1e-9)) ++outside_span;
        if (!covered && any && x > lo + 1e-7 && x < hi - 1e-7) ++uncovered_inside;
      }
      CHECK(outside_span == 0);
      CHECK(uncovered_inside == 0);
      if (any && hi - lo > 1e-3) {
        CHECK(std::isfinite(env.height_at(lo + 1e-9, y)));
        CHECK(std::isfinite(env.height_at(hi - 1e-9, y)));
        CHECK(finite > 0);
      }
    }
  }
}

TEST_CASE("swept envelope of a level ball move is the capsule: analytic check") {
  // A level move along x: across the track the envelope is the ball's circle
  // of radius R centred R above the tip, for every x between the ends.
  const Cutter ball("ball", 4, 4);
  const SweptEnvelope env(ball, {0, 0, 1}, {10, 0, 1});
  for (double x : {0.0, 2.5, 7.0, 10.0})
    for (double y : {-3.9, -2.0, 0.0, 1.0, 3.5})
      CHECK(env.height_at(x, y) == doctest::Approx(1 + 4 - std::sqrt(16 - y * y)).epsilon(1e-14).scale(1));
  // Beyond the ends: the end ball.
  CHECK(env.height_at(12, 1) == doctest::Approx(1 + 4 - std::sqrt(16 - 5.0)).epsilon(1e-14).scale(1));
  CHECK_FALSE(std::isfinite(env.height_at(5, 4.01)));
}

TEST_CASE("swept envelope: a row in pieces is the whole row bit for bit, and the piece bound is below brute force") {
  std::mt19937 rng(29);
  const Cutter ball("ball", 3, 3), bull("bull", 3, 1), flat("flat", 2.5, 0);
  int bounded = 0, pieces = 0, tight = 0, other_pieces = 0, other_tight = 0;
  for (int m = 0; m < 120; ++m) {
    Eigen::Vector3d a = random_point(rng, 6), b = random_point(rng, 6);
    if (m % 8 == 3) b.z() = a.z();  // level move
    if (m % 8 == 5) b = a + 0.002 * (b - a);  // a short chord: the generic bound is tight
    if (m % 8 == 6) b = Eigen::Vector3d(a.x(), a.y(), a.z() + 1);  // plunge
    const Cutter& cutter = m < 40 ? ball : (m < 80 ? bull : flat);
    const bool is_ball = m < 40 && m % 8 != 6;
    const SweptEnvelope env(cutter, a, b);
    std::uniform_real_distribution<double> uy(env.shadow_box().min().y(), env.shadow_box().max().y());
    for (int r = 0; r < 10; ++r) {
      const double y = uy(rng);
      double xl = 0, xh = 0;
      if (!env.row_span(y, xl, xh)) continue;
      const double dx = 0.037;
      const int n = static_cast<int>(std::floor((xh - xl) / dx)) + 1;
      std::vector<double> whole(n), piece(n);
      env.row(y, xl, dx, n, whole.data());
      for (int k0 = 0; k0 < n; k0 += 7) {
        const int k1 = std::min(n - 1, k0 + 6);
        env.row(y, xl, dx, k0, k1 - k0 + 1, piece.data());
        double lowest = std::numeric_limits<double>::infinity();
        for (int k = k0; k <= k1; ++k) {
          CHECK(piece[k - k0] == whole[k]);  // the same bits, wherever the piece starts
          lowest = std::min(lowest, brute_force_height(cutter, a, b, xl + k * dx, y, 2000));
        }
        const double bound = env.row_lower_bound(y, xl, dx, k0, k1);
        CAPTURE(m);
        CAPTURE(k0);
        if (!is_ball) {
          // The generic bound: always there, below brute force, and within
          // the piece's own variation for a short chord.
          REQUIRE(std::isfinite(bound));
          CHECK(bound <= lowest + 1e-9);
          if (m % 8 == 5) {
            ++other_pieces;
            other_tight += bound >= lowest - 0.05;
          }
          continue;
        }
        ++pieces;
        if (!std::isfinite(bound)) {
          CHECK(bound < 0);  // -infinity: no bound, never +infinity or NaN
          continue;
        }
        ++bounded;
        // Below the envelope at every node (brute force overestimates the
        // minimum by sub-nanometres).
        CHECK(bound <= lowest + 1e-9);
        // Mostly close to it: the tangents of a smooth convex function over
        // 7 nodes of 0.037 mm (looser near the rim, where it is steep).
        tight += bound >= lowest - 0.01;
      }
    }
  }
  // Most pieces lie away from the shadow's rim, where the tangents exist.
  CHECK(pieces > 500);
  CHECK(bounded > pieces / 2);
  CHECK(tight > bounded * 3 / 4);
  CHECK(other_pieces > 50);
  CHECK(other_tight > other_pieces / 2);
}

TEST_CASE("swept envelope: the bound over a rectangle is below the brute-force envelope at every point in it, and tight for a plunge") {
  std::mt19937 rng(37);
  const Cutter cutters[] = {Cutter("ball", 3, 3), Cutter("bull", 4, 1), Cutter("flat", 2.5, 0)};
  int plunges = 0, tight = 0;
  for (const Cutter& cutter : cutters)
    for (int m = 0; m < 30; ++m) {
      Eigen::Vector3d a = random_point(rng, 6), b = random_point(rng, 6);
      const bool plunge = m % 3 == 0;
      if (plunge) b = Eigen::Vector3d(a.x(), a.y(), a.z() + 4);
      const SweptEnvelope env(cutter, a, b);
      const Eigen::AlignedBox2d shadow = env.shadow_box();
      std::uniform_real_distribution<double> ux(shadow.min().x() - 1, shadow.max().x() + 1),
          uy(shadow.min().y() - 1, shadow.max().y() + 1), size(0.05, 2.0);
      for (int r = 0; r < 8; ++r) {
        const Eigen::Vector2d lo(ux(rng), uy(rng));
        const Eigen::AlignedBox2d area(lo, lo + Eigen::Vector2d(size(rng), size(rng)));
        const double bound = env.lower_bound(area);
        REQUIRE_FALSE(std::isnan(bound));
        // The lowest envelope over a 41 x 41 grid of the rectangle.
        double lowest = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= 40; ++i)
          for (int j = 0; j <= 40; ++j) {
            const Eigen::Vector2d p = area.min() + Eigen::Vector2d(i / 40.0, j / 40.0).cwiseProduct(area.sizes());
            lowest = std::min(lowest, brute_force_height(cutter, a, b, p.x(), p.y(), 400));
          }
        CAPTURE(cutter.name());
        CAPTURE(m);
        CHECK(bound <= lowest + 1e-9);
        const Eigen::Vector2d axis = a.head<2>();
        if (plunge && std::isfinite(lowest)) {
          // A plunge's envelope is the lower tip's cutter: the bound is the
          // profile at the rectangle's nearest point, which the grid comes
          // within a grid step of.
          ++plunges;
          const double step = area.sizes().norm() / 40;
          const double nearest = (axis.cwiseMax(area.min()).cwiseMin(area.max()) - axis).norm();
          if (nearest + step < cutter.radius() - 1e-3) {
            const double at_grid = a.z() + cutter.height_at(nearest + step);
            CHECK(bound >= a.z() + cutter.height_at(nearest) - 1e-12);
            tight += lowest <= at_grid + 1e-9;
          }
        }
      }
    }
  CHECK(plunges > 10);
  CHECK(tight > 5);
}
