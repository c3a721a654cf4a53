#pragma once
// Area of a trimmed face to near machine precision, as a test oracle.
//
// Green's theorem turns the area integral over the kept region R into line
// integrals along the trim loops:  area = ∬_R a(s,t) ds dt = ∮ F(s,t) dt with
// a = |Su x Sv| and F(s,t) = ∫_{s0}^{s} a(σ,t) dσ. Both integrals are
// Gauss-Legendre, split at every knot line the path crosses (a is smooth only
// inside knot spans), so the result is exact for the polygonal region up to
// quadrature error far below 1e-9 relative: the only difference from the true
// face's area is the trim polygon's own distance from the true boundary.
// Even-odd loops: each loop's integral is signed by its orientation; its
// magnitude counts with the sign (-1)^depth, depth = number of loops around it
// (loops may touch but not cross).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/part.hpp"

namespace furrow::test {

namespace trimmed_area_detail {

// Gauss-Legendre nodes/weights on [-1, 1], 8 points.
constexpr double kNodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                              -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                              0.7966664774136267,  0.9602898564975363};
constexpr double kWeights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};

// Integral of f over [a, b] (either order): Gauss-Legendre on every piece
// between the breakpoints inside the range, each piece cut in `parts(length)`
// equal parts.
template <class Fn, class Parts>
double gauss(double a, double b, const std::vector<double>& breaks, Parts parts, Fn f) {
  std::vector<double> cuts{a};
  for (double k : breaks)
    if (k > std::min(a, b) && k < std::max(a, b)) cuts.push_back(k);
  cuts.push_back(b);
  std::sort(cuts.begin(), cuts.end());
  if (b < a) std::reverse(cuts.begin(), cuts.end());
  double sum = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const int n = parts(std::abs(cuts[c + 1] - cuts[c]));
    for (int p = 0; p < n; ++p) {
      const double x0 = cuts[c] + (cuts[c + 1] - cuts[c]) * p / n;
      const double x1 = cuts[c] + (cuts[c + 1] - cuts[c]) * (p + 1) / n;
      const double half = 0.5 * (x1 - x0), mid = 0.5 * (x0 + x1);
      for (int g = 0; g < 8; ++g) sum += kWeights[g] * half * f(mid + half * kNodes[g]);
    }
  }
  return sum;
}

inline bool in_polygon(const UvLoop& loop, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t k = 0, n = loop.size(); k < n; ++k) {
    const Eigen::Vector2d& a = loop[k];
    const Eigen::Vector2d& b = loop[(k + 1) % n];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()) > p.x())
      inside = !inside;
  }
  return inside;
}

inline double distance_to_polygon(const UvLoop& loop, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0, n = loop.size(); k < n; ++k) {
    const Eigen::Vector2d a = loop[k], ab = loop[(k + 1) % n] - a;
    const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

}  // namespace trimmed_area_detail

// Area [mm^2] of the face's kept region (the whole domain when untrimmed).
inline double trimmed_area(const Face& face) {
  using namespace trimmed_area_detail;
  const NurbsSurface& s = face.surface();
  const ParameterDomain& d = s.domain();
  const std::vector<double>& ks = s.knots_u();
  const std::vector<double>& kt = s.knots_v();
  auto element = [&](double u, double v) {
    const SurfaceDerivatives e = s.evaluate(u, v, 1);
    return e.Su.cross(e.Sv).norm();
  };
  // Inner integrals: 2 parts per knot span (16 points). Outer, along a
  // polygon edge: parts in proportion to the edge's share of the domain, so
  // the long edges of an untrimmed rectangle get as many points as the many
  // short edges of a dense trim loop.
  auto inner_parts = [](double) { return 2; };
  auto outer_parts = [](double fraction) {
    return std::max(1, static_cast<int>(std::ceil(16 * fraction)));
  };
  auto F = [&](double u, double v) {
    return gauss(d.u0, u, ks, inner_parts, [&](double x) { return element(x, v); });
  };
  // ∮ F dt along one closed polygon.
  auto loop_integral = [&](const UvLoop& loop) {
    double total = 0;
    for (std::size_t k = 0, n = loop.size(); k < n; ++k) {
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % n];
      if (a.y() == b.y()) continue;  // dt = 0
      // Parameter λ in [0,1]; breakpoints where the edge crosses knot lines.
      std::vector<double> breaks;
      for (double knot : ks)
        if (a.x() != b.x()) breaks.push_back((knot - a.x()) / (b.x() - a.x()));
      for (double knot : kt) breaks.push_back((knot - a.y()) / (b.y() - a.y()));
      const double share = std::max(std::abs(b.x() - a.x()) / d.width_u(),
                                    std::abs(b.y() - a.y()) / d.width_v());
      total += gauss(0.0, 1.0, breaks, [&](double piece) { return outer_parts(piece * share); },
                     [&](double l) {
        const Eigen::Vector2d p = a + l * (b - a);
        return F(p.x(), p.y()) * (b.y() - a.y());
      });
    }
    return total;
  };
  std::vector<UvLoop> loops = face.trim().loops();
  if (loops.empty()) loops.push_back({{d.u0, d.v0}, {d.u1, d.v0}, {d.u1, d.v1}, {d.u0, d.v1}});
  double area = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    // The nesting depth is read at the loop's vertex farthest from the other
    // loops (loops may touch, e.g. along the domain's edge).
    Eigen::Vector2d probe = loops[l][0];
    double clearance = -1;
    const std::size_t stride = std::max<std::size_t>(1, loops[l].size() / 64);
    for (std::size_t k = 0; k < loops[l].size(); k += stride) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t m = 0; m < loops.size(); ++m)
        if (m != l) nearest = std::min(nearest, distance_to_polygon(loops[m], loops[l][k]));
      if (nearest > clearance) {
        clearance = nearest;
        probe = loops[l][k];
      }
    }
    int depth = 0;
    for (std::size_t m = 0; m < loops.size(); ++m)
      if (m != l && in_polygon(loops[m], probe)) ++depth;
    area += (depth % 2 == 0 ? 1 : -1) * std::abs(loop_integral(loops[l]));
  }
  return area;
}

}  // namespace furrow::test
