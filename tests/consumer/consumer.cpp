// Uses only installed public headers: a cylinder of radius 25 built as an
// exact rational NURBS must show principal curvatures 0 and -1/25 (convex,
// normal out of the material) at every sampled point; exits 0 when it does.
#include <cmath>
#include <cstdio>

#include "geometry/differential_geometry.hpp"
#include "geometry/primitives.hpp"

int main() {
  const double radius = 25.0;
  const furrow::NurbsSurface cylinder = furrow::make_cylinder(radius, 40.0, 0.0, 2.0);
  int bad = 0;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double u = cylinder.domain().u0 + (cylinder.domain().u1 - cylinder.domain().u0) * i / 4.0;
      const double v = cylinder.domain().v0 + (cylinder.domain().v1 - cylinder.domain().v0) * j / 4.0;
      const furrow::DifferentialGeometry g = furrow::differential_geometry(cylinder, u, v, false);
      const double k_round = std::abs(g.k1) > std::abs(g.k2) ? g.k1 : g.k2;
      const double k_flat = std::abs(g.k1) > std::abs(g.k2) ? g.k2 : g.k1;
      if (std::abs(std::abs(k_round) - 1 / radius) > 1e-12 || std::abs(k_flat) > 1e-12) ++bad;
    }
  std::printf("furrow %s consumer: %d of 25 points off the analytic curvature\n", FURROW_VERSION, bad);
  return bad == 0 ? 0 : 1;
}
