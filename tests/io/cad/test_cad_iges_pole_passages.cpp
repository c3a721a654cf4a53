// CAD import of IGES sphere faces (type 144 of a type 120) bounded by
// model-space curves only (type 142 PPTR 0) that pass through a pole of the
// sphere in their interior, not at their ends (docs/formats.md "IGES
// boundaries"): there the rotation angle jumps, by half a turn for a
// great circle, which the importer must leave free as it does where two
// curves meet at a pole. Cases, each in every CRTN and PREF and either
// loop direction:
// - a quarter sphere bounded by half a great circle over a pole and half
//   the equator (pi R^2);
// - caps whose boundary circle passes through a pole (2 pi R^2 (1 - cos
//   alpha)), across the seam or not;
// - a half sphere bounded by one full great circle through both poles,
//   which encloses a half on either side: the face is the one lying in the
//   file's own parameter rectangle (IGES 5.3 type 144).
// Oracles: analytic area and centroid (a half sphere's surface: R / 2 from
// the centre along its middle direction; a cap's at R (1 + cos alpha) / 2
// along its axis; the quarter's by the patch formula, patch_centroid()),
// and the file's surface normal, into the sphere.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "iges_case_import.hpp"
#include "iges_revolved_patches.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kSpacing = 80;  // case k lies around x = k * kSpacing
const double pi = M_PI;

// Writes every case of `make` in every CRTN, PREF and direction.
template <class Make>
void check_pole_cases(const std::string& file_name, Make make) {
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (int crtn = 0; crtn <= 3; ++crtn)
    for (int pref = 0; pref <= 3; ++pref)
      for (const bool reversed : {false, true}) {
        // make() writes its shapes, each on a sphere at the next place.
        make(builder, cases, crtn, pref, reversed);
      }
  check_case_file(builder, cases, file_name, kSpacing);
}

// The sphere's surface for the next case (the writer's type 120: axis +y,
// generatrix south to north, a whole turn), its centre in `centre`.
int next_sphere(IgesBuilder& b, const std::vector<ExpectedFace>& cases, SpherePatch& sphere) {
  sphere.centre = Eigen::Vector3d(kSpacing * static_cast<double>(cases.size()), 0, 0);
  double arc_start = 0;
  return write_sphere_surface(b, sphere, arc_start);
}

// The face bounded by `curves` (in running order; reversed: each curve is
// written reversed and the order turned round by the caller) on `surface`.
void add_face(IgesBuilder& b, int surface, const std::vector<int>& curves, int crtn, int pref) {
  b.trimmed_surface(surface, b.curve_on_surface(surface, 0, curves.size() == 1 ? curves[0] : b.composite(curves), pref, crtn));
}

std::function<Eigen::Vector3d(const Eigen::Vector3d&)> into(const Eigen::Vector3d& centre) {
  return [centre](const Eigen::Vector3d& q) { return Eigen::Vector3d(-(q - centre).normalized()); };
}

std::string variant_name(const char* shape, double a, double b, int crtn, int pref, bool reversed) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s %.3f %.3f, CRTN %d, PREF %d, %s", shape, a, b, crtn, pref,
                reversed ? "reversed" : "as built");
  return buf;
}

}  // namespace

TEST_CASE("CAD import: an IGES quarter sphere bounded by half a great circle over the pole keeps its region") {
  // Half the great circle in the meridian plane of theta_a, from the
  // equator over the pole (north or south) to theta_a + pi, then the
  // equator back through theta_a + pi/2: the quarter theta_a..theta_a + pi
  // of that hemisphere; theta_a = -pi/2 puts the quarter across the seam.
  struct Shape {
    double theta_a;
    double side;  // +1 north, -1 south
  };
  const Shape shapes[] = {{0.3, 1}, {-pi / 2, 1}, {2.0, -1}, {-1.0, -1}};
  check_pole_cases("iges-pole-quarter", [&](IgesBuilder& b, std::vector<ExpectedFace>& cases, int crtn, int pref,
                                           bool reversed) {
    for (const Shape& s : shapes) {
      SpherePatch sphere;
      const int surface = next_sphere(b, cases, sphere);
      const Eigen::Vector3d& c = sphere.centre;
      const double R = sphere.radius;
      const Eigen::Vector3d d = SpherePatch::direction(s.theta_a, 0);
      const Eigen::Vector3d up = s.side * Eigen::Vector3d::UnitY();
      // The equator: c + R (cos theta x - sin theta z).
      const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Z = Eigen::Vector3d::UnitZ();
      std::vector<int> curves;
      if (!reversed) {
        curves.push_back(b.bspline_arc(c, d, up, R, 0, pi));
        curves.push_back(b.bspline_arc(c, X, -Z, R, s.theta_a + pi, s.theta_a));
      } else {
        curves.push_back(b.bspline_arc(c, X, -Z, R, s.theta_a, s.theta_a + pi));
        curves.push_back(b.bspline_arc(c, d, up, R, pi, 0));
      }
      add_face(b, surface, curves, crtn, pref);
      SpherePatch quarter = sphere;
      quarter.theta0 = s.theta_a;
      quarter.theta1 = s.theta_a + pi;
      quarter.phi0 = s.side > 0 ? 0 : -pi / 2;
      quarter.phi1 = s.side > 0 ? pi / 2 : 0;
      ExpectedFace e{variant_name("quarter over the pole, theta_a/side", s.theta_a, s.side, crtn, pref, reversed),
                     pi * R * R, into(c), patch_centroid(quarter), 1e-2 * R};
      cases.push_back(e);
    }
  });
}

TEST_CASE("CAD import: IGES caps whose boundary circle passes through a pole keep their area") {
  // The circle of angular radius alpha about the direction at rotation
  // angle theta_c and latitude +-(pi/2 - alpha) runs through the pole;
  // written from the point farthest from that pole, the pole lies halfway
  // along the curve. Around the pole the cap covers half a turn of angles
  // (theta_c -+ pi/2): theta_c = 0 puts it across the seam.
  struct Shape {
    double theta_c, alpha, side;
  };
  const Shape shapes[] = {{0.0, 0.6, 1}, {2.0, 0.6, 1}, {0.0, 1.2, 1}, {4.0, 0.8, -1}, {0.0, 0.5, -1}};
  check_pole_cases("iges-pole-caps", [&](IgesBuilder& b, std::vector<ExpectedFace>& cases, int crtn, int pref,
                                        bool reversed) {
    for (const Shape& s : shapes) {
      SpherePatch sphere;
      const int surface = next_sphere(b, cases, sphere);
      const Eigen::Vector3d& c = sphere.centre;
      const double R = sphere.radius;
      const Eigen::Vector3d d = SpherePatch::direction(s.theta_c, s.side * (pi / 2 - s.alpha));
      const Eigen::Vector3d pole = s.side * Eigen::Vector3d::UnitY();
      // e1 points away from the pole, so the curve starts opposite it.
      const Eigen::Vector3d e1 = -(pole - pole.dot(d) * d).normalized();
      const Eigen::Vector3d e2 = d.cross(e1);
      const int circle = b.bspline_arc(c + R * std::cos(s.alpha) * d, e1, e2, R * std::sin(s.alpha),
                                       reversed ? 2 * pi : 0, reversed ? 0 : 2 * pi);
      add_face(b, surface, {circle}, crtn, pref);
      ExpectedFace e{variant_name("cap through the pole, theta_c/alpha", s.theta_c, s.side * s.alpha, crtn, pref,
                                  reversed),
                     2 * pi * R * R * (1 - std::cos(s.alpha)), into(c),
                     Eigen::Vector3d(c + d * R * (1 + std::cos(s.alpha)) / 2), 1e-2 * R};
      cases.push_back(e);
    }
  });
}

TEST_CASE("CAD import: an IGES half sphere bounded by one great circle through both poles is the half in the file's rectangle") {
  // One closed type 126, the great circle in the meridian plane of theta_a,
  // from the equator at theta_a over the north pole, down through theta_a
  // + pi and the south pole back: it bounds the half sphere on either side.
  // In the file's rectangle (rotation angles 0..2 pi) it encloses the half
  // between its two meridians that does not cross the seam.
  const double angles[] = {0.4, 4.0, 1.7};
  check_pole_cases("iges-pole-half-sphere", [&](IgesBuilder& b, std::vector<ExpectedFace>& cases, int crtn, int pref,
                                               bool reversed) {
    for (const double theta_a : angles) {
      SpherePatch sphere;
      const int surface = next_sphere(b, cases, sphere);
      const Eigen::Vector3d& c = sphere.centre;
      const double R = sphere.radius;
      const int circle = b.bspline_arc(c, SpherePatch::direction(theta_a, 0), Eigen::Vector3d::UnitY(), R,
                                       reversed ? 2 * pi : 0, reversed ? 0 : 2 * pi);
      add_face(b, surface, {circle}, crtn, pref);
      const double other = theta_a < pi ? theta_a + pi : theta_a - pi;
      const double middle = 0.5 * (theta_a + other);
      ExpectedFace e{variant_name("half sphere between the meridians", theta_a, other, crtn, pref, reversed),
                     2 * pi * R * R, into(c), Eigen::Vector3d(c + 0.5 * R * SpherePatch::direction(middle, 0)),
                     1e-2 * R};
      cases.push_back(e);
    }
  });
}
