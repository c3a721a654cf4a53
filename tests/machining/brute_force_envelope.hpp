#pragma once
// Brute-force references for the machining predictors (tests only): the
// swept cutter by dense positions along the move, and the error along a
// normal by scanning then bisecting. Deliberately simple and slow, sharing
// no code with src/machining beyond Cutter::height_at (the profile).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "machining/cutter/cutter.hpp"

namespace furrow::test {

// min over s of T(s).z + height_at(|(x, y) - T_xy(s)|) from `samples` + 1
// positions, again `samples` + 1 positions between the neighbours of the
// best one, plus the exact positions where the rim passes over (x, y).
inline double brute_force_height(const Cutter& cutter, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 double x, double y, int samples) {
  const double R = cutter.radius();
  double best = std::numeric_limits<double>::infinity(), best_s = 0;
  auto consider = [&](double s) {
    if (s < 0 || s > 1) return;
    const Eigen::Vector3d t = a + s * (b - a);
    const double d = std::hypot(x - t.x(), y - t.y());
    if (d > R * (1 + 1e-12)) return;
    const double z = t.z() + cutter.height_at(std::min(d, R));
    if (z < best) best = z, best_s = s;
  };
  for (int i = 0; i <= samples; ++i) consider(double(i) / samples);
  const double centre = best_s, h = 1.0 / samples;
  for (int i = 0; i <= samples; ++i) consider(centre - h + 2 * h * i / samples);
  const double px = a.x() - x, py = a.y() - y, dx = b.x() - a.x(), dy = b.y() - a.y();
  const double qa = dx * dx + dy * dy, qb = 2 * (px * dx + py * dy), qc = px * px + py * py - R * R;
  if (qa > 0) {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      consider((-qb - std::sqrt(disc)) / (2 * qa));
      consider((-qb + std::sqrt(disc)) / (2 * qa));
    }
  }
  return best;
}

// Signed distance along n from q to the surface z = H(x, y): scan t in
// steps of `step` away from q until the sign of H - line changes, then
// bisect. Returns NaN when nothing is crossed within `range`.
template <class H>
double brute_force_normal_error(const H& height, const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                                double step = 1e-3, double range = 5.0) {
  auto g = [&](double t) { return height(q.x() + t * n.x(), q.y() + t * n.y()) - (q.z() + t * n.z()); };
  const double g0 = g(0);
  if (!std::isfinite(g0)) return std::numeric_limits<double>::quiet_NaN();
  if (g0 == 0) return 0;
  const double dir = g0 > 0 ? 1 : -1;
  double a = 0;
  for (double t = step; t <= range; t += step) {
    const double gt = g(dir * t);
    if ((g0 > 0 && gt <= 0) || (g0 < 0 && gt >= 0)) {
      double lo = dir * a, hi = dir * t;  // g(lo) has g0's sign, g(hi) the other
      for (int k = 0; k < 48; ++k) {
        const double mid = 0.5 * (lo + hi);
        const double gm = g(mid);
        ((gm > 0) == (g0 > 0) && gm != 0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    if (!std::isfinite(gt)) return std::numeric_limits<double>::quiet_NaN();
    a = t;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace furrow::test
