#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "cutter_reference.hpp"
#include "geometry/part.hpp"
#include "geometry/primitives.hpp"
#include "machining/gouge/local_gouge.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kDeg = M_PI / 180;

// Biquadratic Bezier patch over [-20, 20]^2 reproducing the height field
// z = f(x, y) exactly when f is a polynomial of degree <= 2 in x and in y
// (interpolation at 3 x 3 nodes).
template <class F>
NurbsSurface quadratic_height_patch(F f) {
  const double x0 = -20, w = 40;
  Eigen::Matrix<double, 9, 9> A;
  Eigen::Matrix<double, 9, 1> b;
  auto bern = [](int i, double s) { return i == 0 ? (1 - s) * (1 - s) : i == 1 ? 2 * s * (1 - s) : s * s; };
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const double s = a / 2.0, t = c / 2.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(a * 3 + c, i * 3 + j) = bern(i, s) * bern(j, t);
      b(a * 3 + c) = f(x0 + w * s, x0 + w * t);
    }
  const Eigen::Matrix<double, 9, 1> z = A.fullPivLu().solve(b);
  std::vector<std::vector<Eigen::Vector3d>> net(3, std::vector<Eigen::Vector3d>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) net[i][j] = {x0 + w * i / 2.0, x0 + w * j / 2.0, z(i * 3 + j)};
  return NurbsSurface(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, net);
}

}  // namespace

TEST_CASE("concave cylinder of radius rho, ball across the axis: gouges exactly when R > rho") {
  const double rho = 25.0;
  // The lower half of a tube about the y axis: concave, normal up toward the axis.
  const Face trough("trough", make_cylinder(rho, 60, M_PI + 0.3, 2 * M_PI - 0.3));
  const GougeOptions options;
  for (double u : {0.1, 0.35, 0.5, 0.8}) {
    const DifferentialGeometry g = trough.geometry(u, 0.5);
    REQUIRE(g.normal.z() > 0);
    REQUIRE(g.k1 == doctest::Approx(1 / rho).epsilon(1e-9));
    for (double R : {rho * 0.5, rho * 0.999, rho, rho * 1.001, rho * 1.5, rho * 3}) {
      CAPTURE(u);
      CAPTURE(R);
      const LocalGouge result = check_local_gouge(Cutter("ball", R, R), g, options);
      CHECK(result.gouges() == (R > rho));
      if (R == rho) CHECK(std::abs(result.max_excess) < 1e-9);  // a tie touches, no gouge
      if (!result.gouges()) continue;
      CHECK(result.max_excess == doctest::Approx(1 / rho - 1 / R).epsilon(1e-9));
      // The gouging directions are around the cross-section (x-z plane),
      // symmetric about it: cos^2(angle to the cross direction) > rho (1/R + tol).
      const double half = std::acos(std::sqrt(rho * (1 / R + options.curvature_tolerance)));
      REQUIRE(result.ranges.size() == 2);
      for (const AngularRange& range : result.ranges) {
        CHECK(range.width == doctest::Approx(2 * half).epsilon(1e-9));
        const Eigen::Vector3d mid = result.direction(range.start + 0.5 * range.width);
        CHECK(std::abs(mid.y()) < 1e-9);  // centred on the cross direction
        CHECK(std::abs(result.direction(range.start).y()) == doctest::Approx(std::sin(half)).epsilon(1e-9));
      }
    }
  }
}

TEST_CASE("a convex surface never gouges with an end mill of r > 0 (nor with a flat one)") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Face dome("dome", make_sphere(12, 0, 2 * M_PI, 0.05, 1.5));
  const Face hill("hill", make_cylinder(7, 30, 0.1, M_PI - 0.1), {}, true);  // convex cylinder
  const Face ring("ring", make_torus(30, 5, 0, 2 * M_PI, -1.2, 1.5));         // outer ring: saddle inside
  GougeOptions exact;
  exact.quick_accept = false;
  int checked = 0;
  for (int k = 0; k < 300; ++k) {
    const double R = 0.5 + 20 * unit(rng);
    const double r = k % 3 == 0 ? R : k % 3 == 1 ? R * unit(rng) : 0.0;
    const Cutter cutter("c", R, r);
    for (const Face* face : {&dome, &hill, &ring}) {
      const DifferentialGeometry g = face->geometry(unit(rng), unit(rng));
      if (g.degenerate || g.normal.z() <= 0 || g.k1 > 0) continue;  // convex points only
      ++checked;
      const LocalGouge quick = check_local_gouge(cutter, g);
      CHECK(quick.status == GougeStatus::clear);
      CHECK(quick.quick);
      const LocalGouge full = check_local_gouge(cutter, g, exact);
      CHECK(full.status == GougeStatus::clear);
      CHECK(full.max_excess <= exact.curvature_tolerance);
      CHECK(full.max_excess <= quick.max_excess + 1e-12);  // the quick value bounds it
    }
  }
  CHECK(checked > 300);
}

TEST_CASE("saddle: principal curvatures say maybe, the directional ranges match a brute-force sweep") {
  // z = 8 + 0.02 x + 0.08 y + 0.012 x^2 - 0.02 y^2 + 0.015 x y: a saddle
  // gently sloping up along y, whose principal frame is turned against the
  // cutter's.
  const Face saddle("saddle", quadratic_height_patch([](double x, double y) {
                      return 8 + 0.02 * x + 0.08 * y + 0.012 * x * x - 0.02 * y * y + 0.015 * x * y;
                    }));
  const double tol = GougeOptions().curvature_tolerance;
  int with_ranges = 0;
  for (const auto& [R, r] : {std::pair{6.0, 1.0}, {6.0, 0.5}, {8.0, 3.0}, {6.0, 2.0}}) {
    const Cutter cutter("c", R, r);
    for (const auto& [u, v] : {std::pair{0.5, 0.5}, {0.47, 0.54}, {0.44, 0.55}, {0.48, 0.5}}) {
      CAPTURE(R);
      CAPTURE(r);
      CAPTURE(u);
      CAPTURE(v);
      const SurfaceDerivatives d = saddle.surface().evaluate(u, v, 2);
      const DifferentialGeometry g = saddle.geometry(d);
      REQUIRE(g.k1 > 0);
      REQUIRE(g.k2 < 0);
      const LocalGouge result = check_local_gouge(cutter, g);
      // "Maybe" by principal curvatures: k1 above the cutter's smallest
      // curvature, but below its largest.
      REQUIRE(g.k1 > result.cutter.k_min);
      REQUIRE(g.k1 < result.cutter.k_max);
      CHECK_FALSE(result.quick);

      // Brute force, independent of the closed form: the cutter's frame and
      // directional curvature from finite differences of the torus, the
      // part's from its fundamental forms, every 0.01 degrees.
      const FdCurvature fd = fd_cutter_at_normal(R, r, g.normal);
      REQUIRE((fd.normal - g.normal).norm() < 1e-7);
      auto excess = [&](double a_deg) {
        const double a = a_deg * kDeg;
        const Eigen::Vector3d t = std::cos(a) * fd.dir_max + std::sin(a) * fd.dir_min;
        return part_normal_curvature(d, g.normal, t) - fd.along(t);
      };
      const std::vector<double> bounds = sign_changes_deg([&](double a) { return excess(a) - tol; }, 0.01);
      double brute_max = -1e9;
      for (double a = 0; a < 360; a += 0.01) brute_max = std::max(brute_max, excess(a));
      CHECK(result.max_excess == doctest::Approx(brute_max).epsilon(1e-5));
      CHECK(result.gouges() == (brute_max > tol));

      std::vector<double> reported;
      for (const AngularRange& range : result.ranges) {
        reported.push_back(range.start / kDeg);
        reported.push_back(std::fmod(range.end() / kDeg, 360.0));
      }
      REQUIRE(reported.size() == bounds.size());
      for (double b : bounds) {
        double nearest = 360;
        for (double x : reported) nearest = std::min(nearest, angle_gap_deg(b, x));
        CHECK(nearest < 0.01);  // the issue asks for 0.1 degrees
      }
      // Membership agrees at sampled directions away from the boundaries.
      for (double a = 0.05; a < 360; a += 0.5) {
        double near_bound = 360;
        for (double b : bounds) near_bound = std::min(near_bound, angle_gap_deg(a, b));
        if (near_bound < 0.02) continue;
        CHECK(result.ranges.contains(a * kDeg) == (excess(a) > tol));
      }
      with_ranges += !result.ranges.empty() && result.ranges[0].width < 2 * M_PI;
    }
  }
  CHECK(with_ranges >= 8);  // the case is not vacuous
}

TEST_CASE("flat end mill in a spherical bowl: the cutting circle gouges exactly when R > rho sin(theta0)") {
  // Concave bowl (inside of a sphere of radius rho), contact at polar angle
  // theta0 from the bottom. Its horizontal section through the contact is a
  // circle of radius rho sin(theta0); the rim circle of radius R fits inside
  // it exactly when R <= rho sin(theta0). Brute force: a rim point outside
  // the sphere is inside the material.
  const double rho = 40;
  const Face bowl("bowl", make_sphere(rho, 0, 2 * M_PI, -1.5, -0.05), {}, true);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int gouging = 0, clear = 0;
  for (int k = 0; k < 200; ++k) {
    const DifferentialGeometry g = bowl.geometry(unit(rng), unit(rng));
    REQUIRE(g.normal.z() > 0);
    const double theta0 = std::acos(g.normal.z());
    const double section = rho * std::sin(theta0);
    const double R = section * (0.5 + unit(rng));
    const Cutter flat("flat", R, 0);
    const LocalGouge result = check_local_gouge(flat, g);
    CHECK(result.cutter.sharp);
    // Brute force over the rim circle, tip located per docs/architecture.md.
    const Eigen::Vector3d e = Eigen::Vector3d(g.normal.x(), g.normal.y(), 0).normalized();
    const Eigen::Vector3d axis = g.point + R * e;
    double outside = -1e9;
    for (int s = 0; s < 20000; ++s) {
      const double phi = 2 * M_PI * s / 20000;
      const Eigen::Vector3d rim = axis + R * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0);
      outside = std::max(outside, rim.norm() - rho);
    }
    const bool brute = outside > 1e-9;
    if (std::abs(R - section) < 1e-6 * section) continue;  // a tie within sampling
    CHECK(result.gouges() == (R > section));
    CHECK(result.gouges() == brute);
    if (result.gouges()) {
      ++gouging;
      // Only the two circumferential directions, as zero-width ranges.
      REQUIRE(result.ranges.size() == 2);
      CHECK(result.ranges[0].start / kDeg == doctest::Approx(90));
      CHECK(result.ranges[1].start / kDeg == doctest::Approx(270));
      CHECK(result.ranges[0].width == 0.0);
      // Excess in normal-curvature terms: 1/rho - sin(theta0)/R.
      CHECK(result.max_excess == doctest::Approx(1 / rho - std::sin(theta0) / R).epsilon(1e-9));
    } else {
      ++clear;
    }
  }
  CHECK(gouging > 20);
  CHECK(clear > 20);
}

TEST_CASE("horizontal contacts: a flat-bottomed cutter gouges any concavity, a ball only a tighter one") {
  const Face trough("trough", make_cylinder(25, 60, M_PI + 0.3, 2 * M_PI - 0.3));
  const DifferentialGeometry g = trough.geometry(0.5, 0.5);  // the bottom line: n = +z
  REQUIRE(g.normal.z() == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(check_local_gouge(Cutter("ball", 10, 10), g).status == GougeStatus::clear);
  const LocalGouge bull = check_local_gouge(Cutter("bull", 10, 2), g);
  CHECK(bull.gouges());
  CHECK(bull.cutter.flat_bottom);
  CHECK(bull.max_excess == doctest::Approx(1 / 25.0).epsilon(1e-9));
  CHECK(check_local_gouge(Cutter("flat", 10, 0), g).gouges());
  // A flat plane is touched, not gouged, by everything.
  const Face plane("plane", make_plane({0, 0, 5}, {10, 0, 0}, {0, 10, 0}));
  for (double r : {0.0, 2.0, 10.0}) CHECK(check_local_gouge(Cutter("c", 10, r), plane.geometry(0.3, 0.6)).status == GougeStatus::clear);
}

TEST_CASE("unreachable and degenerate points are reported, not computed") {
  // A ceiling: (0,10,0) x (10,0,0) = (0,0,-100), normal -z. (A wall, n_z = 0,
  // is a side contact: test_side_contact.cpp.)
  const Face ceiling("ceiling", make_plane({0, 0, 0}, {0, 10, 0}, {10, 0, 0}));
  const LocalGouge r = check_local_gouge(Cutter("b", 3, 3), ceiling.geometry(0.5, 0.5));
  CHECK(r.status == GougeStatus::unreachable);
  CHECK(r.ranges.empty());
  DifferentialGeometry degenerate;
  CHECK(check_local_gouge(Cutter("b", 3, 3), degenerate).status == GougeStatus::degenerate);
}
