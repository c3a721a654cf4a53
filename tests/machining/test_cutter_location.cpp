#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "machining/cutter/cutter_location.hpp"

using namespace furrow;

namespace {

Eigen::Vector3d random_upward_normal(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (;;) {
    Eigen::Vector3d n(unit(rng), unit(rng), unit(rng));
    if (n.norm() < 0.1 || n.norm() > 1 || n.z() < 0.02) continue;
    return n.normalized();
  }
}

}  // namespace

TEST_CASE("cutter location: the contact lies on the cutter and the cutter normal there is the part normal") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-50, 50);
  const Cutter cutters[] = {Cutter("ball", 5, 5), Cutter("flat", 5, 0), Cutter("bull", 5, 1.25),
                            Cutter("bull2", 3, 2.9)};
  for (const Cutter& cutter : cutters) {
    const double R = cutter.radius(), r = cutter.corner_radius();
    for (int k = 0; k < 200; ++k) {
      CAPTURE(cutter.name());
      const Eigen::Vector3d P(coord(rng), coord(rng), coord(rng));
      const Eigen::Vector3d n = random_upward_normal(rng);
      const CutterLocation loc = cutter_location(cutter, P, n);
      REQUIRE(loc.reachable);
      // The tube centre is R - r horizontally from the axis, r above the tip.
      const Eigen::Vector3d CT = loc.tube_centre - loc.tip;
      CHECK(std::hypot(CT.x(), CT.y()) == doctest::Approx(R - r).epsilon(1e-12).scale(1));
      CHECK(CT.z() == doctest::Approx(r).epsilon(1e-12).scale(1));
      CHECK((loc.tube_centre - P).norm() == doctest::Approx(r).epsilon(1e-12).scale(1));
      // The contact lies on the cutter's lower envelope at its distance from
      // the axis.
      const Eigen::Vector3d d = P - loc.tip;
      const double rho = std::hypot(d.x(), d.y());
      CHECK(rho == doctest::Approx(loc.contact_radius).epsilon(1e-12));
      CHECK(d.z() == doctest::Approx(cutter.height_at(std::min(rho, R))).epsilon(1e-9).scale(1));
      CHECK(d.z() == doctest::Approx(loc.contact_height).epsilon(1e-9).scale(1));
      // The cutter's outward normal there is -n: radially outward by
      // sin(theta0) and down by cos(theta0), i.e. the profile slope is
      // tan(theta0). (For the flat rim: the normal is inside its cone.)
      const Eigen::Vector3d radial(d.x() / rho, d.y() / rho, 0);
      const double theta0 = std::acos(n.z());
      CHECK(loc.contact_angle == doctest::Approx(theta0).epsilon(1e-12));
      CHECK((-n - (std::sin(theta0) * radial - std::cos(theta0) * Eigen::Vector3d::UnitZ())).norm() < 1e-9);
      if (r > 0 && rho < R - 1e-9) CHECK(cutter.slope_at(rho) == doctest::Approx(std::tan(theta0)).epsilon(1e-7));
      if (r == 0) {
        CHECK(rho == doctest::Approx(R));
        CHECK(d.z() == doctest::Approx(0).scale(1));
      }
      // No point of the cutter's envelope is below the part's tangent plane
      // near the contact at first order: the envelope point at the contact's
      // azimuth and rho +- drho stays above the plane (tangency).
      for (double drho : {-1e-4, 1e-4}) {
        const double rr = rho + drho;
        if (rr < 0 || rr > R) continue;
        const Eigen::Vector3d Q = loc.tip + rr * radial + cutter.height_at(rr) * Eigen::Vector3d::UnitZ();
        CHECK((Q - P).dot(n) >= -1e-9);
      }
    }
  }
}

TEST_CASE("cutter location: docs/architecture.md formulas for a bull-nose, and the horizontal case") {
  const Cutter bull("t", 6, 2);
  const Eigen::Vector3d P(10, 20, 30);
  const double t = 0.5;
  const Eigen::Vector3d n(std::sin(t) * std::cos(1.0), std::sin(t) * std::sin(1.0), std::cos(t));
  const CutterLocation loc = cutter_location(bull, P, n);
  const Eigen::Vector3d e(std::cos(1.0), std::sin(1.0), 0);
  const Eigen::Vector3d C = P + 2 * n, A = C + 4 * e, T = A - 2 * Eigen::Vector3d::UnitZ();
  CHECK((loc.tip - T).norm() < 1e-12);
  CHECK((loc.toward_axis - e).norm() < 1e-12);
  CHECK(loc.contact_radius == doctest::Approx(4 + 2 * std::sin(t)));
  CHECK_FALSE(loc.horizontal);

  const CutterLocation flat = cutter_location(bull, P, Eigen::Vector3d::UnitZ());
  CHECK(flat.horizontal);
  CHECK((flat.tip - (P + Eigen::Vector3d(4, 0, 0))).norm() < 1e-12);
  CutterLocationOptions side;
  side.horizontal_side = Eigen::Vector3d(0, -2, 0.5);
  const CutterLocation flat2 = cutter_location(bull, P, Eigen::Vector3d::UnitZ(), side);
  CHECK((flat2.tip - (P + Eigen::Vector3d(0, -4, 0))).norm() < 1e-12);
}

TEST_CASE("cutter location: n_z < 0 is not reachable and nothing is computed") {
  // (n_z = 0, a vertical wall, is a side contact: test_side_contact.cpp.)
  const Cutter ball("b", 5, 5);
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(1, 0, -1e-12), Eigen::Vector3d(0, 0.6, -0.8),
                                   Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 0),
                                   Eigen::Vector3d(std::nan(""), 0, 1)}) {
    const CutterLocation loc = cutter_location(ball, Eigen::Vector3d(1, 2, 3), n);
    CHECK_FALSE(loc.reachable);
    CHECK(loc.tip == Eigen::Vector3d::Zero());
  }
}
