#pragma once
// Reference geometry for cutter tests, written from docs/architecture.md's description
// of the end mill and not from the library's code: the corner surface as an
// explicit surface of revolution and its curvature by finite differences, a
// part's normal curvature straight from its fundamental forms, and the
// brute-force searches the tests compare with (a dense sweep of directions,
// a drop cutter by grid search).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/differential_geometry.hpp"

namespace furrow::test {

// Corner (torus) surface of an end mill with tip at the origin, axis +z:
// X(phi, theta) = rho(theta) (cos phi, sin phi, 0) + h(theta) z,
// rho = (R - r) + r sin(theta), h = r (1 - cos(theta)).
inline Eigen::Vector3d corner_point(double R, double r, double phi, double theta) {
  const double rho = (R - r) + r * std::sin(theta);
  return {rho * std::cos(phi), rho * std::sin(phi), r - r * std::cos(theta)};
}

struct FdCurvature {
  double k_max = 0, k_min = 0;
  Eigen::Vector3d dir_max, dir_min, normal;
  Eigen::Matrix2d I, II;
  Eigen::Vector3d Xp, Xt;
  // Normal curvature in a tangent direction t: II(c)/I(c) with t = J c.
  double along(const Eigen::Vector3d& t) const {
    Eigen::Matrix<double, 3, 2> J;
    J << Xp, Xt;
    const Eigen::Vector2d c = (J.transpose() * J).ldlt().solve(J.transpose() * t);
    return c.dot(II * c) / c.dot(I * c);
  }
};

// Curvature of the corner surface at (phi, theta) by central finite
// differences, in the part's sign convention: the normal is the part's (up,
// into the cutter), so the cutter's curvatures come out positive. dir_max is
// signed uphill (z >= 0), dir_min = normal x dir_max.
inline FdCurvature fd_corner_curvature(double R, double r, double phi, double theta) {
  const double h = 1e-4;
  auto X = [&](double p, double t) { return corner_point(R, r, p, t); };
  const Eigen::Vector3d Xp = (X(phi + h, theta) - X(phi - h, theta)) / (2 * h);
  const Eigen::Vector3d Xt = (X(phi, theta + h) - X(phi, theta - h)) / (2 * h);
  const Eigen::Vector3d Xpp = (X(phi + h, theta) - 2 * X(phi, theta) + X(phi - h, theta)) / (h * h);
  const Eigen::Vector3d Xtt = (X(phi, theta + h) - 2 * X(phi, theta) + X(phi, theta - h)) / (h * h);
  const Eigen::Vector3d Xpt = (X(phi + h, theta + h) - X(phi + h, theta - h) -
                               X(phi - h, theta + h) + X(phi - h, theta - h)) / (4 * h * h);
  FdCurvature c;
  Eigen::Vector3d n = Xp.cross(Xt).normalized();
  if (n.z() < 0) n = -n;
  c.normal = n;
  c.Xp = Xp;
  c.Xt = Xt;
  c.I << Xp.dot(Xp), Xp.dot(Xt), Xp.dot(Xt), Xt.dot(Xt);
  c.II << Xpp.dot(n), Xpt.dot(n), Xpt.dot(n), Xtt.dot(n);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(c.II, c.I);
  c.k_min = eig.eigenvalues()(0);
  c.k_max = eig.eigenvalues()(1);
  c.dir_min = (eig.eigenvectors()(0, 0) * Xp + eig.eigenvectors()(1, 0) * Xt).normalized();
  c.dir_max = (eig.eigenvectors()(0, 1) * Xp + eig.eigenvectors()(1, 1) * Xt).normalized();
  if (c.dir_max.z() < 0) c.dir_max = -c.dir_max;
  c.dir_min = n.cross(c.dir_max);
  return c;
}

// FD curvature of the cutter's corner at the contact whose part normal is n
// (n_z > 0, not vertical): the contact sits radially outward, opposite n_xy.
inline FdCurvature fd_cutter_at_normal(double R, double r, const Eigen::Vector3d& n) {
  const double phi = std::atan2(-n.y(), -n.x());
  const double theta = std::acos(n.z());
  return fd_corner_curvature(R, r, phi, theta);
}

// A part's normal curvature in tangent direction t from its first and second
// fundamental forms (no principal decomposition): t = a Su + b Sv solved by
// least squares, then II(a,b) / I(a,b).
inline double part_normal_curvature(const SurfaceDerivatives& d, const Eigen::Vector3d& normal,
                                    const Eigen::Vector3d& t) {
  Eigen::Matrix<double, 3, 2> J;
  J << d.Su, d.Sv;
  const Eigen::Vector2d c = (J.transpose() * J).ldlt().solve(J.transpose() * t);
  Eigen::Matrix2d I, II;
  I << d.Su.dot(d.Su), d.Su.dot(d.Sv), d.Su.dot(d.Sv), d.Sv.dot(d.Sv);
  II << d.Suu.dot(normal), d.Suv.dot(normal), d.Suv.dot(normal), d.Svv.dot(normal);
  return c.dot(II * c) / c.dot(I * c);
}

// Angles (degrees) where g changes sign around the circle: sampled every
// `step_deg` from an offset (so a boundary exactly at 0 is seen), each sign
// change refined by bisection.
template <class G>
std::vector<double> sign_changes_deg(G g, double step_deg) {
  std::vector<double> out;
  const double first = 0.37 * step_deg;
  const int n = static_cast<int>(std::lround(360.0 / step_deg));
  double prev = g(first);
  for (int k = 1; k <= n; ++k) {
    const double a = first + k * step_deg;
    const double cur = g(a);
    if ((prev > 0) != (cur > 0)) {
      double lo = a - step_deg, hi = a;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((g(mid) > 0) == (prev > 0) ? lo : hi) = mid;
      }
      out.push_back(std::fmod(0.5 * (lo + hi), 360.0));
    }
    prev = cur;
  }
  return out;
}

// Smallest difference of two angles in degrees.
inline double angle_gap_deg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

// Brute-force drop cutter over a disc of radius R: the largest value(rho,
// phi) (a surface height minus the cutter's envelope height at rho) by a
// polar grid, rim included, then zooming into the best cell repeatedly:
// derivative-free, independent of the library's Newton solvers.
template <class Value>
double maximize_over_disc(double R, Value value, int radii = 60, int angles = 180) {
  double best = -1e300, best_rho = 0, best_phi = 0;
  for (int i = 0; i <= radii; ++i)
    for (int k = 0; k < angles; ++k) {
      const double rho = R * i / radii, phi = 2 * M_PI * k / angles;
      const double v = value(rho, phi);
      if (v > best) best = v, best_rho = rho, best_phi = phi;
    }
  double dr = R / radii, dp = 2 * M_PI / angles;
  for (int level = 0; level < 24; ++level, dr *= 0.4, dp *= 0.4) {
    const double r0 = best_rho, p0 = best_phi;
    for (int i = -5; i <= 5; ++i)
      for (int k = -5; k <= 5; ++k) {
        const double rho = std::clamp(r0 + dr * i / 5, 0.0, R), phi = p0 + dp * k / 5;
        const double v = value(rho, phi);
        if (v > best) best = v, best_rho = rho, best_phi = phi;
      }
  }
  return best;
}

}  // namespace furrow::test
