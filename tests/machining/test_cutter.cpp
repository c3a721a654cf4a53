#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_curvature.hpp"
#include "cutter_reference.hpp"

using namespace furrow;

using namespace furrow::test;

TEST_CASE("cutter: ball, flat and bull-nose are values of R and r") {
  CHECK(Cutter("b", 5, 5).type() == ToolType::ball);
  CHECK(Cutter("f", 5, 0).type() == ToolType::flat);
  CHECK(Cutter("t", 5, 1).type() == ToolType::bull);
  const Cutter bull("t", 5, 1.5);
  CHECK(bull.flat_radius() == 3.5);
  CHECK(bull.corner().centre_rho == 3.5);
  CHECK(bull.corner().centre_h == 1.5);
  CHECK(bull.spec().diameter == 10);
  CHECK(bull.spec().type == ToolType::bull);
  CHECK_THROWS_WITH_AS(Cutter("x", 3, 4), doctest::Contains("corner radius 4 exceeds the cutter radius 3"), InputError);
  CHECK_THROWS_WITH_AS(Cutter("x", -3, 0), doctest::Contains("radius must be positive"), InputError);
  CHECK_THROWS_WITH_AS(Cutter("x", 3, -1), doctest::Contains("must not be negative"), InputError);
  CHECK_THROWS_AS(Cutter("x", std::nan(""), 0), InputError);
}

TEST_CASE("cutter: the lower envelope is the profile (flat, torus arc, open beyond R)") {
  for (const auto& [R, r] : {std::pair{6.0, 6.0}, {6.0, 0.0}, {6.0, 2.0}, {4.0, 0.5}}) {
    const Cutter c("c", R, r);
    CAPTURE(R);
    CAPTURE(r);
    for (int k = 0; k <= 400; ++k) {
      const double rho = R * k / 400.0;
      const double h = c.height_at(rho);
      if (rho <= R - r) {
        CHECK(h == 0.0);
        CHECK(c.slope_at(rho) == 0.0);
      } else {
        // On the arc's circle (rho - (R - r))^2 + (h - r)^2 = r^2, lower half.
        const double d = rho - (R - r);
        CHECK(d * d + (h - r) * (h - r) == doctest::Approx(r * r).epsilon(1e-12));
        CHECK(h <= r + 1e-15);
        if (rho < R) {
          // Slope from a central difference of the envelope.
          const double dh = 1e-7;
          if (rho - dh > R - r && rho + dh < R)
            CHECK(c.slope_at(rho) == doctest::Approx((c.height_at(rho + dh) - c.height_at(rho - dh)) / (2 * dh)).epsilon(1e-5));
        }
      }
    }
    CHECK(c.height_at(R) == doctest::Approx(r));
    CHECK(std::isinf(c.height_at(R * 1.0001)));
  }
}

TEST_CASE("cutter curvature: formulas agree with finite differences of the torus surface") {
  // Bull-nose and ball at several contact angles theta0 and azimuths.
  for (const auto& [R, r] : {std::pair{5.0, 1.5}, {5.0, 5.0}, {8.0, 0.8}}) {
    const Cutter cutter("c", R, r);
    for (double theta0_deg : {3.0, 15.0, 30.0, 45.0, 60.0, 75.0, 88.0}) {
      for (double azimuth : {0.0, 1.1, 2.5, 4.0}) {
        CAPTURE(R);
        CAPTURE(r);
        CAPTURE(theta0_deg);
        const double theta0 = theta0_deg * M_PI / 180;
        // Part normal tilted by theta0 with horizontal part along e (toward
        // the axis). The contact sits at azimuth phi = azimuth + pi on the
        // cutter (radially outward = -e).
        const Eigen::Vector3d e(std::cos(azimuth), std::sin(azimuth), 0);
        const Eigen::Vector3d n = std::sin(theta0) * e + std::cos(theta0) * Eigen::Vector3d::UnitZ();
        const FdCurvature fd = fd_corner_curvature(R, r, azimuth + M_PI, theta0);
        REQUIRE((fd.normal - n).norm() < 1e-7);

        const CutterCurvature c = cutter_curvature(cutter, n);
        REQUIRE(c.reachable);
        CHECK_FALSE(c.sharp);
        CHECK_FALSE(c.flat_bottom);
        CHECK(c.k_max == doctest::Approx(fd.k_max).epsilon(1e-5));
        CHECK(c.k_min == doctest::Approx(fd.k_min).epsilon(1e-5));
        CHECK(c.k_max == doctest::Approx(1 / r).epsilon(1e-12));
        CHECK(c.k_min == doctest::Approx(std::sin(theta0) / (R - r + r * std::sin(theta0))).epsilon(1e-12));
        // Directions in part coordinates (up to sign, except at the ball's
        // umbilic where any frame is principal).
        if (r < R) {
          CHECK(c.dir_max.dot(fd.dir_max) == doctest::Approx(1).epsilon(1e-6));
          CHECK(c.dir_min.dot(fd.dir_min) == doctest::Approx(1).epsilon(1e-6));
        }
        CHECK(c.dir_max.dot(n) == doctest::Approx(0).scale(1).epsilon(1e-12));
        CHECK(c.dir_max.cross(c.dir_min).dot(n) == doctest::Approx(1).epsilon(1e-12));
        CHECK(c.dir_max.z() >= 0);  // uphill along the meridian
        CHECK(c.dir_min.z() == doctest::Approx(0).scale(1).epsilon(1e-12));
        // Euler with the returned frame gives the torus's normal curvature
        // in every direction.
        for (double a = 0; a < 2 * M_PI; a += 0.3) {
          const Eigen::Vector3d t = std::cos(a) * c.dir_max + std::sin(a) * c.dir_min;
          const double euler = c.k_max * std::cos(a) * std::cos(a) + c.k_min * std::sin(a) * std::sin(a);
          CHECK(euler == doctest::Approx(fd.along(t)).epsilon(1e-5));
        }
      }
    }
  }
}

TEST_CASE("cutter curvature: a ball is 1/R in every direction, at any contact angle") {
  const Cutter ball("b", 6.35, 6.35);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    Eigen::Vector3d n(unit(rng), unit(rng), std::abs(unit(rng)) + 1e-3);
    n.normalize();
    const CutterCurvature c = cutter_curvature(ball, n);
    REQUIRE(c.reachable);
    CHECK(c.k_max == doctest::Approx(1 / 6.35).epsilon(1e-12));
    CHECK(c.k_min == doctest::Approx(1 / 6.35).epsilon(1e-12));
  }
  // At the very tip too (n = z, rho_c = 0): the limit, not 0/0.
  const CutterCurvature tip = cutter_curvature(ball, Eigen::Vector3d::UnitZ());
  CHECK(tip.k_min == doctest::Approx(1 / 6.35));
  CHECK_FALSE(tip.flat_bottom);
}

TEST_CASE("cutter curvature: flat rim is sharp, horizontal contacts touch the flat bottom, n_z < 0 is unreachable") {
  const Cutter flat("f", 4, 0), bull("t", 4, 1);
  const Eigen::Vector3d n = Eigen::Vector3d(std::sin(0.4), 0, std::cos(0.4));
  const CutterCurvature cf = cutter_curvature(flat, n);
  CHECK(cf.sharp);
  CHECK(std::isinf(cf.k_max));
  CHECK(cf.k_min == doctest::Approx(std::sin(0.4) / 4));  // the bottom circle, Meusnier
  CHECK_FALSE(cf.flat_bottom);
  for (const Cutter* c : {&flat, &bull}) {
    const CutterCurvature h = cutter_curvature(*c, Eigen::Vector3d::UnitZ());
    CHECK(h.flat_bottom);
    CHECK(h.k_min == 0.0);
    CHECK((h.toward_axis - Eigen::Vector3d::UnitX()).norm() < 1e-15);
    CHECK((h.dir_max + Eigen::Vector3d::UnitX()).norm() < 1e-15);
  }
  CHECK_FALSE(cutter_curvature(bull, Eigen::Vector3d(1, 0, -1e-12)).reachable);
  CHECK_FALSE(cutter_curvature(bull, Eigen::Vector3d(0.3, 0, -1)).reachable);
  CHECK_FALSE(cutter_curvature(bull, Eigen::Vector3d::Zero()).reachable);
}
