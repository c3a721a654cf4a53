// Closest point on a part: analytic feet on primitives, and the adversarial
// cases (concave cylinder axis, evolute of a dimple, beyond the domain edge,
// sharp edges between faces, trimmed holes) against a brute-force oracle
// (support/closest_point_oracle.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/closest_point.hpp"
#include "base/error.hpp"
#include "geometry/local_foot_point.hpp"
#include "geometry/primitives.hpp"
#include "geometry/seed_grid.hpp"
#include "io/part_file.hpp"
#include "support/closest_point_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using test::brute_force;
using test::Oracle;

namespace {

Part single_face(NurbsSurface s, bool reversed = false, Trim trim = {}) {
  Part p;
  p.faces.emplace_back("face", std::move(s), std::move(trim), reversed);
  return p;
}

Part mould() { return read_part(test::source_path("examples/parts/mould.json")); }

UvLoop uv_circle(double cx, double cy, double r, int n) {
  UvLoop l;
  for (int k = 0; k < n; ++k)
    l.emplace_back(cx + r * std::cos(2 * M_PI * k / n), cy + r * std::sin(2 * M_PI * k / n));
  return l;
}

// The finder must match the oracle's minimum distance (it may find a
// different but equally near foot when there are ties).
void check_against_oracle(const ClosestPointFinder& finder, const Eigen::Vector3d& q,
                          double tolerance = 1e-9) {
  const ClosestPoint c = finder.project(q);
  const Oracle o = brute_force(finder.part(), q);
  CAPTURE(q.transpose());
  CAPTURE(o.point.transpose());
  CAPTURE(c.point.transpose());
  CHECK(c.converged);
  CHECK(std::abs(c.distance - o.distance) <= tolerance);
  CHECK(std::abs((q - c.point).norm() - c.distance) < 1e-12);
}

}  // namespace

TEST_CASE("seed breaks follow the knot spans within the cell bounds") {
  ClosestPointOptions o;
  const std::vector<double> knots = {0, 0, 0, 0, 0.25, 0.5, 1, 1, 1, 1};
  const std::vector<double> b = seed_breaks(knots, 0, 1, o);  // 3 spans -> 3 x 3 cells (min 8)
  CHECK(b.size() == 10);
  CHECK(b[3] == 0.25);
  CHECK(b[6] == 0.5);
  o.max_cells = 4;
  o.min_cells = 2;
  o.cells_per_span = 2;
  CHECK(seed_breaks(knots, 0, 1, o).size() == 5);  // too many spans: uniform
}

TEST_CASE("sphere: foot points and signed distances are exact to 1e-9 mm") {
  const double R = 50;
  const Part part = single_face(make_sphere(R, 0.2, 2.0, -0.6, 0.9));
  const ClosestPointFinder finder(part);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> lon(0.3, 1.9), lat(-0.5, 0.8), off(-20, 20);
  for (int k = 0; k < 300; ++k) {
    const double a = lon(rng), b = lat(rng), h = off(rng);
    const Eigen::Vector3d dir(std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b));
    const Eigen::Vector3d q = (R + h) * dir;
    const ClosestPoint c = finder.project(q);
    CAPTURE(q.transpose());
    CAPTURE(c.iterations);
    CAPTURE(c.uv.transpose());
    CHECK(c.converged);
    CHECK(c.location == FootLocation::interior);
    CHECK((c.point - R * dir).norm() < 1e-9);
    CHECK(std::abs(c.signed_distance - h) <= 1e-9);
    CHECK((c.normal - dir).norm() < 1e-9);
  }
}

TEST_CASE("concave cylinder: points on and near the axis get the true minimum") {
  const double R = 30;
  // Unreversed: the inside of a tube (normal toward the axis, concave).
  const Part part = single_face(make_cylinder(R, 60, M_PI, 2 * M_PI));  // lower half (z <= 0)
  const ClosestPointFinder finder(part);
  SUBCASE("on the axis every point of the arc is a foot at distance R") {
    for (double y : {0.0, 7.5, 30.0, 60.0}) {
      const ClosestPoint c = finder.project({0, y, 0});
      CHECK(c.distance == doctest::Approx(R).epsilon(1e-12));
      CHECK(c.signed_distance > 0);  // the axis is in the air
    }
  }
  SUBCASE("just below the axis: the foot is straight down") {
    for (double e : {1e-9, 1e-6, 1e-3, 0.5}) {
      const ClosestPoint c = finder.project({0.2 * e, 20, -e});
      const double rho = std::hypot(0.2 * e, e);
      CHECK(c.distance == doctest::Approx(R - rho).epsilon(1e-12));
      CHECK(c.location == FootLocation::interior);
    }
  }
  SUBCASE(
      "just above the axis: the interior stationary point is a maximum, the feet are the edges") {
    for (double e : {1e-6, 1e-3, 2.0}) {
      const Eigen::Vector3d q(0.1 * e, 20, e);  // slightly toward +x: the t = 2 pi edge is nearer
      const ClosestPoint c = finder.project(q);
      CHECK(c.location == FootLocation::domain_edge);
      CHECK(c.distance == doctest::Approx((q - Eigen::Vector3d(R, 20, 0)).norm()).epsilon(1e-12));
      check_against_oracle(finder, q);
    }
  }
}

TEST_CASE("full cylinder: points at the seam, across it and near the axis agree with brute force") {
  // One closed NURBS face: its seam (angle 0 = 2 pi) is a domain edge whose
  // cells are never pruned, while the cells next to it are.
  const double R = 25;
  const Part part = single_face(make_cylinder(R, 40, 0, 2 * M_PI));
  const ClosestPointFinder finder(part);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> angle(-0.2, 0.2), along(-5, 45), radius(0.02, 60);
  for (int k = 0; k < 30; ++k) {
    const double a = k < 3 ? 0.0 : angle(rng), rho = k == 0 ? 1e-7 : radius(rng);
    const Eigen::Vector3d q(rho * std::cos(a), along(rng), rho * std::sin(a));
    const ClosestPoint c = finder.project(q);
    const double y = std::clamp(q.y(), 0.0, 40.0);
    // The nearest point of the closed tube (its ends are open circles).
    CHECK(c.distance == doctest::Approx(std::hypot(std::abs(rho - R), q.y() - y)).epsilon(1e-10));
    check_against_oracle(finder, q);
  }
}

TEST_CASE("mould: random points near and far agree with brute force") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-15, 115), y(-15, 95), z(0, 50);
  for (int k = 0; k < 40; ++k) check_against_oracle(finder, {x(rng), y(rng), z(rng)});
}

TEST_CASE("mould: points along the normal of the dimple through its centre of curvature") {
  const Part part = mould();
  const Face& face = part.faces[0];
  // Find the tightest concave point (largest k1) on a grid.
  double best_k = 0;
  Eigen::Vector2d best_uv(0, 0);
  for (int i = 1; i < 100; ++i)
    for (int j = 1; j < 100; ++j) {
      const DifferentialGeometry g = face.geometry(i / 100.0, j / 100.0);
      if (g.k1 > best_k) {
        best_k = g.k1;
        best_uv = {i / 100.0, j / 100.0};
      }
    }
  REQUIRE(best_k > 0.05);
  const DifferentialGeometry g = face.geometry(best_uv.x(), best_uv.y());
  const ClosestPointFinder finder(part);
  // Before, at and beyond the centre of curvature (the evolute).
  for (double f : {0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 1.5, 2.5}) {
    const Eigen::Vector3d q = g.point + (f / best_k) * g.normal;
    check_against_oracle(finder, q);
    check_against_oracle(finder, q + 0.3 * g.d1);  // off the normal line
  }
}

TEST_CASE("mould: points beyond the domain edges and corners") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  for (const Eigen::Vector3d& q :
       {Eigen::Vector3d(-10, 40, 25), Eigen::Vector3d(110, 20, 10), Eigen::Vector3d(50, -8, 40),
        Eigen::Vector3d(30, 90, 22), Eigen::Vector3d(-5, -5, 30), Eigen::Vector3d(108, 85, 15)}) {
    const ClosestPoint c = finder.project(q);
    CHECK(c.location == FootLocation::domain_edge);
    check_against_oracle(finder, q);
  }
}

TEST_CASE("sharp ridge and valley between two planar faces: nearest face wins") {
  for (double ridge_z : {20.0, -20.0}) {
    Part part;
    part.faces.emplace_back("left", make_plane({0, 0, 0}, {50, 0, ridge_z}, {0, 40, 0}));
    part.faces.emplace_back("right", make_plane({50, 0, ridge_z}, {50, 0, -ridge_z}, {0, 40, 0}));
    const ClosestPointFinder finder(part);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> dx(-6, 6), y(0, 40), dz(-3, 15);
    for (int k = 0; k < 30; ++k) {
      const Eigen::Vector3d q(50 + dx(rng), y(rng), ridge_z + dz(rng));
      check_against_oracle(finder, q);
      // The winning face is the one whose own oracle distance is smaller.
      double own[2];
      for (int f = 0; f < 2; ++f) {
        Part alone;
        alone.faces.push_back(part.faces[f]);
        own[f] = brute_force(alone, q).distance;
      }
      const ClosestPoint c = finder.project(q);
      if (std::abs(own[0] - own[1]) > 1e-6) CHECK(c.face == (own[0] < own[1] ? 0u : 1u));
    }
    // Above the ridge line the foot is the ridge itself (convex case).
    if (ridge_z > 0) {
      const ClosestPoint c = finder.project({50, 10, ridge_z + 5});
      CHECK(c.distance == doctest::Approx(5).epsilon(1e-12));
      CHECK(c.location == FootLocation::domain_edge);
    }
  }
}

TEST_CASE("closest point on the other faces: brute force over the part without that face") {
  const Part part = read_part(test::source_path("examples/parts/two_face.json"));
  const ClosestPointFinder finder(part);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(20, 80), y(-5, 65), z(0, 30);
  for (int k = 0; k < 40; ++k) {
    const Eigen::Vector3d q(x(rng), y(rng), z(rng));
    for (std::size_t excluded = 0; excluded < 2; ++excluded) {
      const std::optional<ClosestPoint> c = finder.project_to_other_faces(q, excluded);
      REQUIRE(c.has_value());
      CHECK(c->face == 1 - excluded);
      Part other;
      other.faces.push_back(part.faces[1 - excluded]);
      CHECK(c->distance == doctest::Approx(brute_force(other, q).distance).epsilon(1e-9).scale(1e-9));
      CHECK(c->converged);
    }
  }
  Part single;
  single.faces.push_back(part.faces[0]);
  CHECK_FALSE(ClosestPointFinder(single).project_to_other_faces({50, 30, 10}, 0).has_value());
}

TEST_CASE("trimmed plane with a hole: the foot is on the hole's boundary polygon") {
  // uv is scaled differently along x and y, so the hole is an ellipse in 3-D.
  const Trim trim({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, uv_circle(0.5, 0.5, 0.2, 48)});
  const Part part = single_face(make_plane({0, 0, 0}, {100, 0, 0}, {0, 80, 0}), false, trim);
  const ClosestPointFinder finder(part);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(35, 65), y(28, 52), z(-4, 4);
  int in_hole = 0;
  for (int k = 0; k < 60; ++k) {
    const Eigen::Vector3d q(x(rng), y(rng), z(rng));
    const Eigen::Vector2d uv(q.x() / 100, q.y() / 80);
    double exact;
    if (trim.contains(uv)) {
      exact = std::abs(q.z());
    } else {  // nearest point of the 3-D hole polygon (the plane map is affine)
      ++in_hole;
      exact = std::numeric_limits<double>::infinity();
      const UvLoop& hole = trim.loops()[1];
      for (std::size_t s = 0; s < hole.size(); ++s) {
        const Eigen::Vector3d a(100 * hole[s].x(), 80 * hole[s].y(), 0);
        const Eigen::Vector3d b(100 * hole[(s + 1) % hole.size()].x(),
                                80 * hole[(s + 1) % hole.size()].y(), 0);
        const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        exact = std::min(exact, (a + t * (b - a) - q).norm());
      }
    }
    const ClosestPoint c = finder.project(q);
    CAPTURE(q.transpose());
    CHECK(std::abs(c.distance - exact) <= 1e-9);
    if (c.location == FootLocation::trim_edge)
      CHECK(trim.distance_to_boundary(c.uv) < 1e-12);
    else
      CHECK(trim.contains(c.uv));
  }
  CHECK(in_hole > 10);
}

TEST_CASE("oblique plate with 30 finely polygonised holes: the foot agrees with the exact polygon distance") {
  // As CAD import writes a drilled plate: one planar face, every hole a
  // 400-gon in (u, v), so a seed cell holds hundreds of trim segments (the
  // search orders and skips them by their bounding spheres). The plane is
  // tilted and the map affine: each trim segment's image is a straight 3-D
  // segment, so the exact answer is the orthogonal distance where the
  // projection is kept and the nearest boundary segment elsewhere.
  const Eigen::Vector3d origin(5, -3, 2), eu(100, 10, 25), ev(-8, 80, -15);
  std::vector<UvLoop> loops{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) loops.push_back(uv_circle(0.1 + 0.16 * i, 0.1 + 0.2 * j, 0.05, 400));
  const Trim trim(loops);
  const Part part = single_face(make_plane(origin, eu, ev), false, trim);
  const ClosestPointFinder finder(part);
  const Eigen::Vector3d normal = eu.cross(ev).normalized();
  Eigen::Matrix<double, 3, 2> map;
  map << eu, ev;
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-0.05, 1.05), offset(-3, 3);
  int in_hole = 0, outside = 0;
  for (int k = 0; k < 600; ++k) {
    const double reach = k % 5 == 0 ? 10 : 1;  // some points far off the plate
    const Eigen::Vector3d q = origin + map * Eigen::Vector2d(u(rng), u(rng)) + reach * offset(rng) * normal;
    const Eigen::Vector2d uv = (map.transpose() * map).ldlt().solve(map.transpose() * (q - origin));
    double exact;
    if (trim.contains(uv)) {
      exact = std::abs((q - origin).dot(normal));
    } else {
      in_hole += uv.minCoeff() > 0 && uv.maxCoeff() < 1;
      outside += !(uv.minCoeff() > 0 && uv.maxCoeff() < 1);
      exact = std::numeric_limits<double>::infinity();
      for (const UvLoop& loop : loops)
        for (std::size_t s = 0; s < loop.size(); ++s) {
          const Eigen::Vector3d a = origin + map * loop[s], b = origin + map * loop[(s + 1) % loop.size()];
          const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          exact = std::min(exact, (a + t * (b - a) - q).norm());
        }
    }
    const ClosestPoint c = finder.project(q);
    CAPTURE(k);
    CHECK(std::abs(c.distance - exact) <= 1e-9);
  }
  CHECK(in_hole > 20);
  CHECK(outside > 20);
}

TEST_CASE("trimmed mould with a hole over the dome: brute force agrees") {
  Part part = mould();
  const Face& f = part.faces[0];
  const Trim trim({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, uv_circle(0.35, 0.5, 0.15, 40)});
  part.faces[0] = Face(f.name(), f.surface(), trim, f.reversed());
  const ClosestPointFinder finder(part);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.15, 0.55), v(0.3, 0.7), h(-3, 6);
  int on_trim = 0;
  for (int k = 0; k < 25; ++k) {
    const double uu = u(rng), vv = v(rng);
    const DifferentialGeometry g = part.faces[0].geometry(uu, vv);
    const Eigen::Vector3d q = g.point + h(rng) * g.normal;
    check_against_oracle(finder, q);
    on_trim += finder.project(q).location == FootLocation::trim_edge;
  }
  CHECK(on_trim > 5);
}

TEST_CASE("a hint changes the cost, never the answer") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> x(0, 100), y(0, 80), z(10, 40);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d q(x(rng), y(rng), z(rng));
    const ClosestPoint cold = finder.project(q);
    const ClosestPoint near_hint = finder.project(q + Eigen::Vector3d(0.01, 0, 0), cold);
    const ClosestPoint warm = finder.project(q, finder.project(q + Eigen::Vector3d(3, -2, 1)));
    CHECK(std::abs(warm.distance - cold.distance) <= 1e-12);
    CHECK(near_hint.converged);
  }
}

// A CMM point's nominal (u,v) is the natural hint, and it sits on the normal
// line through q: a stationary point of the distance. Beyond the centre of
// curvature it is a saddle or maximum, and Newton from there can crawl along
// an almost flat valley up to its iteration cap. Found by bench_projection
// (points 20 mm off the mould); the hinted answer must still be the global,
// converged one.
TEST_CASE("a hint at a stationary point beyond the centre of curvature gives the cold answer") {
  const Part part = mould();
  const ClosestPointFinder finder(part);
  ClosestPoint hint;
  hint.face = 0;
  hint.uv = {0.29444521553662723, 0.57097231067760024};
  hint.point = part.faces[0].surface().point(hint.uv.x(), hint.uv.y());
  const Eigen::Vector3d q(30.588187818458294, 45.03498303255013, 11.978131817196406);
  const ClosestPoint cold = finder.project(q);
  const ClosestPoint warm = finder.project(q, hint);
  CHECK(cold.converged);
  CHECK(warm.converged);
  CHECK(std::abs(warm.distance - cold.distance) <= 1e-12);
  check_against_oracle(finder, q);
  // The same kind of hint over many points 20 mm off the surface.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1), h(-20, 20);
  int unconverged = 0;
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double uu = unit(rng), vv = unit(rng);
    const DifferentialGeometry g = part.faces[0].geometry(uu, vv);
    const Eigen::Vector3d p = g.point + h(rng) * g.normal;
    ClosestPoint nominal;
    nominal.face = 0;
    nominal.uv = {uu, vv};
    nominal.point = g.point;
    const ClosestPoint a = finder.project(p), b = finder.project(p, nominal);
    unconverged += !a.converged || !b.converged;
    worst = std::max(worst, std::abs(a.distance - b.distance));
  }
  CHECK(unconverged == 0);
  CHECK(worst <= 1e-9);
}

TEST_CASE("non-convergence is reported, not hidden") {
  const Part part = mould();
  ClosestPointOptions o;
  o.max_newton_iterations = 1;
  const ClosestPointFinder finder(part, o);
  int unconverged = 0;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> x(0, 100), y(0, 80), z(0, 50);
  for (int k = 0; k < 50; ++k) unconverged += !finder.project({x(rng), y(rng), z(rng)}).converged;
  CHECK(unconverged > 0);
  o.step_tolerance = 0;
  CHECK_THROWS_AS(ClosestPointFinder(part, o), InputError);
}

TEST_CASE("local segment solve finds the minimum along a uv line") {
  const NurbsSurface plane = make_plane({0, 0, 0}, {10, 0, 0}, {0, 10, 0});
  ClosestPointOptions o;
  const LocalFoot f = foot_point_on_segment(plane, {3, 7, 2}, {0, 0}, {1, 0}, o);
  CHECK(f.converged);
  CHECK((f.point - Eigen::Vector3d(3, 0, 0)).norm() < 1e-12);
  CHECK(f.uv.x() == doctest::Approx(0.3));
}
