// ParameterMap (src/io/cad_parameter_map): carrying angle parameters of
// analytic surfaces over to their rational NURBS forms. Oracles: the analytic
// surfaces themselves (N(map(u,v)) must be S(u,v)), monotonicity, and the
// domain ends.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/primitives.hpp"
#include "io/cad/cad_parameter_map.hpp"

using namespace furrow;

namespace {

double worst_mismatch(const NurbsSurface& nurbs, ParameterMap& map, const ParameterMap::Evaluator& s,
                      const ParameterDomain& b, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> fu(b.u0, b.u1), fv(b.v0, b.v1);
  double worst = 0;
  for (int k = 0; k < 500; ++k) {
    const double u = fu(rng), v = fv(rng);
    const Eigen::Vector2d st = map(u, v);
    worst = std::max(worst, (nurbs.point(st.x(), st.y()) - s(u, v)).norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("ParameterMap: a rational cylinder's angle is recovered exactly") {
  const double radius = 25.4, length = 50.8, a0 = 0.3, a1 = 2.9;
  const NurbsSurface nurbs = make_cylinder(radius, length, a0, a1);
  const ParameterMap::Evaluator cylinder = [&](double t, double y) {
    return Eigen::Vector3d(radius * std::cos(t), y, radius * std::sin(t));
  };
  const ParameterDomain bounds{a0, a1, 0, length};
  ParameterMap map(nurbs, cylinder, bounds);
  CHECK_FALSE(map.is_identity());
  CHECK(worst_mismatch(nurbs, map, cylinder, bounds, 7) <= 1e-9);
  CHECK(max_deviation(nurbs, map, cylinder, bounds, 13) <= 1e-9);
  CHECK(map.failures() == 0);
  // Ends of the rectangle go to the ends of the NURBS domain; the map grows.
  const ParameterDomain& d = nurbs.domain();
  CHECK(map(a0, 0).x() == doctest::Approx(d.u0).scale(1));
  CHECK(map(a1, length).x() == doctest::Approx(d.u1).scale(1));
  CHECK(map(a0, length).y() == doctest::Approx(d.v1).scale(1));
  double previous = -1e300;
  for (int k = 0; k <= 100; ++k) {
    const double s = map(a0 + (a1 - a0) * k / 100, 1).x();
    CHECK(s > previous);
    previous = s;
  }
  // The identity would be wrong by far more than the tolerance: the rational
  // parametrisation really differs from the angle.
  ParameterMap identity;
  CHECK(max_deviation(nurbs, identity, cylinder, {d.u0, d.u1, 0, length}, 13) > 1e-3);
}

TEST_CASE("ParameterMap: a full sphere, poles and seam included") {
  const double radius = 15;
  const NurbsSurface nurbs = make_sphere(radius, 0, 2 * M_PI, -M_PI / 2, M_PI / 2);
  const ParameterMap::Evaluator sphere = [&](double phi, double lambda) {
    return Eigen::Vector3d(radius * std::cos(lambda) * std::cos(phi),
                           radius * std::cos(lambda) * std::sin(phi), radius * std::sin(lambda));
  };
  const ParameterDomain bounds{0, 2 * M_PI, -M_PI / 2, M_PI / 2};
  ParameterMap map(nurbs, sphere, bounds);
  CHECK(worst_mismatch(nurbs, map, sphere, bounds, 11) <= 1e-9);
  CHECK(map.failures() == 0);
  const ParameterDomain& d = nurbs.domain();
  // A pole line maps onto the domain's edge, keeping its u order (a trim
  // loop running along it stays on the boundary).
  CHECK(map(1.0, M_PI / 2).y() == doctest::Approx(d.v1).scale(1));
  CHECK(map(1.0, -M_PI / 2).y() == doctest::Approx(d.v0).scale(1));
  CHECK(map(1.0, M_PI / 2).x() < map(2.0, M_PI / 2).x());
  // Either side of the seam goes to its own end of the domain.
  CHECK(map(1e-9, 0).x() - d.u0 < 1e-6 * d.width_u());
  CHECK(d.u1 - map(2 * M_PI - 1e-9, 0).x() < 1e-6 * d.width_u());
  CHECK(map(2 * M_PI, 0.3).x() == doctest::Approx(d.u1).scale(1));
}

TEST_CASE("ParameterMap: a direction run backwards is detected") {
  const double radius = 10, length = 5, a0 = -0.4, a1 = 1.1;
  const NurbsSurface nurbs = make_cylinder(radius, length, a0, a1);
  // The original runs its angle the other way: u = a0 is the NURBS's a1 end.
  const ParameterMap::Evaluator backwards = [&](double u, double y) {
    const double t = a1 - (u - a0);
    return Eigen::Vector3d(radius * std::cos(t), y, radius * std::sin(t));
  };
  const ParameterDomain bounds{a0, a1, 0, length};
  ParameterMap map(nurbs, backwards, bounds);
  CHECK(worst_mismatch(nurbs, map, backwards, bounds, 3) <= 1e-9);
  CHECK(map(a0, 1).x() == doctest::Approx(nurbs.domain().u1).scale(1));
  CHECK(map(a0 + 0.1, 1).x() > map(a0 + 0.2, 1).x());
}

TEST_CASE("ParameterMap: a conversion that is not a product map is caught by max_deviation") {
  const double radius = 10, length = 5;
  const NurbsSurface nurbs = make_cylinder(radius, length, 0.0, 1.5);
  // Sheared parametrisation: the angle depends on both parameters.
  const ParameterMap::Evaluator sheared = [&](double u, double v) {
    const double t = u + 0.05 * v;
    return Eigen::Vector3d(radius * std::cos(t), v, radius * std::sin(t));
  };
  const ParameterDomain bounds{0.0, 1.25, 0, length};
  ParameterMap map(nurbs, sheared, bounds);
  CHECK(max_deviation(nurbs, map, sheared, bounds, 13) > 1e-3);
}
