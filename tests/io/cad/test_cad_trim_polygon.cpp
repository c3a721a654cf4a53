// TrimPolygonBuilder (src/io/cad_trim_polygon): boundary curves to trim
// polygons. Oracles: the exact circle (distances of vertices and edge
// midpoints, the disc's area pi R^2) and the domain rectangle.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "io/cad/cad_trim_polygon.hpp"

using namespace furrow;

namespace {

// A 100 x 100 mm plane patch: (s,t) in [0,1]^2, 1 unit = 100 mm.
NurbsSurface square_plate() {
  return make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(100, 0, 0), Eigen::Vector3d(0, 100, 0));
}

BoundaryCurve circle(const Eigen::Vector2d& centre, double radius, double a0, double a1) {
  return {[=](double a) { return Eigen::Vector2d(centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a))); },
          a0, a1, false};
}

double polygon_area(const UvLoop& loop) {
  double twice = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector2d& p = loop[k];
    const Eigen::Vector2d& q = loop[(k + 1) % loop.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return std::abs(twice) / 2;
}

}  // namespace

TEST_CASE("Trim polygon: a circle is sampled within tolerance and its disc area is unbiased") {
  const NurbsSurface plate = square_plate();
  const Eigen::Vector2d centre(0.5, 0.4);
  for (double radius_mm : {2.0, 20.0}) {
    CAPTURE(radius_mm);
    const double r = radius_mm / 100;
    for (double tolerance : {1e-4, 1e-5, 1e-6}) {
      CAPTURE(tolerance);
      TrimPolygonOptions options;
      options.chord_tolerance = tolerance;
      TrimPolygonBuilder builder(plate, options);
      // Two half circles, as a CAD file often splits a closed edge.
      const UvLoop loop = builder.loop({circle(centre, r, 0, M_PI), circle(centre, r, M_PI, 2 * M_PI)});
      CHECK(builder.tolerance_met());
      CHECK(builder.worst_sag() <= tolerance);
      // Every vertex and edge midpoint lies within 2/3 of the sag (plus a
      // margin for the uneven edges) on either side of the circle.
      double worst = 0;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
        worst = std::max(worst, std::abs((a - centre).norm() * 100 - radius_mm));
        worst = std::max(worst, std::abs((0.5 * (a + b) - centre).norm() * 100 - radius_mm));
      }
      CHECK(worst <= 0.8 * tolerance);
      // Near-minimal count: an inscribed polygon with sag = tolerance needs
      // pi / acos(1 - tol/R) edges.
      const double minimal = M_PI / std::acos(1 - tolerance / radius_mm);
      CHECK(loop.size() >= minimal);
      CHECK(loop.size() <= 1.3 * minimal + 16);
      // Balanced: the inscribed polygon would be short by 4/3 tol/R.
      const double area = polygon_area(loop) * 1e4;
      const double disc = M_PI * radius_mm * radius_mm;
      CHECK(std::abs(area - disc) <= 1e-3 * (4.0 / 3.0) * tolerance / radius_mm * disc);
    }
  }
}

TEST_CASE("Trim polygon: straight boundaries stay exact, the domain rectangle is recognised") {
  const NurbsSurface plate = square_plate();
  TrimPolygonBuilder builder(plate, {});
  auto segment = [](Eigen::Vector2d a, Eigen::Vector2d b) {
    return BoundaryCurve{[=](double x) { return Eigen::Vector2d(a + x * (b - a)); }, 0, 1, false};
  };
  const Eigen::Vector2d c00(0, 0), c10(1, 0), c11(1, 1), c01(0, 1);
  const UvLoop loop =
      builder.loop({segment(c00, c10), segment(c10, c11), segment(c11, c01), segment(c01, c00)});
  REQUIRE(loop.size() == 4);
  CHECK(loop[0] == c00);
  CHECK(loop[1] == c10);
  CHECK(loop[2] == c11);
  CHECK(loop[3] == c01);
  CHECK(is_domain_rectangle({loop}, plate.domain()));
  CHECK_FALSE(is_domain_rectangle({loop, loop}, plate.domain()));
  // A rectangle inside the domain is a real trim.
  const UvLoop inner = builder.loop({segment({0.2, 0.2}, {0.8, 0.2}), segment({0.8, 0.2}, {0.8, 0.8}),
                                     segment({0.8, 0.8}, {0.2, 0.8}), segment({0.2, 0.8}, {0.2, 0.2})});
  CHECK_FALSE(is_domain_rectangle({inner}, plate.domain()));
  // A collapsed curve (a pole's line in the parameter plane) adds one straight edge.
  BoundaryCurve pole = segment(c01, c00);
  pole.collapsed = true;
  const UvLoop with_pole = builder.loop({segment(c00, c10), segment(c10, c11), segment(c11, c01), pole});
  CHECK(with_pole.size() == 4);
}

TEST_CASE("Trim polygon: an unreachable tolerance is reported, not looped on") {
  const NurbsSurface plate = square_plate();
  TrimPolygonOptions options;
  options.chord_tolerance = 1e-12;
  options.max_subdivisions = 3;
  TrimPolygonBuilder builder(plate, options);
  // The first-pass estimate is capped at 2^3 edges per coarse piece too.
  const UvLoop loop = builder.loop({circle({0.5, 0.5}, 0.3, 0, 2 * M_PI)});
  CHECK_FALSE(builder.tolerance_met());
  CHECK(builder.worst_sag() > 1e-12);
  CHECK(loop.size() <= 8 * 8 * 8 + 1);
}
