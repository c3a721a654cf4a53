// The Bezier piece of a NURBS surface over a cell, against the B-spline
// evaluator (Cox-de Boor over the whole knot vector: an independent route to
// the same numbers) and the Bernstein basis against its closed form.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/bezier_patch.hpp"
#include "geometry/bspline_basis.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

namespace {

double binomial(int n, int k) {
  double b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

// Distinct knot values inside [lo, hi] (the span ends).
std::vector<double> span_ends(const std::vector<double>& knots, double lo, double hi) {
  std::vector<double> ends{lo};
  for (double k : knots)
    if (k > ends.back() && k < hi) ends.push_back(k);
  ends.push_back(hi);
  return ends;
}

}  // namespace

TEST_CASE("Bernstein polynomials and their derivatives match the closed form") {
  for (int p = 1; p <= 7; ++p)
    for (double t : {0.0, 1e-300, 0.137, 0.5, 0.91, 1.0}) {
      double ders[3][16];
      bernstein_with_derivatives(p, t, 2, ders);
      for (int i = 0; i <= p; ++i) {
        // B = C(p,i) t^i (1-t)^(p-i), differentiated by hand.
        const double c = binomial(p, i);
        auto pw = [](double x, int e) { return e < 0 ? 0.0 : std::pow(x, e); };
        const double s = 1 - t;
        const double b = c * pw(t, i) * pw(s, p - i);
        const double d1 = c * (i * pw(t, i - 1) * pw(s, p - i) - (p - i) * pw(t, i) * pw(s, p - i - 1));
        const double d2 = c * (i * (i - 1) * pw(t, i - 2) * pw(s, p - i) -
                               2.0 * i * (p - i) * pw(t, i - 1) * pw(s, p - i - 1) +
                               (p - i) * (p - i - 1) * pw(t, i) * pw(s, p - i - 2));
        CAPTURE(p);
        CAPTURE(t);
        CAPTURE(i);
        CHECK(ders[0][i] == doctest::Approx(b).epsilon(1e-14));
        CHECK(std::abs(ders[1][i] - d1) <= 1e-12 * (1 + std::abs(d1)));
        CHECK(std::abs(ders[2][i] - d2) <= 1e-12 * (1 + std::abs(d2)));
      }
    }
}

TEST_CASE("a Bezier cell of a NURBS surface evaluates like the surface, derivatives included") {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int degrees[][2] = {{1, 1}, {2, 3}, {3, 3}, {5, 2}, {3, 5}, {1, 3}};
  int cells = 0;
  for (const auto& deg : degrees)
    for (int variant = 0; variant < 4; ++variant) {
      const NurbsSurface surface =
          test::random_surface(rng, deg[0], deg[1], variant % 2 == 0, variant >= 2);
      const ParameterDomain& dom = surface.domain();
      const auto eu = span_ends(surface.knots_u(), dom.u0, dom.u1);
      const auto ev = span_ends(surface.knots_v(), dom.v0, dom.v1);
      for (std::size_t a = 0; a + 1 < eu.size(); ++a)
        for (std::size_t b = 0; b + 1 < ev.size(); ++b) {
          // The whole span, and a random sub-box of it (what a seed cell is).
          for (int sub = 0; sub < 2; ++sub) {
            Eigen::Vector2d lo(eu[a], ev[b]), hi(eu[a + 1], ev[b + 1]);
            if (sub == 1) {
              const Eigen::Vector2d size = hi - lo;
              const Eigen::Vector2d l = lo + Eigen::Vector2d(0.5 * unit(rng), 0.5 * unit(rng)).cwiseProduct(size);
              hi = l + Eigen::Vector2d(0.1 + 0.4 * unit(rng), 0.1 + 0.4 * unit(rng)).cwiseProduct(size);
              lo = l;
            }
            const auto patch = BezierPatch::within_span(surface, lo, hi);
            REQUIRE(patch.has_value());
            ++cells;
            const Eigen::Vector2d h = hi - lo;
            const double size = 100.0;  // the nets span about 100 mm
            for (int k = 0; k < 12; ++k) {
              // Corners and edges exactly, then random interior points.
              const double s = k < 4 ? (k & 1) : unit(rng), t = k < 4 ? (k >> 1 & 1) : unit(rng);
              const double u = k < 4 ? (s == 0 ? lo.x() : hi.x()) : lo.x() + s * h.x();
              const double v = k < 4 ? (t == 0 ? lo.y() : hi.y()) : lo.y() + t * h.y();
              // At the upper end of an inner span the B-spline evaluator takes
              // the next span's polynomial; the cell's is the limit from below.
              const double ou = u == hi.x() && u < dom.u1 ? std::nextafter(u, lo.x()) : u;
              const double ov = v == hi.y() && v < dom.v1 ? std::nextafter(v, lo.y()) : v;
              const SurfaceDerivatives want = surface.evaluate(ou, ov, 2);
              const SurfaceDerivatives got = patch->evaluate(u, v, 2);
              CAPTURE(deg[0]);
              CAPTURE(deg[1]);
              CAPTURE(variant);
              CAPTURE(u);
              CAPTURE(v);
              // Rounding of a degree <= 5 evaluation, per parameter length
              // for each derivative taken.
              const double span = std::min(h.x(), h.y());
              CHECK((got.S - want.S).norm() <= 1e-12 * size);
              CHECK((got.Su - want.Su).norm() <= 1e-11 * (want.Su.norm() + size / span));
              CHECK((got.Sv - want.Sv).norm() <= 1e-11 * (want.Sv.norm() + size / span));
              CHECK((got.Suu - want.Suu).norm() <= 1e-10 * (want.Suu.norm() + size / (span * span)));
              CHECK((got.Suv - want.Suv).norm() <= 1e-10 * (want.Suv.norm() + size / (span * span)));
              CHECK((got.Svv - want.Svv).norm() <= 1e-10 * (want.Svv.norm() + size / (span * span)));
            }
          }
        }
    }
  CHECK(cells > 100);
}

TEST_CASE("a box across an interior knot has no Bezier piece") {
  std::mt19937 rng(7);
  NurbsSurface surface = test::random_surface(rng, 3, 3, true, false);
  auto ends = [&] { return span_ends(surface.knots_u(), surface.domain().u0, surface.domain().u1); };
  while (ends().size() < 3) surface = test::random_surface(rng, 3, 3, true, false);  // want an inner knot
  const auto eu = ends();
  const double v0 = surface.domain().v0;
  CHECK_FALSE(BezierPatch::within_span(surface, {eu[0], v0}, {eu[2], v0 + 1e-3}).has_value());
  CHECK(BezierPatch::within_span(surface, {eu[0], v0}, {eu[1], v0 + 1e-3}).has_value());
  CHECK_FALSE(BezierPatch::within_span(surface, {eu[0], v0}, {eu[0], v0 + 1e-3}).has_value());
}
