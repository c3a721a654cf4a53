#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/nurbs_surface.hpp"
#include "geometry/surface_grid.hpp"
#include "support/random_surface.hpp"

using namespace furrow;

namespace {

// Grid parameters along one direction: random ones, every interior knot
// exactly, both domain ends, one value outside on each side (clamped), in a
// shuffled order (the grid must not assume sorted parameters).
std::vector<double> grid_parameters(std::mt19937& rng, const std::vector<double>& knots, int degree,
                                    int num_control, int random_count) {
  const double lo = knots[degree], hi = knots[num_control];
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> t;
  for (int k = 0; k < random_count; ++k) t.push_back(lo + (hi - lo) * unit(rng));
  for (int k = degree + 1; k < num_control; ++k) t.push_back(knots[k]);
  t.push_back(lo);
  t.push_back(hi);
  t.push_back(lo - 0.1 * (hi - lo));
  t.push_back(hi + 0.1 * (hi - lo));
  std::shuffle(t.begin(), t.end(), rng);
  return t;
}

bool close(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double rel) {
  return (a - b).norm() <= rel * std::max(1.0, b.norm());
}

bool identical(const SurfaceDerivatives& a, const SurfaceDerivatives& b) {
  return a.S == b.S && a.Su == b.Su && a.Sv == b.Sv && a.Suu == b.Suu && a.Suv == b.Suv &&
         a.Svv == b.Svv;
}

// Every grid point against NurbsSurface::evaluate, the independent oracle.
// Returns the number of points compared; counts bit-identical ones.
int compare_grid(const NurbsSurface& s, const std::vector<double>& us, const std::vector<double>& vs,
                 int order, SurfaceGridScratch& scratch, int& identical_count) {
  const SurfaceGrid grid(s, us, vs, order);
  REQUIRE(grid.nu() == static_cast<int>(us.size()));
  REQUIRE(grid.nv() == static_cast<int>(vs.size()));
  std::vector<SurfaceDerivatives> row(us.size());
  int compared = 0;
  for (int j = 0; j < grid.nv(); ++j) {
    grid.evaluate_row(j, row.data(), scratch);
    for (int i = 0; i < grid.nu(); ++i) {
      const SurfaceDerivatives e = s.evaluate(us[i], vs[j], order);
      const SurfaceDerivatives& g = row[i];
      CAPTURE(us[i]);
      CAPTURE(vs[j]);
      CHECK(close(g.S, e.S, 1e-12));
      CHECK(close(g.Su, e.Su, 1e-12));
      CHECK(close(g.Sv, e.Sv, 1e-12));
      CHECK(close(g.Suu, e.Suu, 1e-12));
      CHECK(close(g.Suv, e.Suv, 1e-12));
      CHECK(close(g.Svv, e.Svv, 1e-12));
      // Entries above the order stay zero, as with evaluate.
      if (order < 1) CHECK((g.Su.isZero(0) && g.Sv.isZero(0)));
      if (order < 2) CHECK((g.Suu.isZero(0) && g.Suv.isZero(0) && g.Svv.isZero(0)));
      if (identical(g, e)) ++identical_count;
      ++compared;
    }
  }
  return compared;
}

}  // namespace

TEST_CASE("grid evaluation equals NurbsSurface::evaluate on random grids, degrees 1-5 and 7") {
  std::mt19937 rng(1907);
  SurfaceGridScratch scratch;  // shared on purpose: rows of other grids must not leak
  int compared = 0, identical_count = 0, surfaces = 0;
  for (int pu : {1, 2, 3, 4, 5, 7}) {
    for (int pv : {1, 2, 3, 5, 7}) {
      for (bool clamped : {true, false}) {
        for (bool rational : {false, true}) {
          const NurbsSurface s = test::random_surface(rng, pu, pv, clamped, rational);
          CAPTURE(pu);
          CAPTURE(pv);
          CAPTURE(clamped);
          CAPTURE(rational);
          const auto us = grid_parameters(rng, s.knots_u(), pu, s.num_u(), 7);
          const auto vs = grid_parameters(rng, s.knots_v(), pv, s.num_v(), 5);
          for (int order = 0; order <= 2; ++order) {
            CAPTURE(order);
            compared += compare_grid(s, us, vs, order, scratch, identical_count);
            // One grid column / one grid row.
            compared += compare_grid(s, {us[0]}, vs, order, scratch, identical_count);
            compared += compare_grid(s, us, {vs[1]}, order, scratch, identical_count);
            compared += compare_grid(s, {us[2]}, {vs[2]}, order, scratch, identical_count);
          }
          ++surfaces;
        }
      }
    }
  }
  CHECK(surfaces == 120);
  CHECK(compared > 20000);
  // The contract is stronger than 1e-12: the same arithmetic in the same order
  // (this is what keeps the partition and error-map outputs byte-identical).
  CHECK(identical_count == compared);
}

TEST_CASE("grid derivatives agree with central differences of grid points") {
  // The oracle uses only grid positions S at u +- h, v +- h (a 3x3 and a 5x1
  // grid around each point), so it is independent of the derivative sums.
  std::mt19937 rng(77);
  int checked = 0;
  for (int pu : {1, 2, 3, 5}) {
    for (int pv : {2, 3, 5}) {
      for (bool rational : {false, true}) {
        const NurbsSurface s = test::random_surface(rng, pu, pv, true, rational);
        const ParameterDomain& d = s.domain();
        const double u = test::parameter_away_from_knots(rng, s.knots_u(), d.u0, d.u1, 1e-3);
        const double v = test::parameter_away_from_knots(rng, s.knots_v(), d.v0, d.v1, 1e-3);
        const double hu = 1e-5 * d.width_u(), hv = 1e-5 * d.width_v();
        const SurfaceGrid grid(s, {u - hu, u, u + hu}, {v - hv, v, v + hv}, 2);
        SurfaceGridScratch scratch;
        SurfaceDerivatives r[3][3];  // r[j][i]
        for (int j = 0; j < 3; ++j) grid.evaluate_row(j, r[j], scratch);
        const SurfaceDerivatives& c = r[1][1];
        const Eigen::Vector3d fu = (r[1][2].S - r[1][0].S) / (2 * hu);
        const Eigen::Vector3d fv = (r[2][1].S - r[0][1].S) / (2 * hv);
        const Eigen::Vector3d fuu = (r[1][2].S - 2 * c.S + r[1][0].S) / (hu * hu);
        const Eigen::Vector3d fvv = (r[2][1].S - 2 * c.S + r[0][1].S) / (hv * hv);
        const Eigen::Vector3d fuv = (r[2][2].S - r[2][0].S - r[0][2].S + r[0][0].S) / (4 * hu * hv);
        const double s1 = c.Su.norm() + c.Sv.norm();
        const double s2 = c.Suu.norm() + c.Suv.norm() + c.Svv.norm() + s1 / d.width_u();
        CAPTURE(pu);
        CAPTURE(pv);
        CAPTURE(rational);
        CHECK((c.Su - fu).norm() <= 1e-7 * s1);
        CHECK((c.Sv - fv).norm() <= 1e-7 * s1);
        // Second differences of positions lose ~half the digits.
        CHECK((c.Suu - fuu).norm() <= 1e-3 * s2);
        CHECK((c.Svv - fvv).norm() <= 1e-3 * s2);
        CHECK((c.Suv - fuv).norm() <= 1e-3 * s2);
        ++checked;
      }
    }
  }
  CHECK(checked == 24);
}
