// Side contacts: a contact point whose normal is horizontal (n_z = 0, a
// vertical wall), touched by the side of the cutter (docs/architecture.md
// "Cutter geometry"). Every expected number comes from the cutter as the
// docs describe it (its profile written out below), from closed-form
// curvatures derived in the comments, or from brute force / finite
// differences on that profile -- never from the library's own results.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/error.hpp"
#include "geometry/part.hpp"
#include "geometry/primitives.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/contact_from_tip.hpp"
#include "machining/cutter/cutter_curvature.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/gouge/contact_sites.hpp"
#include "machining/gouge/local_gouge.hpp"
#include "machining/gouge/tool_selection.hpp"
#include "machining/prediction/path_contacts.hpp"

using namespace furrow;

namespace {

constexpr double kDeg = M_PI / 180;
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// The end mill of docs/architecture.md as a solid, written from its profile
// in the (rho, h) half-plane (rho from the axis, h above the tip): a flat
// bottom h = 0 for rho <= R - r, the corner arc of centre (R - r, r) and
// radius r, the cylindrical side rho = R above h = r (the shank, as tall as
// `height`). A point is inside when it is between the bottom and the top
// and within the profile's radius at its height.
struct SolidCutter {
  double R, r, height;
  double radius_at(double h) const {  // the profile's rho at height h (-1: none)
    if (h < 0 || h > height) return -1;
    if (h >= r) return R;
    return (R - r) + std::sqrt(std::max(0.0, r * r - (r - h) * (r - h)));
  }
  bool inside(const Eigen::Vector3d& tip, const Eigen::Vector3d& x) const {
    const double rho = std::hypot(x.x() - tip.x(), x.y() - tip.y());
    return rho <= radius_at(x.z() - tip.z());
  }
};

// The cutter's normal curvature at a contact P in the tangent direction t
// (unit, perpendicular to n), by finite differences on the solid: the
// cutter's surface seen from P along n (into the cutter) lies d(s) away at
// the offset s t, and the normal curvature is the limit of 2 d(s) / s^2
// (positive: the cutter bends away from the part, the part's convention).
// d(s) by bisection on inside(); +infinity when the cutter has no surface
// there within reach (below the sharp rim of a flat end mill).
double fd_cutter_curvature(const SolidCutter& c, const Eigen::Vector3d& tip, const Eigen::Vector3d& P,
                           const Eigen::Vector3d& n, const Eigen::Vector3d& t, double s = 1e-2) {
  const Eigen::Vector3d base = P + s * t;
  double lo = -1.0, hi = 1.0;  // outside at lo (the part side), inside at hi
  if (c.inside(tip, base + lo * n)) return -std::numeric_limits<double>::infinity();
  if (!c.inside(tip, base + hi * n)) return std::numeric_limits<double>::infinity();
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (c.inside(tip, base + mid * n) ? hi : lo) = mid;
  }
  return 2 * hi / (s * s);
}

// A part point with given principal curvatures and directions (the part's
// convention: positive where the part bends toward its normal, i.e. is
// concave as seen by the tool).
DifferentialGeometry part_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double k1,
                                const Eigen::Vector3d& d1, double k2) {
  DifferentialGeometry g;
  g.degenerate = false;
  g.point = p;
  g.normal = n;
  g.k1 = k1;
  g.k2 = k2;
  g.d1 = d1;
  g.d2 = n.cross(d1);  // (d1, d2, n) right-handed
  g.K = k1 * k2;
  g.H = 0.5 * (k1 + k2);
  return g;
}

// Where f (the brute-force excess k_part - k_tool - tol) is positive must be
// exactly where the library reports a gouge, away from the boundaries (a
// tenth of a degree: the FD curvature is good to ~1e-8 /mm). The directions
// are t = cos a z + sin a y in the wall's tangent plane; the cutter's
// curvature by finite differences on the solid located at `tip`.
void check_against_brute_force(const LocalGouge& g, const DifferentialGeometry& part, const SolidCutter& solid,
                               const Eigen::Vector3d& tip, const Eigen::Vector3d& y, double tol) {
  auto excess = [&](double a) {
    const Eigen::Vector3d t = std::cos(a) * kZ + std::sin(a) * y;
    return part.normal_curvature(t) - fd_cutter_curvature(solid, tip, part.point, part.normal, t);
  };
  int compared = 0;
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3600; ++k) {
    const double a = (k + 0.5) * 0.1 * kDeg;
    const double f = excess(a);
    best = std::max(best, f);
    if ((excess(a - 0.1 * kDeg) > tol) != (f > tol) || (excess(a + 0.1 * kDeg) > tol) != (f > tol)) continue;
    CAPTURE(a / kDeg);
    CAPTURE(f);
    CHECK(g.ranges.contains(a) == (f > tol));
    ++compared;
  }
  CHECK(compared > 3000);
  CHECK(g.max_excess == doctest::Approx(best).epsilon(1e-4).scale(1e-6));
}

}  // namespace

TEST_CASE("side contact: the cutter location at n_z = 0 is the lowest side point, T = P + R n - r z") {
  // Three cutters, a wall facing -y through P. The rule (docs/architecture.md
  // "Side contact"): the contact is the end of the corner arc, height r above
  // the tip (the rim, height 0, of a flat end mill).
  const Eigen::Vector3d P(3, -2, 7), n(0, -1, 0);
  const struct {
    double R, r;
  } tools[] = {{30, 10}, {5, 5}, {4, 0}};
  for (const auto& tool : tools) {
    CAPTURE(tool.R);
    CAPTURE(tool.r);
    const Cutter cutter("c", tool.R, tool.r);
    const CutterLocation loc = cutter_location(cutter, P, n);
    REQUIRE(loc.reachable);
    CHECK(loc.vertical);
    CHECK_FALSE(loc.horizontal);
    const Eigen::Vector3d expected = P + tool.R * n - tool.r * kZ;
    CHECK((loc.tip - expected).norm() < 1e-12);
    CHECK(loc.contact_angle == doctest::Approx(M_PI / 2));
    CHECK(loc.contact_radius == doctest::Approx(tool.R));
    CHECK(loc.contact_height == doctest::Approx(tool.r));
    // Brute force on the solid: it touches the wall's plane at P and stays on
    // the air side everywhere; P is the lowest point it has on the plane.
    const SolidCutter solid{tool.R, tool.r, 3 * tool.R};
    // Heights: a grid, plus the end of the corner arc and just around it.
    std::vector<double> heights = {tool.r, tool.r - 1e-6, tool.r + 1e-6};
    for (int i = 0; i <= 400; ++i) heights.push_back(solid.height * i / 400);
    double deepest = 1e300, lowest_touch = 1e300;
    for (const double h : heights) {
      const double rho = solid.radius_at(h);
      if (rho < 0) continue;
      for (int k = 0; k < 720; ++k) {
        const double phi = 2 * M_PI * k / 720;
        const Eigen::Vector3d x = loc.tip + Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), h);
        const double into_wall = -(x - P).dot(n);  // > 0: beyond the wall, in the material
        deepest = std::min(deepest, -into_wall);
        if (into_wall > -1e-9) lowest_touch = std::min(lowest_touch, x.z());
      }
    }
    CHECK(deepest > -1e-9);  // never inside the material
    CHECK(deepest < 1e-9);   // and touching
    // "Touching" within 1e-9 mm reaches sqrt(2 r 1e-9) below the equator on
    // the torus (tangent to the wall there); the rim of a flat end mill has
    // nothing below it.
    CHECK(lowest_touch <= P.z() + 1e-12);
    CHECK(lowest_touch >= P.z() - std::sqrt(2 * tool.r * 1e-9) - 1e-12);
    // Located against the other wall (+x normal) the same way.
    const CutterLocation east = cutter_location(cutter, P, Eigen::Vector3d(1, 0, 0));
    REQUIRE(east.reachable);
    CHECK((east.tip - (P + Eigen::Vector3d(tool.R, 0, -tool.r))).norm() < 1e-12);
  }
}

TEST_CASE("side contact: only the sign of n_z decides, -1e-12 is refused and +1e-300 is a side contact") {
  const Cutter bull("b", 30, 10);
  const Eigen::Vector3d P(1, 2, 3);
  const CutterLocation below = cutter_location(bull, P, Eigen::Vector3d(1, 0, -1e-12));
  CHECK_FALSE(below.reachable);
  CHECK_FALSE(cutter_curvature(bull, Eigen::Vector3d(1, 0, -1e-12)).reachable);
  const DifferentialGeometry wall_down = part_point(P, Eigen::Vector3d(1, 0, -1e-12), 0, kZ, 0);
  CHECK(check_local_gouge(bull, wall_down).status == GougeStatus::unreachable);

  const CutterLocation above = cutter_location(bull, P, Eigen::Vector3d(1, 0, 1e-300));
  REQUIRE(above.reachable);
  CHECK(above.vertical);
  CHECK((above.tip - (P + Eigen::Vector3d(30, 0, -10))).norm() < 1e-12);
  const CutterLocation zero = cutter_location(bull, P, Eigen::Vector3d(1, 0, 0));
  REQUIRE(zero.reachable);
  CHECK((zero.tip - above.tip).norm() < 1e-12);
  CHECK(cutter_location(bull, P, Eigen::Vector3d(1, 0, -0.0)).reachable);  // -0 is 0

  const CutterCurvature c = cutter_curvature(bull, Eigen::Vector3d(1, 0, 1e-300));
  REQUIRE(c.reachable);
  CHECK(c.side);
  CHECK((c.dir_max - kZ).norm() < 1e-12);  // the meridian points straight up
  CHECK(c.k_max == doctest::Approx(1 / 10.0));
  CHECK(c.k_min == doctest::Approx(1 / 30.0));
  CHECK(c.side_k_min == doctest::Approx(1 / 30.0));
  // Just off the wall the corner arc alone touches: no side piece.
  CHECK_FALSE(cutter_curvature(bull, Eigen::Vector3d(std::cos(0.01), 0, std::sin(0.01))).side);
}

TEST_CASE("side contact: bull-nose R30 r10 in a vertical bore, gouge ranges from the closed form") {
  // The part: a bore (a vertical cylinder of radius Rc about the z axis, the
  // material outside it), the tool inside, touching at P = (Rc, 0, z0) with
  // the part normal n = (-1, 0, 0) (out of the material, toward the bore's
  // axis), so theta0 = 90 deg.
  //
  // Part curvature (the conventions: positive where the surface bends toward
  // n): around the bore the section is the circle of radius Rc, centred on
  // the n side: +1/Rc horizontally; along the vertical generator 0. With a
  // tangent direction at angle a from +z (counter-clockwise about n),
  // t(a) = cos a z + sin a y, Euler: k_part(a) = sin^2 a / Rc.
  //
  // Cutter curvature at the contact (also positive: the cutter bends away
  // from the part, toward its own axis, along n):
  //   - up (cos a > 0) lies the cylindrical side, radius R: its generator is
  //     straight (0) and its parallel is the circle of radius R seen face on
  //     (the normal -n lies in the circle's plane, Meusnier factor
  //     sin 90 deg = 1): 1/R. Euler: k_up(a) = sin^2 a / R.
  //   - down (cos a < 0) lies the torus at its equator: the meridian is the
  //     corner arc of radius r (1/r), the parallel the circle of radius
  //     rho_c = (R - r) + r sin 90 deg = R, again seen face on: 1/R.
  //     Euler: k_down(a) = cos^2 a / r + sin^2 a / R.
  // (Equivalently: the normal curvature of the cutter's surface measured
  // with its own outward normal -n is -1/R around the equator and -1/r down
  // the meridian; with the part's n both change sign.)
  //
  // Gouge where f(a) = k_part - k_tool > tol:
  //   up:   sin^2 a (1/Rc - 1/R) > tol        -> sin^2 a > tol / (1/Rc - 1/R)
  //   down: sin^2 a (1/Rc - 1/R) - cos^2 a / r > tol
  //         -> sin^2 a > (1/r + tol) / (1/Rc - 1/R + 1/r)
  // for Rc < R (both need 1/Rc > 1/R). With s_up, s_down those bounds on
  // |sin a|, the ranges are [asin s_up, 180 - asin s_down] (through the
  // horizontal +y) and [180 + asin s_down, 360 - asin s_up], not symmetric
  // about the horizontal because the side above is straight and the torus
  // below is not. The largest excess is at a = 90: 1/Rc - 1/R.
  const double R = 30, r = 10;
  const Cutter bull("bull", R, r);
  const SolidCutter solid{R, r, 3 * R};
  GougeOptions options;
  options.quick_accept = false;  // the ranges and the exact maximum
  const double tol = options.curvature_tolerance;
  const Eigen::Vector3d n(-1, 0, 0), y(0, 1, 0);
  for (const double Rc : {20.0, 25.0, 29.0}) {
    CAPTURE(Rc);
    const Eigen::Vector3d P(Rc, 0, 4);
    const DifferentialGeometry g = part_point(P, n, 1 / Rc, y, 0.0);
    const LocalGouge result = check_local_gouge(bull, g, options);
    REQUIRE(result.status == GougeStatus::gouge);
    REQUIRE(result.cutter.side);
    REQUIRE((result.cutter.dir_max - kZ).norm() < 1e-12);
    REQUIRE((result.cutter.dir_min - y).norm() < 1e-12);
    const double c = 1 / Rc - 1 / R;
    const double s_up = std::sqrt(tol / c), s_down = std::sqrt((1 / r + tol) / (c + 1 / r));
    REQUIRE(result.ranges.size() == 2);
    const AngularRange& first = result.ranges[0];
    const AngularRange& second = result.ranges[1];
    CHECK(first.start == doctest::Approx(std::asin(s_up)).epsilon(1e-9));
    CHECK(first.end() == doctest::Approx(M_PI - std::asin(s_down)).epsilon(1e-9));
    CHECK(second.start == doctest::Approx(M_PI + std::asin(s_down)).epsilon(1e-9));
    CHECK(second.end() == doctest::Approx(2 * M_PI - std::asin(s_up)).epsilon(1e-9));
    CHECK(result.max_excess == doctest::Approx(c).epsilon(1e-9));
    CHECK(std::abs(std::sin(result.max_excess_angle)) == doctest::Approx(1.0));
    // Brute force: the cutter's curvature by finite differences on the
    // solid located at the tip the docs give, the part's from Euler.
    const Eigen::Vector3d tip = P + R * n - r * kZ;
    check_against_brute_force(result, g, solid, tip, y, tol);
  }
  // A bore wider than the cutter only touches: the tie is straight up (the
  // side's generator against the bore's), max excess exactly 0.
  const DifferentialGeometry wide = part_point({40, 0, 4}, n, 1 / 40.0, y, 0.0);
  const LocalGouge clear = check_local_gouge(bull, wide, options);
  CHECK(clear.status == GougeStatus::clear);
  CHECK(std::abs(clear.max_excess) < 1e-15);
  // Outside a boss (convex wall, material inside a cylinder of radius 15):
  // k_part = -sin^2 a / 15 <= 0, clear with the same tie.
  const DifferentialGeometry boss = part_point({15, 0, 4}, Eigen::Vector3d(1, 0, 0), 0.0, kZ, -1 / 15.0);
  const LocalGouge outside = check_local_gouge(bull, boss, options);
  CHECK(outside.status == GougeStatus::clear);
  CHECK(std::abs(outside.max_excess) < 1e-15);
  // With quick accept the clear verdicts stand (the cutter's smallest
  // curvature at a side contact is the side's 0, up the wall).
  CHECK(check_local_gouge(bull, wide).status == GougeStatus::clear);
  CHECK(check_local_gouge(bull, part_point({20, 0, 4}, n, 1 / 20.0, y, 0.0)).status == GougeStatus::gouge);
}

TEST_CASE("side contact: a ball at the equator of a spherical bowl gouges upward with its shank") {
  // The inside of a sphere of radius rho (the material outside), at its
  // equator: the wall is vertical there, n = (-1, 0, 0) toward the centre,
  // and the part bends toward n by 1/rho in every direction (umbilic).
  // A ball of radius R < rho: below the equator its sphere, 1/R in every
  // direction: f = 1/rho - 1/R < 0, clear. Above, its straight shank:
  // k_up(a) = sin^2 a / R, so f(a) = 1/rho - sin^2 a / R > tol for
  // sin^2 a < R (1/rho - tol): one range centred on straight up,
  // [-asin s, asin s] with s = sqrt(R (1/rho - tol)). (The bowl closes in
  // above the equator while the shank goes straight up: a gouge the sphere
  // alone would not show.) The largest excess is 1/rho, straight up.
  const double R = 5, rho = 20;
  const Cutter ball("ball", R, R);
  const SolidCutter solid{R, R, 4 * R};
  GougeOptions options;
  options.quick_accept = false;
  const double tol = options.curvature_tolerance;
  const Eigen::Vector3d P(rho, 0, 0), n(-1, 0, 0), y(0, 1, 0);
  const DifferentialGeometry g = part_point(P, n, 1 / rho, y, 1 / rho);
  const LocalGouge result = check_local_gouge(ball, g, options);
  REQUIRE(result.status == GougeStatus::gouge);
  REQUIRE(result.ranges.size() == 1);
  const double s = std::sqrt(R * (1 / rho - tol));
  CHECK(result.ranges[0].start == doctest::Approx(2 * M_PI - std::asin(s)).epsilon(1e-9));
  CHECK(result.ranges[0].width == doctest::Approx(2 * std::asin(s)).epsilon(1e-9));
  CHECK(result.max_excess == doctest::Approx(1 / rho).epsilon(1e-9));
  CHECK((result.direction(result.max_excess_angle) - kZ).norm() < 1e-9);
  const Eigen::Vector3d tip = P + R * n - R * kZ;
  check_against_brute_force(result, g, solid, tip, y, tol);
  // On a plane wall the ball only touches (the tie straight up).
  const LocalGouge plane = check_local_gouge(ball, part_point(P, n, 0, y, 0), options);
  CHECK(plane.status == GougeStatus::clear);
  CHECK(std::abs(plane.max_excess) < 1e-15);
}

TEST_CASE("side contact: a flat end mill in a bore cuts with its side above the rim, not below it") {
  // r = 0: the contact is the rim (height 0 above the tip). Up: the
  // cylinder, f = sin^2 a (1/Rc - 1/R) as for the bull-nose. Down: nothing
  // of the cutter lies below the rim, so only the horizontal circle can
  // cut (+-90 deg, the cylinder's directions too). Ranges:
  // [asin s_up, 90] and [270, 360 - asin s_up], s_up = sqrt(tol / (1/Rc - 1/R)).
  const double R = 8, Rc = 6;
  const Cutter flat("flat", R, 0);
  const SolidCutter solid{R, 0, 4 * R};
  GougeOptions options;
  options.quick_accept = false;
  const double tol = options.curvature_tolerance;
  const Eigen::Vector3d P(Rc, 0, 2), n(-1, 0, 0), y(0, 1, 0);
  const DifferentialGeometry g = part_point(P, n, 1 / Rc, y, 0.0);
  const LocalGouge result = check_local_gouge(flat, g, options);
  REQUIRE(result.status == GougeStatus::gouge);
  CHECK(result.cutter.sharp);
  CHECK(result.cutter.side);
  const double c = 1 / Rc - 1 / R, s_up = std::sqrt(tol / c);
  REQUIRE(result.ranges.size() == 2);
  CHECK(result.ranges[0].start == doctest::Approx(std::asin(s_up)).epsilon(1e-9));
  CHECK(result.ranges[0].end() == doctest::Approx(M_PI / 2).epsilon(1e-12));
  CHECK(result.ranges[1].start == doctest::Approx(1.5 * M_PI).epsilon(1e-12));
  CHECK(result.ranges[1].end() == doctest::Approx(2 * M_PI - std::asin(s_up)).epsilon(1e-9));
  CHECK(result.max_excess == doctest::Approx(c).epsilon(1e-9));
  const Eigen::Vector3d tip = P + R * n;  // r = 0: the rim at the contact's height
  check_against_brute_force(result, g, solid, tip, y, tol);
}

TEST_CASE("side contact: tool selection and the contact under a tip at a vertical wall") {
  // A plane wall facing -y (Su x Sv = (10,0,0) x (0,0,10) = (0,-100,0)).
  Part part;
  part.faces.emplace_back("wall", make_plane({0, 0, 0}, {10, 0, 0}, {0, 0, 10}));
  const DifferentialGeometry g = part.faces[0].geometry(0.5, 0.5);
  REQUIRE(g.normal.z() >= 0);
  REQUIRE(std::abs(g.normal.y() + 1) < 1e-15);
  const std::vector<Cutter> library = {Cutter("ball", 3, 3), Cutter("bull", 4, 1), Cutter("flat", 2, 0)};
  // A plane cannot be gouged by a convex cutter touching it, and the cutter
  // at the wall (brute-forced above: it stays on the air side) touches
  // nothing else here: every site is machinable and the largest tool
  // (bull, R = 4) is gouge-free everywhere.
  std::vector<ContactSite> sites;
  for (const double u : {0.3, 0.5, 0.7})
    for (const double v : {0.2, 0.5, 0.8}) {
      ContactSite site;
      site.uv = {u, v};
      sites.push_back(site);
    }
  const ToolSelection sel = select_tools(part, library, sites);
  REQUIRE(sel.sites.size() == sites.size());
  for (const SiteSelection& s : sel.sites) {
    CAPTURE(s.site.uv.transpose());
    CHECK(s.machinable);
    CHECK(s.tool == 0);
    CHECK(sel.library[0].name() == "bull");
    CHECK(s.interference == 0.0);
  }
  // The cutter lowered at the tip of a side contact does not rest on the
  // wall it touches: its side slides down it (docs/architecture.md "Side
  // contact"), so nothing holds it here.
  for (const Cutter& cutter : library) {
    CAPTURE(cutter.name());
    const CutterLocation loc = cutter_location(cutter, g.point, g.normal);
    REQUIRE(loc.reachable);
    const TipContactFinder finder(part, cutter);
    const TipContactResult found = finder.find(loc.tip);
    CHECK(found.contacts.empty());
  }
}

TEST_CASE("side contact: a contact-point path on a wall is located with the side, n_z < 0 is bad input") {
  Part part;
  part.faces.emplace_back("wall", make_plane({0, 0, 0}, {10, 0, 0}, {0, 0, 10}));
  const Cutter bull("bull", 4, 1);
  Toolpath path;
  path.kind = ToolpathKind::contact_points;
  path.source = "wall.csv";
  ToolpathPass pass;
  for (int k = 0; k < 3; ++k) {
    ToolpathPoint p;
    p.position = {2.0 + 3 * k, 0, 5};
    p.normal = {0, -1, k == 1 ? 1e-300 : 0.0};
    p.line = k + 2;
    pass.points.push_back(p);
  }
  path.passes.push_back(pass);
  const PathGeometry located = locate_path(part, bull, path);
  REQUIRE(located.passes.size() == 1);
  for (int k = 0; k < 3; ++k) {
    const PathPoint& p = located.passes[0][k];
    CHECK(p.contact.valid);
    CHECK((p.tip - Eigen::Vector3d(2.0 + 3 * k, -4, 4)).norm() < 1e-12);  // P + R n - r z
  }
  path.passes[0].points[1].normal = {0, -1, -1e-12};
  CHECK_THROWS_WITH_AS(locate_path(part, bull, path), doctest::Contains("wall.csv:3"), InputError);
}
