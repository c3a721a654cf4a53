#pragma once
// Seeded random NURBS surfaces for property tests: any degree, clamped or
// unclamped knots, random interior knots (some repeated), random weights.
#include <algorithm>
#include <random>
#include <vector>

#include "geometry/nurbs_surface.hpp"

namespace furrow::test {

inline std::vector<double> random_knots(std::mt19937& rng, int degree, int count, bool clamped) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int total = count + degree + 1;
  std::vector<double> knots;
  if (clamped) {
    knots.assign(degree + 1, 0.0);
    std::vector<double> interior;
    for (int k = 0; k < count - degree - 1; ++k) interior.push_back(0.05 + 0.9 * unit(rng));
    std::sort(interior.begin(), interior.end());
    // Repeat one interior knot (multiplicity 2 <= degree) now and then.
    if (degree >= 2 && interior.size() >= 2 && unit(rng) < 0.5) interior[1] = interior[0];
    knots.insert(knots.end(), interior.begin(), interior.end());
    knots.insert(knots.end(), degree + 1, 1.0);
  } else {
    double t = -0.3 * unit(rng);
    for (int k = 0; k < total; ++k) {
      knots.push_back(t);
      t += 0.1 + unit(rng);
    }
  }
  return knots;
}

inline NurbsSurface random_surface(std::mt19937& rng, int degree_u, int degree_v, bool clamped,
                                   bool rational) {
  std::uniform_int_distribution<int> extra(0, 4);
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  std::uniform_real_distribution<double> weight(0.4, 2.5);
  const int nu = degree_u + 1 + extra(rng);
  const int nv = degree_v + 1 + extra(rng);
  std::vector<std::vector<Eigen::Vector3d>> net(nu, std::vector<Eigen::Vector3d>(nv));
  std::vector<std::vector<double>> weights(nu, std::vector<double>(nv, 1.0));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      // A wavy height field over a grid keeps the patch regular (no folds).
      net[i][j] = Eigen::Vector3d(20.0 * i + 0.2 * coord(rng), 20.0 * j + 0.2 * coord(rng),
                                  0.3 * coord(rng));
      if (rational) weights[i][j] = weight(rng);
    }
  return NurbsSurface(degree_u, degree_v, random_knots(rng, degree_u, nu, clamped),
                      random_knots(rng, degree_v, nv, clamped), net, weights);
}

// A parameter inside the domain at least `margin` (relative) away from every
// knot, so finite differences do not straddle a discontinuity.
inline double parameter_away_from_knots(std::mt19937& rng, const std::vector<double>& knots,
                                        double lo, double hi, double margin) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const double t = lo + (hi - lo) * (0.02 + 0.96 * unit(rng));
    bool clear = true;
    for (double k : knots)
      if (std::abs(k - t) < margin * (hi - lo)) clear = false;
    if (clear) return t;
  }
  return 0.5 * (lo + hi);
}

}  // namespace furrow::test
