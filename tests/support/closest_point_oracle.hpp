#pragma once
// Brute-force closest point on a part, the oracle of the closest-point
// tests: dense sampling of every face (kept by its trim) and of every trim
// loop, then a derivative-free compass search from the best discrete minima
// and a golden-section search along the best trim segments. Slow (about
// 60 000 surface evaluations per face and point) and independent of the
// finder's cells, bounds and Newton solves.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "geometry/part.hpp"

namespace furrow::test {

struct Oracle {
  double distance = std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

// Compass search on |S(uv) - q|^2 restricted to the kept region of the face.
inline void compass(const Face& face, const Eigen::Vector3d& q, Eigen::Vector2d uv, double step,
             std::size_t face_index, Oracle& best) {
  const ParameterDomain& d = face.domain();
  auto value = [&](const Eigen::Vector2d& p) {
    return (face.surface().point(p.x(), p.y()) - q).squaredNorm();
  };
  double f = value(uv);
  const Eigen::Vector2d dirs[8] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1},
                                   {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  while (step > 1e-15) {
    bool moved = false;
    for (const auto& dir : dirs) {
      Eigen::Vector2d p = uv + step * dir;
      p.x() = std::clamp(p.x(), d.u0, d.u1);
      p.y() = std::clamp(p.y(), d.v0, d.v1);
      if (!face.trim().contains(p)) continue;
      const double fp = value(p);
      if (fp < f) {
        f = fp;
        uv = p;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  if (std::sqrt(f) < best.distance) {
    best.distance = std::sqrt(f);
    best.face = face_index;
    best.point = face.surface().point(uv.x(), uv.y());
  }
}

// Golden-section search along one uv segment (trim boundary).
inline void golden(const Face& face, const Eigen::Vector3d& q, const Eigen::Vector2d& a,
            const Eigen::Vector2d& b, double t_lo, double t_hi, std::size_t face_index,
            Oracle& best) {
  auto value = [&](double t) {
    const Eigen::Vector2d p = a + t * (b - a);
    return (face.surface().point(p.x(), p.y()) - q).squaredNorm();
  };
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = t_hi - g * (t_hi - t_lo), x2 = t_lo + g * (t_hi - t_lo);
  double f1 = value(x1), f2 = value(x2);
  for (int it = 0; it < 200; ++it) {
    if (f1 < f2) {
      t_hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = t_hi - g * (t_hi - t_lo);
      f1 = value(x1);
    } else {
      t_lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = t_lo + g * (t_hi - t_lo);
      f2 = value(x2);
    }
  }
  for (double t : {t_lo, t_hi, 0.5 * (t_lo + t_hi)}) {
    const double f = std::sqrt(value(t));
    if (f < best.distance) {
      best.distance = f;
      best.face = face_index;
      const Eigen::Vector2d p = a + t * (b - a);
      best.point = face.surface().point(p.x(), p.y());
    }
  }
}

inline Oracle brute_force(const Part& part, const Eigen::Vector3d& q, int n = 240) {
  Oracle best;
  for (std::size_t fi = 0; fi < part.faces.size(); ++fi) {
    const Face& face = part.faces[fi];
    const ParameterDomain& d = face.domain();
    std::vector<double> f((n + 1) * (n + 1), std::numeric_limits<double>::infinity());
    auto at = [&](int i, int j) {
      return Eigen::Vector2d(d.u0 + d.width_u() * i / n, d.v0 + d.width_v() * j / n);
    };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const Eigen::Vector2d uv = at(i, j);
        if (face.trim().contains(uv))
          f[i * (n + 1) + j] = (face.surface().point(uv.x(), uv.y()) - q).norm();
      }
    // Discrete local minima, best few refined.
    std::vector<std::pair<double, int>> minima;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double v = f[i * (n + 1) + j];
        if (!std::isfinite(v)) continue;
        bool is_min = true;
        for (int a = -1; a <= 1 && is_min; ++a)
          for (int b = -1; b <= 1; ++b) {
            const int ii = i + a, jj = j + b;
            if (ii < 0 || jj < 0 || ii > n || jj > n || (a == 0 && b == 0)) continue;
            if (f[ii * (n + 1) + jj] < v) {
              is_min = false;
              break;
            }
          }
        if (is_min) minima.push_back({v, i * (n + 1) + j});
      }
    std::sort(minima.begin(), minima.end());
    for (std::size_t k = 0; k < std::min<std::size_t>(6, minima.size()); ++k)
      compass(face, q, at(minima[k].second / (n + 1), minima[k].second % (n + 1)), d.width_u() / n,
              fi, best);
    // Trim loops: dense samples per segment, golden section around the best.
    for (const UvLoop& loop : face.trim().loops())
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
        const int m = 40;
        int best_s = 0;
        double best_f = std::numeric_limits<double>::infinity();
        for (int s = 0; s <= m; ++s) {
          const Eigen::Vector2d p = a + (static_cast<double>(s) / m) * (b - a);
          const double v = (face.surface().point(p.x(), p.y()) - q).norm();
          if (v < best_f) {
            best_f = v;
            best_s = s;
          }
        }
        golden(face, q, a, b, std::max(0, best_s - 1) / double(m),
               std::min(m, best_s + 1) / double(m), fi, best);
      }
  }
  return best;
}

}  // namespace furrow::test
