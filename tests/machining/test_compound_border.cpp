#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "cutter_reference.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/gouge/compound_border.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kDeg = M_PI / 180;

// The valley wall's curvature across the edge x = 50 at height y (the
// example's defining formula: z = 10 + 0.02 (50 - x)^2 (1 + 0.5 ((y-30)/30)^2)).
double valley_curvature_across(double y) { return 0.04 * (1 + 0.5 * std::pow((y - 30) / 30, 2)); }

}  // namespace

TEST_CASE("two-face part: the border finds the neighbour and compares each face over its own half") {
  const Part part = read_part(source_path("examples/parts/two_face.json"));
  REQUIRE(part.faces.size() == 2);
  const BorderLocator locator(part);
  const double tol = GougeOptions().curvature_tolerance;
  int gouging = 0;
  for (double v : {0.0, 0.1, 0.3, 0.5, 0.75, 1.0}) {
    const ContactSurfaces c = contact_surfaces(locator, 0, {1.0, v});  // valley_wall's x = 50 edge
    CAPTURE(v);
    REQUIRE(c.has_neighbour);
    CHECK(part.faces[c.neighbour_face].name() == "crown");
    CHECK(c.neighbour_uv.x() == doctest::Approx(0).scale(1));
    CHECK(c.neighbour_uv.y() == doctest::Approx(v).epsilon(1e-9));
    CHECK_FALSE(c.crease);
    REQUIRE(c.inward_count == (v == 0.0 || v == 1.0 ? 2 : 1));
    CHECK(c.inward[0].x() == doctest::Approx(-1).epsilon(1e-12));  // into the valley: -x
    const double y = 60 * v;
    const double k_valley = valley_curvature_across(y);

    for (double R : {15.0, 20.0, 22.0, 30.0}) {
      CAPTURE(R);
      const Cutter ball("ball", R, R);
      const LocalGouge border = check_contact(ball, c);
      // Analytic: only the valley can gouge (the crown is convex), in the
      // directions within the valley's half where 0.04 b(y) cos^2 > 1/R.
      const bool expected = k_valley > 1 / R + tol;
      CHECK(border.gouges() == expected);
      if (!expected) continue;
      ++gouging;
      CHECK(border.max_excess == doctest::Approx(k_valley - 1 / R).epsilon(1e-9));
      if (c.inward_count == 1) {
        // One range only (the valley side), centred on -x.
        REQUIRE(border.ranges.size() == 1);
        const AngularRange& range = border.ranges[0];
        CHECK(border.direction(range.start + 0.5 * range.width).x() == doctest::Approx(-1).epsilon(1e-9));
        CHECK(range.width == doctest::Approx(2 * std::acos(std::sqrt((1 / R + tol) / k_valley))).epsilon(1e-9));
        // Treated as an interior point of the valley wall instead, both
        // opposite ranges would be reported.
        CHECK(check_local_gouge(ball, c.geometry).ranges.size() == 2);
      }

      // Brute force: every 0.01 degrees, the direction's curvature from the
      // face it points into (fundamental forms), against the ball's 1/R.
      const SurfaceDerivatives dv = part.faces[0].surface().evaluate(1.0, v, 2);
      const SurfaceDerivatives dc = part.faces[1].surface().evaluate(0.0, v, 2);
      auto excess = [&](double a_deg) {
        const Eigen::Vector3d t = border.direction(a_deg * kDeg);
        // Into the valley (x < 50) and, at the corners, also along +-y into
        // the face: the valley's quarter is t.x <= 0 and t.y inward.
        bool into_valley = t.x() < 0, into_crown = t.x() > 0;
        if (v == 0.0) into_valley &= t.y() > 0, into_crown &= t.y() > 0;
        if (v == 1.0) into_valley &= t.y() < 0, into_crown &= t.y() < 0;
        double k = -1e9;
        if (into_valley) k = part_normal_curvature(dv, c.geometry.normal, t);
        if (into_crown) k = part_normal_curvature(dc, c.neighbour_geometry.normal, t);
        return k - 1 / R - tol;
      };
      const std::vector<double> bounds = sign_changes_deg(excess, 0.01);
      std::vector<double> reported;
      for (const AngularRange& range : border.ranges) {
        reported.push_back(range.start / kDeg);
        reported.push_back(std::fmod(range.end() / kDeg, 360.0));
      }
      REQUIRE(reported.size() == bounds.size());
      for (std::size_t i = 0; i < bounds.size(); ++i) {
        double nearest = 360;
        for (double x : reported) nearest = std::min(nearest, angle_gap_deg(x, bounds[i]));
        CHECK(nearest < 0.01);
      }
    }
  }
  CHECK(gouging >= 10);

  // The same edge seen from the crown: the valley is its neighbour.
  const ContactSurfaces from_crown = contact_surfaces(locator, 1, {0.0, 0.5});
  REQUIRE(from_crown.has_neighbour);
  CHECK(part.faces[from_crown.neighbour_face].name() == "valley_wall");
  CHECK(check_contact(Cutter("ball", 30, 30), from_crown).gouges());
  // An interior point of the crown: convex, never gouges.
  CHECK(check_contact(Cutter("ball", 30, 30), contact_surfaces(locator, 1, {0.5, 0.5})).status == GougeStatus::clear);
}

TEST_CASE("faces meeting along trim curves: the same half-circle rule as at a domain side") {
  // A plane z = 0 and a trough z = c (x - 50)^2, both over x, y in [0, 100]
  // and trimmed to x <= 50 and x >= 50: they meet tangentially along x = 50,
  // which is a trim curve of both and a domain side of neither. Across the
  // edge the plane is flat and the trough curves k = 2c (concave: > 0).
  const double c = 0.025, k_trough = 2 * c;
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {100, 0, 0}, {0, 100, 0}),
                          Trim({{{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}}}));
  const double z_end = c * 2500;  // z at x = 0 and x = 100; the middle control point makes z(50) = 0
  part.faces.emplace_back(
      "trough",
      NurbsSurface(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1},
                   {{{0, 0, z_end}, {0, 100, z_end}}, {{50, 0, -z_end}, {50, 100, -z_end}}, {{100, 0, z_end}, {100, 100, z_end}}}),
      Trim({{{0.5, 0}, {1, 0}, {1, 1}, {0.5, 1}}}));
  const BorderLocator locator(part);
  const double tol = GougeOptions().curvature_tolerance;
  const Cutter ball("ball", 30, 30);  // 1/R = 0.033 < k_trough: gouges toward the trough
  for (const std::size_t face : {std::size_t{0}, std::size_t{1}}) {
    CAPTURE(face);
    const ContactSurfaces on_edge = contact_surfaces(locator, face, {0.5, 0.37});
    CHECK(on_edge.sides == kTrimEdge);
    REQUIRE(on_edge.inward_count == 1);
    CHECK(on_edge.inward[0].x() == doctest::Approx(face == 0 ? -1 : 1).epsilon(1e-12));
    REQUIRE(on_edge.has_neighbour);
    CHECK(on_edge.neighbour_face == 1 - face);
    CHECK((on_edge.neighbour_uv - Eigen::Vector2d(0.5, 0.37)).norm() < 1e-9);
    CHECK(on_edge.border_search_converged);
    CHECK_FALSE(on_edge.crease);
    const LocalGouge g = check_contact(ball, on_edge);
    REQUIRE(g.gouges());
    CHECK(g.max_excess == doctest::Approx(k_trough - 1.0 / 30).epsilon(1e-9));
    // One range, centred on +x (into the trough), as wide as k cos^2 > 1/R allows.
    REQUIRE(g.ranges.size() == 1);
    const AngularRange& range = g.ranges[0];
    CHECK(g.direction(range.start + 0.5 * range.width).x() == doctest::Approx(1).epsilon(1e-9));
    CHECK(range.width == doctest::Approx(2 * std::acos(std::sqrt((1.0 / 30 + tol) / k_trough))).epsilon(1e-9));
  }
  // Without the trim edge the plane's point would be flat all round.
  CHECK_FALSE(check_local_gouge(ball, contact_surfaces(locator, 0, {0.5, 0.37}).geometry).gouges());
  // Off the edge the faces are interior points again.
  CHECK(contact_surfaces(locator, 0, {0.3, 0.37}).sides == 0u);
  CHECK(contact_surfaces(locator, 1, {0.7, 0.37}).sides == 0u);
  // A smaller ball clears both sides.
  CHECK_FALSE(check_contact(Cutter("ball", 15, 15), contact_surfaces(locator, 0, {0.5, 0.37})).gouges());
}

TEST_CASE("two-face border with a bull-nose: the flat bottom goes over the crown, so no gouge") {
  const Part part = read_part(source_path("examples/parts/two_face.json"));
  const BorderLocator locator(part);
  const ContactSurfaces c = contact_surfaces(locator, 0, {1.0, 0.5});
  REQUIRE(std::hypot(c.geometry.normal.x(), c.geometry.normal.y()) < 1e-9);  // a horizontal contact
  const Cutter bull("bull", 5, 2);
  const LocalGouge border = check_contact(bull, c);
  CHECK(border.status == GougeStatus::clear);
  CHECK(border.cutter.flat_bottom);
  CHECK(border.cutter.toward_axis.x() == doctest::Approx(1));  // the axis over the crown
  // Alone (no border), the valley's concavity sits under the flat bottom in
  // some direction whatever the axis side: a gouge.
  CHECK(check_local_gouge(bull, c.geometry).gouges());
  // A corner radius tighter than the valley: gouges on the valley side.
  CHECK(check_contact(Cutter("bull", 40, 30), c).gouges());
}

TEST_CASE("creases: a concave V edge is reported, a convex ridge is not a gouge") {
  // Two planes meeting along x = 10, tilted by 20 degrees each.
  const double s = std::tan(20 * kDeg) * 10;
  for (const bool valley : {true, false}) {
    const double zs = valley ? s : -s;
    Part part;
    part.faces.emplace_back("left", make_bilinear({0, 0, zs}, {10, 0, 0}, {0, 10, zs}, {10, 10, 0}));
    part.faces.emplace_back("right", make_bilinear({10, 0, 0}, {20, 0, zs}, {10, 10, 0}, {20, 10, zs}));
    const BorderLocator locator(part);
    const ContactSurfaces c = contact_surfaces(locator, 0, {1.0, 0.5});
    REQUIRE(c.has_neighbour);
    CHECK(c.crease);
    CHECK(c.crease_angle == doctest::Approx(40 * kDeg).epsilon(1e-9));
    CHECK(c.concave_crease == valley);
    const LocalGouge r = check_contact(Cutter("ball", 3, 3), c);
    CHECK(r.status == (valley ? GougeStatus::concave_crease : GougeStatus::clear));
  }
}

TEST_CASE("domain sides and inward directions") {
  const ParameterDomain d{0, 2, -1, 1};
  CHECK(domain_sides(d, {0, 0}, 1e-9) == kSideUMin);
  CHECK(domain_sides(d, {2, 1}, 1e-9) == (kSideUMax | kSideVMax));
  CHECK(domain_sides(d, {1, 0}, 1e-9) == 0u);
  const Face plane("p", make_plane({0, 0, 0}, {10, 0, 0}, {0, 5, 0}));
  const SurfaceDerivatives sd = plane.surface().evaluate(1, 0, 1);
  const BorderDirections b = border_directions(plane, {1, 0}, sd, Eigen::Vector3d::UnitZ(), BorderOptions());
  CHECK(b.sides == (kSideUMax | kSideVMin));
  REQUIRE(b.count == 2);
  CHECK((b.inward[0] - Eigen::Vector3d(-1, 0, 0)).norm() < 1e-12);
  CHECK((b.inward[1] - Eigen::Vector3d(0, 1, 0)).norm() < 1e-12);
}

TEST_CASE("the seam of a closed face is not a border, its ends are") {
  // A whole tube: u runs once round (the sides u = u0 and u = u1 are the same
  // line in space), v along the axis (y in [0, 50]).
  const Face tube("tube", make_cylinder(10, 50, 0, 2 * M_PI));
  const ParameterDomain& d = tube.domain();
  auto sides_at = [&](double u, double v) {
    const SurfaceDerivatives sd = tube.surface().evaluate(u, v, 1);
    return border_directions(tube, {u, v}, sd, tube.geometry(sd).normal, BorderOptions()).sides;
  };
  const double v_mid = 0.5 * (d.v0 + d.v1);
  CHECK(sides_at(d.u0, v_mid) == 0u);
  CHECK(sides_at(d.u1, v_mid) == 0u);
  CHECK(sides_at(d.u0, d.v0) == unsigned(kSideVMin));
  CHECK(sides_at(d.u1, d.v1) == unsigned(kSideVMax));
  // Half a tube has real sides there.
  const Face half("half", make_cylinder(10, 50, 0, M_PI));
  const SurfaceDerivatives sd = half.surface().evaluate(half.domain().u0, v_mid, 1);
  CHECK(border_directions(half, {half.domain().u0, v_mid}, sd, half.geometry(sd).normal, BorderOptions()).sides ==
        unsigned(kSideUMin));
}

TEST_CASE("a neighbour search that cannot converge says so instead of passing for a free edge") {
  const Part part = read_part(source_path("examples/parts/two_face.json"));
  const Eigen::Vector2d on_edge(1.0, 0.37);  // valley_wall's x = 50 edge, between seed cells
  const ContactSurfaces converged = contact_surfaces(BorderLocator(part), 0, on_edge);
  CHECK(converged.border_search_converged);
  CHECK(converged.has_neighbour);

  BorderOptions capped;
  capped.closest.max_newton_iterations = 1;  // one Newton step cannot also confirm its own convergence
  const BorderLocator starved(part, capped);
  const BorderNeighbour nb = starved.neighbour(0, part.faces[0].surface().point(on_edge.x(), on_edge.y()));
  CHECK_FALSE(nb.converged);
  CHECK_FALSE(contact_surfaces(starved, 0, on_edge).border_search_converged);
  // An interior point never searches.
  CHECK(contact_surfaces(starved, 0, {0.5, 0.5}).border_search_converged);
}
