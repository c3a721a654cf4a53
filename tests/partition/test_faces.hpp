#pragma once
// Faces with known curvature for the partition tests, and an independent
// area quadrature to check region areas against.
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "geometry/nurbs_surface.hpp"

namespace furrow::test {

// Bicubic Bezier patch over [0, X] x [0, Y] that is exactly the height field
// z = A(x) + B(y), A and B cubic. `a` and `b` are the power coefficients of
// A(X t) and B(Y s) in t, s in [0, 1]. Bernstein coefficients of a cubic
// c0 + c1 t + c2 t^2 + c3 t^3 are c0, c0 + c1/3, c0 + 2c1/3 + c2/3,
// c0 + c1 + c2 + c3; x and y are linear in t and s, so the patch reproduces
// the height field exactly (partition of unity lets the two sums add).
inline NurbsSurface separable_cubic_patch(double X, double Y, const std::array<double, 4>& a,
                                          const std::array<double, 4>& b) {
  auto bernstein = [](const std::array<double, 4>& c) {
    return std::array<double, 4>{c[0], c[0] + c[1] / 3, c[0] + 2 * c[1] / 3 + c[2] / 3,
                                 c[0] + c[1] + c[2] + c[3]};
  };
  const auto ba = bernstein(a), bb = bernstein(b);
  std::vector<std::vector<Eigen::Vector3d>> net(4, std::vector<Eigen::Vector3d>(4));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) net[i][j] = {X * i / 3.0, Y * j / 3.0, ba[i] + bb[j]};
  const std::vector<double> k{0, 0, 0, 0, 1, 1, 1, 1};
  return NurbsSurface(3, 3, k, k, net);
}

// Power coefficients (in t = x / X) of alpha (x - x0)^3.
inline std::array<double, 4> shifted_cube(double alpha, double x0, double X) {
  return {-alpha * x0 * x0 * x0, 3 * alpha * X * x0 * x0, -3 * alpha * X * X * x0,
          alpha * X * X * X};
}

inline std::vector<double> clamped_uniform_knots(int count, int degree) {
  std::vector<double> k(static_cast<std::size_t>(degree) + 1, 0.0);
  const int spans = count - degree;
  for (int s = 1; s < spans; ++s) k.push_back(static_cast<double>(s) / spans);
  k.insert(k.end(), static_cast<std::size_t>(degree) + 1, 1.0);
  return k;
}

// Bicubic B-spline over [0, X] x [0, Y] with n x n control points placed at
// the Greville abscissae (so x and y are exactly linear) and heights
// z(x, y): a smooth approximation of the height field.
inline NurbsSurface height_field_patch(double X, double Y, int n,
                                       const std::function<double(double, double)>& z) {
  const std::vector<double> k = clamped_uniform_knots(n, 3);
  std::vector<double> g(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) g[i] = (k[i + 1] + k[i + 2] + k[i + 3]) / 3.0;
  std::vector<std::vector<Eigen::Vector3d>> net(n, std::vector<Eigen::Vector3d>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) net[i][j] = {X * g[i], Y * g[j], z(X * g[i], Y * g[j])};
  return NurbsSurface(3, 3, k, k, net);
}

// Composite Simpson rule over [x0, x1] x [y0, y1] with n (even) intervals per
// direction: error O(h^4), independent of the partition's midpoint cells.
inline double simpson2d(const std::function<double(double, double)>& f, double x0, double x1,
                        double y0, double y1, int n = 400) {
  const double hx = (x1 - x0) / n, hy = (y1 - y0) / n;
  auto weight = [n](int k) { return (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0); };
  double sum = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) sum += weight(i) * weight(j) * f(x0 + i * hx, y0 + j * hy);
  return sum * hx * hy / 9.0;
}

}  // namespace furrow::test
