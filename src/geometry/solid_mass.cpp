#include "geometry/solid_mass.hpp"

#include <array>
#include <cmath>

namespace furrow {

namespace {

constexpr int kCells = 48, kSubcells = 6;

// Sums over a face: [V, V c_x, V c_y, V c_z] contributions, area, vector area.
struct Sums {
  double volume = 0, area = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero(), vector_area = Eigen::Vector3d::Zero();
  void add(const Eigen::Vector3d& x, const Eigen::Vector3d& ndA) {  // ndA: outward normal times the area element
    volume += x.dot(ndA) / 3;
    moment += 0.5 * x.cwiseProduct(x).cwiseProduct(ndA);
    area += ndA.norm();
    vector_area += ndA;
  }
};

void add_point(const Face& face, double sign, double u, double v, double weight, Sums& sums) {
  const SurfaceDerivatives d = face.surface().evaluate(u, v, 1);
  sums.add(d.S, sign * weight * d.Su.cross(d.Sv));
}

}  // namespace

SolidMass solid_mass(const Part& part) {
  Sums sums;
  const double g = 0.5 / std::sqrt(3.0);  // Gauss-Legendre nodes at the cell centre -+ g * width
  for (const Face& face : part.faces) {
    const ParameterDomain& d = face.domain();
    const double du = d.width_u() / kCells, dv = d.width_v() / kCells;
    const double sign = face.reversed() ? -1 : 1;
    const Trim& trim = face.trim();
    const double half_diagonal = 0.5 * std::hypot(du, dv);
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j) {
        const double u0 = d.u0 + du * i, v0 = d.v0 + dv * j;
        const Eigen::Vector2d middle(u0 + du / 2, v0 + dv / 2);
        if (trim.empty() || !trim.edge_near(middle, half_diagonal * (1 + 1e-9))) {
          // Wholly in or wholly out of the trim.
          if (!trim.empty() && !trim.contains(middle)) continue;
          for (double a : {-g, g})
            for (double b : {-g, g}) add_point(face, sign, middle.x() + a * du, middle.y() + b * dv, du * dv / 4, sums);
          continue;
        }
        const double su = du / kSubcells, sv = dv / kSubcells;
        for (int a = 0; a < kSubcells; ++a)
          for (int b = 0; b < kSubcells; ++b) {
            const Eigen::Vector2d uv(u0 + su * (a + 0.5), v0 + sv * (b + 0.5));
            if (!trim.contains(uv)) continue;
            for (double p : {-g, g})
              for (double q : {-g, g}) add_point(face, sign, uv.x() + p * su, uv.y() + q * sv, su * sv / 4, sums);
          }
      }
  }
  SolidMass m;
  m.volume = sums.volume;
  m.area = sums.area;
  m.vector_area = sums.vector_area.norm();
  m.closed = m.volume > 0 && m.vector_area <= 1e-3 * m.area;
  if (m.volume > 0) m.centroid = sums.moment / m.volume;
  return m;
}

}  // namespace furrow
