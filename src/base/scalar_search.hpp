#pragma once
// One-dimensional searches shared by the machining predictors: minimising a
// unimodal function on an interval (Brent's method: parabolic steps with a
// golden-section fallback) and finding a bracketed root (Illinois regula
// falsi with a bisection safeguard).
//
// Why these two: the swept cutter's height along a move is convex in the
// move parameter (cutter.hpp: height_at is convex and nondecreasing, the
// horizontal distance is convex, the tip height linear), so a bracketed
// minimisation is robust; the error along a surface normal is a sign change
// of "envelope minus line", bracketed by construction. Both shrink their
// bracket every iteration (golden section and bisection guarantee it), so the
// iteration cap is a visible safety net, not a convergence hope; the result
// says whether the tolerance was reached.
//
// Header-only templates: the callers pass lambdas evaluated millions of
// times (z-map cells), which must inline.
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

struct ScalarSearchOptions {
  double tolerance = 1e-10;  // absolute, on the argument (same unit as the interval)
  int max_iterations = 200;  // each iteration shrinks the bracket at least by 0.618 or 0.5
};

struct ScalarSearchResult {
  double x = 0;      // argument of the minimum / of the root
  double value = 0;  // f(x)
  bool converged = false;
  int iterations = 0;
};

// Minimum of f on [a, b] (a <= b), f unimodal there (convex functions are);
// the end points are evaluated too, so a minimum at an end is found exactly.
// f may return +infinity (never NaN).
template <class F>
ScalarSearchResult minimize_unimodal(F&& f, double a, double b, const ScalarSearchOptions& options = {}) {
  ScalarSearchResult best;
  best.x = a;
  best.value = f(a);
  const double fb = f(b);
  if (fb < best.value) {
    best.x = b;
    best.value = fb;
  }
  if (!(b - a > options.tolerance)) {
    best.converged = true;
    return best;
  }
  constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt 5) / 2
  double x = a + kGolden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0, e = 0;
  int it = 0;
  for (; it < options.max_iterations; ++it) {
    const double m = 0.5 * (a + b);
    const double tol = 0.5 * options.tolerance;
    if (std::fabs(x - m) <= 2 * tol - 0.5 * (b - a)) {
      best.converged = true;
      break;
    }
    bool golden = true;
    if (std::fabs(e) > tol && std::isfinite(fx) && std::isfinite(fw) && std::isfinite(fv)) {
      // Parabola through (v, fv), (w, fw), (x, fx).
      double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::fabs(q);
      const double e_prev = e;
      e = d;
      if (std::fabs(p) < std::fabs(0.5 * q * e_prev) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < 2 * tol || b - u < 2 * tol) d = x < m ? tol : -tol;
        golden = false;
      }
    }
    if (golden) {
      e = (x < m ? b : a) - x;
      d = kGolden * e;
    }
    const double u = std::fabs(d) >= tol ? x + d : x + (d > 0 ? tol : -tol);
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  best.iterations = it;
  if (fx < best.value) {
    best.x = x;
    best.value = fx;
  }
  return best;
}

// Root of f in [a, b] given fa = f(a) and fb = f(b) of opposite signs (either
// may be +-infinity: such an end is approached by bisection). Converged when
// the bracket is below the tolerance or f is exactly 0.
template <class F>
ScalarSearchResult find_bracketed_root(F&& f, double a, double fa, double b, double fb,
                                       const ScalarSearchOptions& options = {}) {
  ScalarSearchResult res;
  if (fa == 0) return {a, 0.0, true, 0};
  if (fb == 0) return {b, 0.0, true, 0};
  // Illinois halves the kept end's value for the interpolation only; the
  // true values are tracked for the result.
  double ga = fa, gb = fb;
  int side = 0;  // which end was kept in the previous iteration
  int it = 0;
  for (; it < options.max_iterations; ++it) {
    if (std::fabs(b - a) <= options.tolerance) {
      res.converged = true;
      break;
    }
    double c;
    if (std::isfinite(ga) && std::isfinite(gb)) {
      c = (a * gb - b * ga) / (gb - ga);
      // Stay strictly inside; fall back to bisection when rounding pushes out.
      const double lo = std::min(a, b), hi = std::max(a, b);
      if (!(c > lo && c < hi)) c = 0.5 * (a + b);
    } else {
      c = 0.5 * (a + b);
    }
    const double fc = f(c);
    if (fc == 0) return {c, 0.0, true, it + 1};
    if ((fc > 0) == (fb > 0)) {
      b = c, fb = gb = fc;
      if (side == -1 && std::isfinite(ga)) ga *= 0.5;
      side = -1;
    } else {
      a = c, fa = ga = fc;
      if (side == 1 && std::isfinite(gb)) gb *= 0.5;
      side = 1;
    }
  }
  res.iterations = it;
  // The end with the smaller |f| (a finite one when there is one).
  const bool take_a = !std::isfinite(fb) || (std::isfinite(fa) && std::fabs(fa) <= std::fabs(fb));
  res.x = take_a ? a : b;
  res.value = take_a ? fa : fb;
  return res;
}

// Largest x in [lo, hi] where a monotone predicate still holds (ok(lo)
// assumed, hi the first guess where it fails): bisection until the bracket
// is below the tolerance. `x` is the last point known to satisfy it.
template <class P>
ScalarSearchResult largest_satisfying(P&& ok, double lo, double hi, const ScalarSearchOptions& options = {}) {
  ScalarSearchResult res;
  for (res.iterations = 0; res.iterations < options.max_iterations; ++res.iterations) {
    if (hi - lo <= options.tolerance) {
      res.converged = true;
      break;
    }
    const double mid = 0.5 * (lo + hi);
    (ok(mid) ? lo : hi) = mid;
  }
  res.x = lo;
  return res;
}

}  // namespace furrow
