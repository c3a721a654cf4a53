#include "geometry/differential_geometry.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace furrow {

double DifferentialGeometry::normal_curvature(const Eigen::Vector3d& t) const {
  if (degenerate) return 0.0;
  const double a = t.dot(d1), b = t.dot(d2);
  const double len2 = a * a + b * b;
  if (!(len2 > 0.0)) return 0.0;
  return (k1 * a * a + k2 * b * b) / len2;
}

double typical_derivative_scale(const NurbsSurface& surface) {
  const double diag = surface.control_box().diagonal().norm();
  const ParameterDomain& dom = surface.domain();
  return diag * diag / (dom.width_u() * dom.width_v());
}

DifferentialGeometry differential_geometry(const SurfaceDerivatives& d, bool reversed,
                                           double derivative_scale) {
  DifferentialGeometry g;
  g.point = d.S;
  const Eigen::Vector3d cross = d.Su.cross(d.Sv);
  const double cross_norm = cross.norm();
  g.area_element = cross_norm;
  const double scale = std::max(d.Su.norm() * d.Sv.norm(), derivative_scale);
  if (!(cross_norm > kDegenerateRelativeTolerance * scale) || !d.Suu.allFinite() ||
      !d.Suv.allFinite() || !d.Svv.allFinite()) {
    g.degenerate = true;
    return g;
  }
  g.degenerate = false;
  g.normal = cross / cross_norm;
  if (reversed) g.normal = -g.normal;
  g.E = d.Su.dot(d.Su);
  g.F = d.Su.dot(d.Sv);
  g.G = d.Sv.dot(d.Sv);
  g.L = d.Suu.dot(g.normal);
  g.M = d.Suv.dot(g.normal);
  g.N = d.Svv.dot(g.normal);

  // Orthonormal tangent frame (e1, e2) with e1 along Su. Expressing e1, e2 in
  // (du, dv) coordinates turns the shape operator into a symmetric 2x2 matrix
  // B_ij = II(e_i, e_j), whose eigen-decomposition is well conditioned even at
  // umbilics (it then returns an orthonormal pair, never NaN).
  const double su_len = std::sqrt(g.E);
  const Eigen::Vector3d e1 = d.Su / su_len;
  const Eigen::Vector3d e2 = g.normal.cross(e1);
  // e1 = c1.(Su, Sv), e2 = c2.(Su, Sv); solve the Gram system for c2.
  const Eigen::Vector2d c1(1.0 / su_len, 0.0);
  Eigen::Matrix2d gram;
  gram << g.E, g.F, g.F, g.G;
  const Eigen::Vector2d c2 = gram.inverse() * Eigen::Vector2d(e2.dot(d.Su), e2.dot(d.Sv));
  Eigen::Matrix2d second;
  second << g.L, g.M, g.M, g.N;
  Eigen::Matrix2d B;
  B(0, 0) = c1.dot(second * c1);
  B(0, 1) = B(1, 0) = c1.dot(second * c2);
  B(1, 1) = c2.dot(second * c2);

  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig;
  eig.computeDirect(B);
  // Eigen sorts ascending: k2 first.
  g.k2 = eig.eigenvalues()(0);
  g.k1 = eig.eigenvalues()(1);
  const Eigen::Vector2d a1 = eig.eigenvectors().col(1);
  g.d1 = (a1(0) * e1 + a1(1) * e2).normalized();
  g.d2 = g.normal.cross(g.d1);
  // "+ 0.0" turns -0.0 into +0.0 so that outputs never print "-0".
  g.k1 += 0.0;
  g.k2 += 0.0;
  g.K = g.k1 * g.k2 + 0.0;
  g.H = 0.5 * (g.k1 + g.k2) + 0.0;
  return g;
}

DifferentialGeometry differential_geometry(const NurbsSurface& surface, double u, double v,
                                           bool reversed) {
  return differential_geometry(surface.evaluate(u, v, 2), reversed,
                               typical_derivative_scale(surface));
}

}  // namespace furrow
