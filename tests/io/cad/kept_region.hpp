#pragma once
// What a trimmed face keeps, measured on a grid of its domain, as oracles for
// the CAD import tests: the centroid of the kept region, the share of kept
// points at which something holds, and the integral of the unit normal.
// Each is a midpoint rule over the cells whose centre the trim keeps, so it
// is independent of the importer's own trim polygons' area computation.
#include <cmath>

#include <Eigen/Core>

#include "geometry/part.hpp"

namespace furrow::test {

// Centroid of the kept region of a face by the midpoint rule on an n x n
// grid of its domain, weighted by the area element: within ~1e-3 of the
// radius for the sphere patches of the tests, while a face that came in as
// the rest of the sphere has its centroid on the other side.
inline Eigen::Vector3d kept_centroid(const Face& f, int n = 240) {
  const ParameterDomain& d = f.domain();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d st(d.u0 + d.width_u() * (i + 0.5) / n, d.v0 + d.width_v() * (j + 0.5) / n);
      if (!f.trim().empty() && !f.trim().contains(st)) continue;
      const SurfaceDerivatives e = f.surface().evaluate(st.x(), st.y(), 1);
      const double w = e.Su.cross(e.Sv).norm();
      sum += w * e.S;
      weight += w;
    }
  return weight > 0 ? Eigen::Vector3d(sum / weight) : Eigen::Vector3d::Constant(std::nan(""));
}

// Share of a grid of kept points of the face (where it has a normal) at
// which `holds` does; 0 when the grid keeps none.
template <class Predicate>
double kept_share(const Face& f, Predicate holds, int n = 24) {
  const ParameterDomain& d = f.domain();
  int yes = 0, total = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d st(d.u0 + d.width_u() * (i + 0.5) / n, d.v0 + d.width_v() * (j + 0.5) / n);
      if (!f.trim().empty() && !f.trim().contains(st)) continue;
      const DifferentialGeometry g = f.geometry(st.x(), st.y());
      if (g.degenerate) continue;
      ++total;
      yes += holds(g);
    }
  return total == 0 ? 0.0 : static_cast<double>(yes) / total;
}

// Integral of the unit normal (Face::reversed() applied) over the kept
// region, by the midpoint rule on a grid of the domain: the same region
// with the same orientation gives the same vector, the other orientation
// its negative.
inline Eigen::Vector3d normal_integral(const Face& f, int n = 160) {
  const ParameterDomain& d = f.domain();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const double cell = d.width_u() * d.width_v() / (n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d st(d.u0 + d.width_u() * (i + 0.5) / n, d.v0 + d.width_v() * (j + 0.5) / n);
      if (!f.trim().empty() && !f.trim().contains(st)) continue;
      const DifferentialGeometry g = f.geometry(st.x(), st.y());
      if (!g.degenerate) sum += g.normal * g.area_element * cell;
    }
  return sum;
}

// Flux of the position field about `q` through the kept region:
// {integral of n . (p - q), integral of |p - q|} over it (n with
// Face::reversed() applied), by the same midpoint rule. The first turns
// sign with the face's orientation where the normal integral may vanish
// (a ball's face with two opposite holes); the second is its scale.
inline Eigen::Vector2d position_flux(const Face& f, const Eigen::Vector3d& q, int n = 100) {
  const ParameterDomain& d = f.domain();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  const double cell = d.width_u() * d.width_v() / (n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d st(d.u0 + d.width_u() * (i + 0.5) / n, d.v0 + d.width_v() * (j + 0.5) / n);
      if (!f.trim().empty() && !f.trim().contains(st)) continue;
      const DifferentialGeometry g = f.geometry(st.x(), st.y());
      if (g.degenerate) continue;
      sum += Eigen::Vector2d(g.normal.dot(g.point - q), (g.point - q).norm()) * g.area_element * cell;
    }
  return sum;
}

}  // namespace furrow::test
