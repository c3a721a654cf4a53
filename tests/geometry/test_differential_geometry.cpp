#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/differential_geometry.hpp"
#include "geometry/part.hpp"
#include "geometry/primitives.hpp"
#include "partition/classification.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

namespace {

void check_orthonormal_frame(const DifferentialGeometry& g) {
  CHECK(g.d1.norm() == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(g.d2.norm() == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(std::abs(g.d1.dot(g.d2)) < 1e-12);
  CHECK(std::abs(g.d1.dot(g.normal)) < 1e-12);
  CHECK(g.d1.cross(g.d2).dot(g.normal) == doctest::Approx(1.0).epsilon(1e-12));
}

}  // namespace

TEST_CASE("sphere: outward normal gives k1 = k2 = -1/R (convex), reversed gives +1/R") {
  const double R = 50.0;
  const Face outward("sphere", make_sphere(R, -2.0, 2.5, -1.3, 1.3));
  const Face inward("sphere_in", make_sphere(R, -2.0, 2.5, -1.3, 1.3), {}, true);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const double u = unit(rng), v = unit(rng);
    const DifferentialGeometry g = outward.geometry(u, v);
    REQUIRE_FALSE(g.degenerate);
    CHECK((g.normal - g.point / R).norm() < 1e-12);
    CHECK(g.k1 == doctest::Approx(-1 / R).epsilon(1e-9));
    CHECK(g.k2 == doctest::Approx(-1 / R).epsilon(1e-9));
    CHECK(g.K == doctest::Approx(1 / (R * R)).epsilon(1e-9));
    CHECK(g.H == doctest::Approx(-1 / R).epsilon(1e-9));
    check_orthonormal_frame(g);  // umbilic: still a frame, never NaN
    CHECK(classify_curvature(g.k1, g.k2, kDefaultCurvatureEps) == CurvatureClass::convex);
    const DifferentialGeometry h = inward.geometry(u, v);
    CHECK((h.normal + g.point / R).norm() < 1e-12);
    CHECK(h.k1 == doctest::Approx(1 / R).epsilon(1e-9));
    CHECK(h.k2 == doctest::Approx(1 / R).epsilon(1e-9));
    CHECK(classify_curvature(h.k1, h.k2, kDefaultCurvatureEps) == CurvatureClass::concave);
  }
}

TEST_CASE("cylinder: -1/R around, 0 along the axis, directions along the axis and the circle") {
  const double R = 25.4;
  const Face convex("cyl", make_cylinder(R, 50.8, 0.2, 2.9), {}, true);
  const Face concave("tube", make_cylinder(R, 50.8, 0.2, 2.9));
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    for (double v : {0.0, 0.4, 1.0}) {
      const DifferentialGeometry g = convex.geometry(u, v);
      REQUIRE_FALSE(g.degenerate);
      const Eigen::Vector3d radial(g.point.x(), 0, g.point.z());
      CHECK((g.normal - radial / R).norm() < 1e-12);
      CHECK(std::abs(g.k1) < 1e-9);
      CHECK(g.k2 == doctest::Approx(-1 / R).epsilon(1e-9));
      CHECK(std::abs(std::abs(g.d1.y()) - 1.0) < 1e-9);  // zero curvature along the axis
      CHECK(std::abs(g.d2.y()) < 1e-9);
      check_orthonormal_frame(g);
      CHECK(classify_curvature(g.k1, g.k2, kDefaultCurvatureEps) == CurvatureClass::convex);
      const DifferentialGeometry h = concave.geometry(u, v);
      CHECK(h.k1 == doctest::Approx(1 / R).epsilon(1e-9));
      CHECK(std::abs(h.k2) < 1e-9);
      CHECK(std::abs(h.d1.y()) < 1e-9);
      CHECK(classify_curvature(h.k1, h.k2, kDefaultCurvatureEps) == CurvatureClass::concave);
      // Normal curvature in any direction follows Euler's formula.
      for (double a = 0; a < M_PI; a += 0.3) {
        const Eigen::Vector3d t = std::cos(a) * g.d1 + std::sin(a) * g.d2;
        CHECK(g.normal_curvature(t) ==
              doctest::Approx(-std::sin(a) * std::sin(a) / R).epsilon(1e-9).scale(1 / R));
      }
    }
  }
}

TEST_CASE("the saddle z = xy has k1 = 1, k2 = -1 at the origin along the diagonals") {
  const Face saddle("saddle", make_bilinear({-1, -1, 1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, 1}));
  const DifferentialGeometry g = saddle.geometry(0.5, 0.5);
  REQUIRE_FALSE(g.degenerate);
  CHECK(g.point.norm() < 1e-15);
  CHECK((g.normal - Eigen::Vector3d::UnitZ()).norm() < 1e-15);
  CHECK(g.k1 == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(g.k2 == doctest::Approx(-1.0).epsilon(1e-12));
  CHECK(g.K == doctest::Approx(-1.0).epsilon(1e-12));
  CHECK(std::abs(g.H) < 1e-12);
  CHECK(std::abs(std::abs(g.d1.dot(Eigen::Vector3d(1, 1, 0).normalized())) - 1) < 1e-12);
  CHECK(std::abs(std::abs(g.d2.dot(Eigen::Vector3d(1, -1, 0).normalized())) - 1) < 1e-12);
  check_orthonormal_frame(g);
  CHECK(classify_curvature(g.k1, g.k2, kDefaultCurvatureEps) == CurvatureClass::saddle);
}

TEST_CASE("a plane has zero curvatures and is planar") {
  const Face plane("plane", make_plane({1, 2, 3}, {40, 0, 5}, {0, 30, 0}));
  for (double u : {0.0, 0.3, 1.0}) {
    const DifferentialGeometry g = plane.geometry(u, 0.6);
    REQUIRE_FALSE(g.degenerate);
    CHECK(g.k1 == 0.0);
    CHECK(g.k2 == 0.0);
    CHECK(g.K == 0.0);
    CHECK(g.H == 0.0);
    CHECK((g.normal - Eigen::Vector3d(-5, 0, 40).normalized()).norm() < 1e-15);
    check_orthonormal_frame(g);
    CHECK(classify_curvature(g.k1, g.k2, kDefaultCurvatureEps) == CurvatureClass::planar);
  }
}

TEST_CASE("fundamental forms agree with the textbook formulas on random surfaces") {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const NurbsSurface s = test::random_surface(rng, 1 + trial % 4, 1 + (trial / 4) % 4, trial % 2, trial % 3 == 0);
    const double u = s.domain().u0 + s.domain().width_u() * unit(rng);
    const double v = s.domain().v0 + s.domain().width_v() * unit(rng);
    const SurfaceDerivatives d = s.evaluate(u, v);
    const DifferentialGeometry g = differential_geometry(s, u, v, false);
    REQUIRE_FALSE(g.degenerate);
    const double det = g.E * g.G - g.F * g.F;
    const double K = (g.L * g.N - g.M * g.M) / det;
    const double H = (g.E * g.N - 2 * g.F * g.M + g.G * g.L) / (2 * det);
    const double scale = std::abs(g.k1) + std::abs(g.k2) + 1e-12;
    CHECK(g.K == doctest::Approx(K).epsilon(1e-9).scale(scale * scale));
    CHECK(g.H == doctest::Approx(H).epsilon(1e-9).scale(scale));
    CHECK(g.k1 >= g.k2);
    check_orthonormal_frame(g);
    // II(t)/I(t) for a tangent t = a Su + b Sv against normal_curvature(t).
    for (int k = 0; k < 5; ++k) {
      const double a = unit(rng) - 0.5, b = unit(rng) - 0.5;
      const double I = g.E * a * a + 2 * g.F * a * b + g.G * b * b;
      const double II = g.L * a * a + 2 * g.M * a * b + g.N * b * b;
      CHECK(g.normal_curvature(a * d.Su + b * d.Sv) == doctest::Approx(II / I).epsilon(1e-8).scale(scale));
    }
    // Principal directions are eigen-directions: normal curvature along d1 is k1.
    CHECK(g.normal_curvature(g.d1) == doctest::Approx(g.k1).epsilon(1e-9).scale(scale));
  }
}

TEST_CASE("a collapsed edge (sphere pole) is reported degenerate, never as garbage") {
  const Face cap("cap", make_sphere(10.0, 0.0, 1.5, 0.3, M_PI / 2));
  const DifferentialGeometry pole = cap.geometry(0.4, 1.0);
  CHECK(pole.degenerate);
  CHECK(pole.K == 0.0);
  CHECK(pole.normal.allFinite());
  CHECK(pole.normal_curvature(Eigen::Vector3d::UnitX()) == 0.0);
  // Just off the pole the point is regular and exact again.
  const DifferentialGeometry near = cap.geometry(0.4, 0.999);
  REQUIRE_FALSE(near.degenerate);
  CHECK(near.k1 == doctest::Approx(-0.1).epsilon(1e-6).scale(0));
  // Parallel tangents: a patch folded onto a line.
  const Face line("line", make_bilinear({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}));
  CHECK(line.geometry(0.5, 0.5).degenerate);
}
