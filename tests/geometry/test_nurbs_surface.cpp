#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "base/error.hpp"
#include "geometry/nurbs_surface.hpp"
#include "geometry/primitives.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

namespace {

// Relative agreement of two vectors against a scale.
bool close(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double rel, double scale) {
  return (a - b).norm() <= rel * std::max(scale, 1e-300);
}

}  // namespace

TEST_CASE("derivatives of random surfaces of degree 1-5 agree with central differences") {
  std::mt19937 rng(2026);
  int checked = 0;
  for (int pu = 1; pu <= 5; ++pu) {
    for (int pv = 1; pv <= 5; ++pv) {
      for (bool clamped : {true, false}) {
        for (bool rational : {false, true}) {
          const NurbsSurface s = test::random_surface(rng, pu, pv, clamped, rational);
          const ParameterDomain& d = s.domain();
          for (int trial = 0; trial < 4; ++trial) {
            const double u = test::parameter_away_from_knots(rng, s.knots_u(), d.u0, d.u1, 1e-3);
            const double v = test::parameter_away_from_knots(rng, s.knots_v(), d.v0, d.v1, 1e-3);
            const double hu = 1e-6 * d.width_u(), hv = 1e-6 * d.width_v();
            const SurfaceDerivatives c = s.evaluate(u, v, 2);
            const SurfaceDerivatives up = s.evaluate(u + hu, v, 2), um = s.evaluate(u - hu, v, 2);
            const SurfaceDerivatives vp = s.evaluate(u, v + hv, 2), vm = s.evaluate(u, v - hv, 2);
            const Eigen::Vector3d fd_u = (up.S - um.S) / (2 * hu);
            const Eigen::Vector3d fd_v = (vp.S - vm.S) / (2 * hv);
            const Eigen::Vector3d fd_uu = (up.Su - um.Su) / (2 * hu);
            const Eigen::Vector3d fd_vv = (vp.Sv - vm.Sv) / (2 * hv);
            const Eigen::Vector3d fd_uv = (vp.Su - vm.Su) / (2 * hv);
            const Eigen::Vector3d fd_vu = (up.Sv - um.Sv) / (2 * hu);
            const double s1 = c.Su.norm() + c.Sv.norm();
            const double s2 = c.Suu.norm() + c.Suv.norm() + c.Svv.norm() + s1 / d.width_u();
            CAPTURE(pu);
            CAPTURE(pv);
            CAPTURE(clamped);
            CAPTURE(rational);
            CHECK(close(c.Su, fd_u, 1e-6, s1));
            CHECK(close(c.Sv, fd_v, 1e-6, s1));
            CHECK(close(c.Suu, fd_uu, 1e-6, s2));
            CHECK(close(c.Svv, fd_vv, 1e-6, s2));
            CHECK(close(c.Suv, fd_uv, 1e-6, s2));
            CHECK(close(c.Suv, fd_vu, 1e-6, s2));
            // Lower orders requested alone give the same numbers.
            CHECK(s.evaluate(u, v, 1).Su == c.Su);
            CHECK(s.point(u, v) == c.S);
            ++checked;
          }
        }
      }
    }
  }
  CHECK(checked == 400);
}

TEST_CASE("a rational cylinder patch lies on the cylinder to 1e-12 relative") {
  const double R = 25.4, L = 50.8;
  const NurbsSurface s = make_cylinder(R, L, 0.0, M_PI);
  CHECK(s.is_rational());
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 10; ++j) {
      const Eigen::Vector3d p = s.point(i / 40.0, j / 10.0);
      CHECK(std::hypot(p.x(), p.z()) == doctest::Approx(R).epsilon(1e-12));
      CHECK(p.y() == doctest::Approx(L * j / 10.0).epsilon(1e-12).scale(L));
    }
}

TEST_CASE("a rational sphere patch lies on the sphere to 1e-12 relative") {
  const double R = 50.0;
  const NurbsSurface s = make_sphere(R, -2.5, 2.0, -1.2, 1.4);
  for (int i = 0; i <= 30; ++i)
    for (int j = 0; j <= 30; ++j)
      CHECK(s.point(i / 30.0, j / 30.0).norm() == doctest::Approx(R).epsilon(1e-12));
}

TEST_CASE("control box contains the surface") {
  std::mt19937 rng(3);
  const NurbsSurface s = test::random_surface(rng, 3, 2, true, true);
  const Eigen::AlignedBox3d box = s.control_box();
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const Eigen::Vector3d p =
          s.point(s.domain().u0 + s.domain().width_u() * i / 20, s.domain().v0 + s.domain().width_v() * j / 20);
      CHECK(box.exteriorDistance(p) < 1e-9);
    }
}

TEST_CASE("surface validation rejects bad control nets and weights with the field named") {
  const std::vector<double> k = {0, 0, 1, 1};
  const std::vector<std::vector<Eigen::Vector3d>> net = {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}};
  auto message = [&](const std::vector<std::vector<Eigen::Vector3d>>& cp,
                     const std::vector<std::vector<double>>& w) {
    try {
      NurbsSurface(1, 1, k, k, cp, w, "faces[3]");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message(net, {}).empty());
  CHECK(message(net, {{1, 1}, {1, -1}}).find("faces[3].weights[1][1]") == 0);
  CHECK(message(net, {{1, 1}, {1, 0}}).find("positive") != std::string::npos);
  CHECK(message(net, {{1, 1}}).find("faces[3].weights") == 0);
  auto bad = net;
  bad[1][0].y() = std::nan("");
  CHECK(message(bad, {}).find("faces[3].control_points[1][0]") == 0);
  CHECK(message({}, {}).find("empty") != std::string::npos);
  CHECK(message({{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}}}, {}).find("rectangular") != std::string::npos);
}
