// CAD import of IGES faces bounded by model-space curves only (type 142
// PPTR 0, every CRTN and PREF, either loop direction) on periodic surfaces
// other than spheres (docs/formats.md "IGES boundaries", "Orientation"):
// - torus patches as type 120 surfaces of revolution across one or both
//   seams and bands closed around the tube or the axis (where
//   OpenCASCADE's healing adds the whole torus's natural bound to the
//   face), each with a hole across a seam, against the analytic area
//   (patch less hole: both are rectangles in the torus's angles, area
//   r dtheta (R dpsi + r (sin psi1 - sin psi0))) and the file's normal;
// - closed shells of such faces, whose volume (solid_mass(), the faces'
//   divergence integral with their outward normals) must be the analytic
//   one and whose every face must point out: a torus of four patches each
//   across a seam (2 pi^2 R r^2), and a can whose side is two faces across
//   and beside the seam of a periodic type 128 B-spline cylinder, closed by
//   two planar type 128 discs (pi rho^2 h).
#include <doctest/doctest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "geometry/solid_mass.hpp"
#include "support/trimmed_area.hpp"
#include "iges_case_import.hpp"
#include "iges_revolved_patches.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kSpacing = 80;  // case k lies around x = k * kSpacing
const double pi = M_PI;

// The closed boundary of the rectangle theta0..theta1, s0..s1 of a torus
// patch (`p`'s fields) in model space: two circles about the axis and two
// circles of the tube, as rational type 126 arcs in a type 102, in the
// order write_revolved_patch() runs its outer loop (reversed: the other way).
int torus_rectangle(IgesBuilder& b, const RevolvedPatch& p, bool reversed) {
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  struct Corner {
    double s, theta;
  };
  std::vector<Corner> corners{{p.s0, p.theta0}, {p.s0, p.theta1}, {p.s1, p.theta1}, {p.s1, p.theta0}};
  if (reversed) corners = {corners[0], corners[3], corners[2], corners[1]};
  std::vector<int> pieces;
  for (std::size_t k = 0; k < 4; ++k) {
    const Corner& a = corners[k];
    const Corner& e = corners[(k + 1) % 4];
    if (a.s == e.s) {
      const Eigen::Vector2d g = p.generatrix(a.s);
      pieces.push_back(b.bspline_arc(p.centre + g.y() * Y, X, -Z, g.x(), a.theta, e.theta));
    } else {
      const Eigen::Vector3d d = std::cos(a.theta) * X - std::sin(a.theta) * Z;
      pieces.push_back(b.bspline_arc(p.centre + p.major * d, d, Y, p.radius, a.s, e.s));
    }
  }
  return b.composite(pieces);
}

// The type 120 torus's normal (Su x Sv with the tube's circle running
// counterclockwise and the rotation about +y): into the tube.
Eigen::Vector3d into_tube(const Eigen::Vector3d& centre, double major, const Eigen::Vector3d& q) {
  const Eigen::Vector3d r = q - centre;
  const Eigen::Vector3d radial = Eigen::Vector3d(r.x(), 0, r.z()).normalized();
  return -(r - major * radial).normalized();
}

}  // namespace

TEST_CASE("CAD import: IGES torus patches across the seams with holes, bounded by model-space curves only, in every CRTN and PREF") {
  struct Shape {
    double theta0, theta1, s0, s1;       // the patch
    double h_theta0, h_theta1, h_s0, h_s1;  // its hole
  };
  const std::vector<Shape> shapes = {
      {-0.8, 0.9, -1.2, 1.0, -0.3, 0.4, -0.5, 0.4},            // across both seams, the hole too
      {0.3, 2.0, 1.5 * pi, 2.5 * pi, 0.8, 1.4, 1.8 * pi, 2.2 * pi},  // across the tube's seam
      {0, pi, 0, 2 * pi, 1.0, 2.0, -0.4, 0.4},                 // the whole tube over half a turn, the hole on its seam
      {-pi / 2, pi / 2, 0.5, 2.0, -0.2, 0.3, 0.9, 1.5},        // across the axis seam, the hole too
      {0, 2 * pi, 0.5, 2.0, -0.3, 0.3, 1.0, 1.5},              // a band around the axis, the hole on its seam
  };
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (int crtn = 0; crtn <= 3; ++crtn)
      for (const bool reversed : {false, true}) {
        // Every CRTN with every PREF over the shapes (PREF = CRTN + shape
        // mod 4), both loop directions, the hole the other way than the
        // outer loop in half of them.
        const Shape& s = shapes[i];
        RevolvedPatch p;
        p.kind = RevolvedPatch::Kind::torus;
        p.centre = Eigen::Vector3d(kSpacing * static_cast<double>(cases.size()), 0, 0);
        p.theta0 = s.theta0, p.theta1 = s.theta1, p.s0 = s.s0, p.s1 = s.s1;
        p.model_space_only = true;
        p.crtn = crtn;
        p.pref = static_cast<int>((static_cast<std::size_t>(crtn) + i) % 4);
        p.reversed_loop = reversed;
        RevolvedPatch hole = p;
        hole.theta0 = s.h_theta0, hole.theta1 = s.h_theta1, hole.s0 = s.h_s0, hole.s1 = s.h_s1;
        const bool hole_reversed = reversed != (crtn % 2 == 1);
        write_revolved_patch(builder, p, {torus_rectangle(builder, hole, hole_reversed)});
        const Eigen::Vector3d centre = p.centre;
        const double major = p.major;
        cases.push_back({p.name() + (hole_reversed ? ", hole reversed" : ""), p.area() - hole.area(),
                         [centre, major](const Eigen::Vector3d& q) { return into_tube(centre, major, q); }});
      }
  check_case_file(builder, cases, "iges-torus-model-space-holes", kSpacing);
}

namespace {

// Imports `builder`'s file and checks that it is one closed shell of
// `faces` faces whose normal is `outward(q)` at every kept point q, whose
// faces' areas add up to `area` (within 1e-6, relative: the trim polygons'
// sag), and whose volume by solid_mass() is `volume` within `tolerance` [mm^3].
void check_closed_shell(const IgesBuilder& builder, const std::string& name, std::size_t faces,
                        const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& outward, double area,
                        double volume, double tolerance) {
  const std::string dir = scratch_dir(name + "-" + std::to_string(getpid()));
  builder.file.write(dir + "/shell.igs");
  const CadImportResult result = import_cad(dir + "/shell.igs");
  REQUIRE(result.part.faces.size() == faces);
  CHECK(result.closed_shells == 1);
  double total = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    CAPTURE(f);
    total += trimmed_area(result.part.faces[f]);
    CHECK(result.faces[f].orientation == CadFaceOrientation::closed_shell);
    CHECK(kept_share(result.part.faces[f], [&](const DifferentialGeometry& g) {
            return g.normal.dot(outward(g.point)) > 0.99;
          }) == 1.0);
  }
  CAPTURE(total);
  CHECK(std::abs(total - area) < 1e-6 * area);
  const SolidMass mass = solid_mass(result.part);
  CAPTURE(mass.volume);
  CAPTURE(volume);
  CHECK(mass.closed);
  CHECK(std::abs(mass.volume - volume) < tolerance);
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

}  // namespace

TEST_CASE("CAD import: a torus of four IGES patches across its seams, bounded by model-space curves only, closes outward") {
  // Each patch crosses the axis seam (theta 0) or the tube's (psi 0) or
  // both; the loops run either way, in every CRTN and PREF over the runs.
  // Oracle: the torus's volume 2 pi^2 R r^2 and the outward normal (away
  // from the tube's core circle) at every kept point.
  for (int crtn = 0; crtn <= 3; ++crtn) {
    CAPTURE(crtn);
    IgesBuilder builder;
    RevolvedPatch p;
    p.kind = RevolvedPatch::Kind::torus;
    for (int k = 0; k < 4; ++k) {
      p.theta0 = k / 2 == 0 ? -pi / 2 : pi / 2;
      p.theta1 = p.theta0 + pi;
      p.s0 = k % 2 == 0 ? -pi / 2 : pi / 2;
      p.s1 = p.s0 + pi;
      p.model_space_only = true;
      p.crtn = crtn;
      p.pref = (crtn + k) % 4;
      p.reversed_loop = (k + crtn) % 2 == 1;
      write_revolved_patch(builder, p);
    }
    const Eigen::Vector3d centre = p.centre;
    const double major = p.major;
    check_closed_shell(
        builder, "iges-torus-shell", 4,
        [centre, major](const Eigen::Vector3d& q) { return Eigen::Vector3d(-into_tube(centre, major, q)); },
        4 * pi * pi * p.major * p.radius, 2 * pi * pi * p.major * p.radius * p.radius,
        // The patches' trims are their whole rectangles: solid_mass()
        // integrates them untrimmed, by Gauss points, to ~1e-9.
        1e-6 * 2 * pi * pi * p.major * p.radius * p.radius);
  }
}

TEST_CASE("CAD import: a can of IGES faces on a periodic type 128 cylinder and planes, bounded by model-space curves only, closes outward") {
  // The side: the cylinder rho (cos u, sin u, z), u the angle, z 0..h, as a
  // type 128 closed and periodic in u (the rational quadratic circle times
  // a line, knots at quarter turns), in two faces: angles -pi/2..pi/2
  // (across its seam) and pi/2..3 pi/2. The ends: two planes as bilinear
  // type 128s, each bounded by the same two half circles. Every boundary
  // is model-space curves only; every face in two runs, each run holding
  // every CRTN (face k: CRTN base + k mod 4) and every PREF (base + 3 k mod
  // 4), loops either way. Oracle: pi rho^2 h, and the outward normal (radial on the
  // side, -z and +z on the ends).
  constexpr double rho = 6, h = 10;
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  for (const int base : {0, 2}) {
    CAPTURE(base);
    IgesBuilder builder;
    std::vector<std::vector<Eigen::Vector3d>> poles;
    std::vector<std::vector<double>> weights;
    const double corner = std::sqrt(0.5);
    for (int i = 0; i <= 8; ++i) {
      const double a = i * pi / 4;
      const double scale = i % 2 ? rho / corner : rho;
      const Eigen::Vector3d q(scale * std::cos(a), scale * std::sin(a), 0);
      poles.push_back({q, q + h * Z});
      weights.push_back({i % 2 ? corner : 1.0, i % 2 ? corner : 1.0});
    }
    const std::vector<double> knots_u{0, 0, 0, pi / 2, pi / 2, pi, pi, 1.5 * pi, 1.5 * pi, 2 * pi, 2 * pi, 2 * pi};
    auto at = [&](double theta, double z) { return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), z); };
    int run = 0;
    // The side's two faces.
    for (const double theta0 : {-pi / 2, pi / 2}) {
      const int surface = builder.bspline_surface(2, 1, knots_u, {0, 0, h, h}, poles, weights, true, true);
      const double theta1 = theta0 + pi;
      std::vector<std::array<double, 2>> corners{{theta0, 0}, {theta1, 0}, {theta1, h}, {theta0, h}};
      const int crtn = (base + run) % 4, pref = (base + 3 * run) % 4;
      const bool reversed = (run + base / 2) % 2 == 1;
      if (reversed) corners = {corners[0], corners[3], corners[2], corners[1]};
      std::vector<int> curves;
      for (std::size_t k = 0; k < 4; ++k) {
        const auto& a = corners[k];
        const auto& e = corners[(k + 1) % 4];
        curves.push_back(a[1] == e[1] ? builder.bspline_arc(a[1] * Z, X, Y, rho, a[0], e[0])
                                      : builder.line(at(a[0], a[1]), at(e[0], e[1])));
      }
      builder.trimmed_surface(surface, builder.curve_on_surface(surface, 0, builder.composite(curves), pref, crtn));
      ++run;
    }
    // The ends: bilinear planes over the square around the disc, each
    // bounded by the two half circles the side's faces end on.
    for (const double z : {0.0, h}) {
      const Eigen::Vector3d o(-rho - 1, -rho - 1, z);
      const double w = 2 * rho + 2;
      const int surface = builder.bspline_surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{o, o + w * Y}, {o + w * X, o + w * X + w * Y}},
                                                  {{1, 1}, {1, 1}}, false, false);
      const int crtn = (base + run) % 4, pref = (base + 3 * run) % 4;
      const bool reversed = (run + base / 2) % 2 == 1;
      const double a0 = reversed ? 1.5 * pi : -pi / 2, a1 = reversed ? -pi / 2 : 1.5 * pi;
      const double mid = 0.5 * (a0 + a1);
      const std::vector<int> halves{builder.bspline_arc(z * Z, X, Y, rho, a0, mid), builder.bspline_arc(z * Z, X, Y, rho, mid, a1)};
      builder.trimmed_surface(surface, builder.curve_on_surface(surface, 0, builder.composite(halves), pref, crtn));
      ++run;
    }
    check_closed_shell(
        builder, "iges-periodic-bspline-can", 4,
        [h](const Eigen::Vector3d& q) {
          if (q.z() < 1e-6) return Eigen::Vector3d(0, 0, -1);
          if (q.z() > h - 1e-6) return Eigen::Vector3d(0, 0, 1);
          return Eigen::Vector3d(Eigen::Vector3d(q.x(), q.y(), 0).normalized());
        },
        2 * pi * rho * h + 2 * pi * rho * rho, pi * rho * rho * h,
        // solid_mass() keeps or drops the trimmed cells' subcells (a 48th,
        // then a 6th, of the ends' 2 rho + 2 wide rectangle) whole: an area
        // error of at most a subcell's width along the circle 2 pi rho, which
        // counts h / 3 times over the top end (x . n = h) and not at all
        // over the bottom one (x . n = 0); the side is untrimmed.
        h / 3 * (2 * rho + 2) / (48 * 6) * 2 * pi * rho);
  }
}
