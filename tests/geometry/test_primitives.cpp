#include <doctest/doctest.h>

#include <cmath>

#include "geometry/part.hpp"
#include "geometry/primitives.hpp"

using namespace furrow;

TEST_CASE("circular arcs of any sweep are exact and split into at most 90 degree pieces") {
  for (double sweep : {0.3, M_PI / 2, 2.0, M_PI, 4.0, 2 * M_PI, -1.0}) {
    const RationalCurve2d arc = make_circular_arc(7.0, 0.4, 0.4 + sweep);
    const int pieces = static_cast<int>((arc.points.size() - 1) / 2);
    CHECK(std::abs(sweep) / pieces <= M_PI / 2 + 1e-12);
    // Extrude to a surface to evaluate with the NURBS evaluator.
    const NurbsSurface s = make_cylinder(7.0, 1.0, 0.4, 0.4 + sweep);
    for (int k = 0; k <= 50; ++k) {
      const Eigen::Vector3d p = s.point(k / 50.0, 0.5);
      CHECK(std::hypot(p.x(), p.z()) == doctest::Approx(7.0).epsilon(1e-12));
    }
    const Eigen::Vector3d end = s.point(1.0, 0.0);
    CHECK(std::atan2(end.z(), end.x()) == doctest::Approx(std::remainder(0.4 + sweep, 2 * M_PI)).epsilon(1e-12).scale(1));
  }
}

TEST_CASE("torus patch: points on the torus, outer equator convex, inner equator saddle") {
  const double Rm = 30, r = 8;
  const Face torus("torus", make_torus(Rm, r, 0.0, 2 * M_PI, 0.0, 2 * M_PI));
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) {
      const Eigen::Vector3d p = torus.surface().point(i / 16.0, j / 16.0);
      const double q = std::hypot(p.x(), p.y()) - Rm;
      CHECK(std::hypot(q, p.z()) == doctest::Approx(r).epsilon(1e-12));
    }
  const DifferentialGeometry outer = torus.geometry(0.1, 0.0);  // psi = 0
  CHECK(outer.k2 == doctest::Approx(-1 / r).epsilon(1e-9));
  CHECK(outer.k1 == doctest::Approx(-1 / (Rm + r)).epsilon(1e-9));
  const DifferentialGeometry inner = torus.geometry(0.1, 0.5);  // psi = pi
  CHECK(inner.k2 == doctest::Approx(-1 / r).epsilon(1e-9));
  CHECK(inner.k1 == doctest::Approx(1 / (Rm - r)).epsilon(1e-9));
}

TEST_CASE("a moved surface is the same surface moved") {
  const NurbsSurface s = make_sphere(5.0, 0.0, 1.0, 0.0, 1.0);
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  m.pretranslate(Eigen::Vector3d(10, -4, 2));
  const NurbsSurface t = transformed(s, m);
  for (double u : {0.0, 0.37, 1.0})
    for (double v : {0.0, 0.5, 0.9}) CHECK((t.point(u, v) - m * s.point(u, v)).norm() < 1e-12);
}
