// CAD import of IGES trimmed surfaces (type 144) whose outer boundary AND
// holes are given as model-space curves only (type 142 with PPTR 0, as
// CATIA writes every boundary), in every CRTN (0-3) and PREF (0-3) and with
// either loop running either way (docs/formats.md "CAD import", "IGES
// boundaries"): sphere and cylinder patches as type 120 surfaces of
// revolution with circular holes inside them, across the seam and on it,
// and a plane as a type 128 B-spline with circular holes. Oracles: the
// analytic area (patch less holes: a spherical cap 2 pi R^2 (1 - cos alpha),
// a circle drawn on a cylinder unrolled pi rho^2, a disc pi rho^2) and the
// file's own surface normal (a face that sews to nothing keeps it).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "iges_case_import.hpp"
#include "iges_occt_curves.hpp"
#include "iges_revolved_patches.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kSpacing = 80;  // case k lies around x = k * kSpacing

// The 32 ways the tests write one boundary set: CRTN 0-3, PREF 0-3, the
// outer loop as built or reversed; with each outer direction the holes run
// one way in half of them and the other way in the other half.
struct Variant {
  int crtn, pref;
  bool outer_reversed, hole_reversed;
};
std::vector<Variant> variants() {
  std::vector<Variant> all;
  for (int crtn = 0; crtn <= 3; ++crtn)
    for (int pref = 0; pref <= 3; ++pref)
      for (const bool reversed : {false, true}) all.push_back({crtn, pref, reversed, reversed != ((crtn + pref) % 2 == 1)});
  return all;
}

const double pi = M_PI;

}  // namespace

TEST_CASE("CAD import: IGES sphere patches with holes, all bounded by model-space curves only, in every CRTN and PREF") {
  struct Shape {
    double theta0, theta1, phi0, phi1;
    std::vector<SphereHole> holes;
  };
  const std::vector<Shape> shapes = {
      {0.5, 2.5, -0.6, 0.9, {{1.5, 0.1, 0.4}}},                  // a hole inside a patch
      {-1.0, 1.0, -0.6, 0.9, {{0.0, 0.1, 0.4}}},                 // ... across the seam, the patch too
      {-1.0, 1.0, 0.2, pi / 2, {{0.0, 0.9, 0.25}, {0.7, 0.6, 0.2}}},  // ... up to the pole
      {0, 2 * pi, -0.7, 0.7, {{0.0, 0.0, 0.4}, {pi, 0.2, 0.3}}},  // a band, one hole on its seam
      {0, 2 * pi, 0.2, pi / 2, {{1.0, 0.9, 0.25}, {0.0, 0.9, 0.25}}},  // a cap around the pole
  };
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (const Shape& shape : shapes)
    for (const Variant& v : variants()) {
      SpherePatch p;
      p.centre = Eigen::Vector3d(kSpacing * static_cast<double>(cases.size()), 0, 0);
      p.theta0 = shape.theta0, p.theta1 = shape.theta1, p.phi0 = shape.phi0, p.phi1 = shape.phi1;
      p.model_space_only = true;
      p.crtn = v.crtn, p.pref = v.pref;
      p.reversed_loop = v.outer_reversed;
      p.generatrix_transformed = v.pref % 2 == 1;
      p.split_at_equator = v.crtn % 2 == 1;
      p.holes = shape.holes;
      for (SphereHole& h : p.holes) h.reversed = v.hole_reversed;
      write_sphere_patch(builder, p);
      // The writer's type 120 turns the generatrix south to north about +y:
      // its normal points into the sphere.
      const Eigen::Vector3d centre = p.centre;
      cases.push_back({p.name() + (v.hole_reversed ? ", holes reversed" : ""), p.area(),
                       [centre](const Eigen::Vector3d& q) { return Eigen::Vector3d(-(q - centre).normalized()); }});
    }
  check_case_file(builder, cases, "iges-sphere-model-space-holes", kSpacing);
}

namespace {

// A lune theta0..theta1 from pole to pole with `holes`, written as case
// `cases.size()` of `builder` with `v`'s fields (the generatrix with a type
// 124 in odd PREFs, the meridians as type 100 arcs in CRTN 2 and 3 and split
// at the equator in odd CRTNs), and what its face must be. Two meridians
// from pole to pole bound the lune and the rest of the sphere alike; the
// lune lies in the file's rectangle (rotation angles 0..2 pi) and the rest
// crosses its seam, so the face is the lune (docs/formats.md "IGES
// boundaries"), less its holes. Oracle: the lune's area 2 R^2 (theta1 -
// theta0) less each hole's cap 2 pi R^2 (1 - cos alpha), the file's normal
// (into the sphere), and the centroid of the lune with the holes' caps taken
// out, by first moments (a cap of angular radius alpha about d has its
// centroid R (1 + cos alpha) / 2 along d), which tells the lune from the rest
// of the sphere with the same holes.
void add_lune(IgesBuilder& builder, std::vector<ExpectedFace>& cases, double theta0, double theta1,
              const std::vector<SphereHole>& holes, const Variant& v) {
  SpherePatch p;
  p.centre = Eigen::Vector3d(kSpacing * static_cast<double>(cases.size()), 0, 0);
  p.theta0 = theta0, p.theta1 = theta1, p.phi0 = -pi / 2, p.phi1 = pi / 2;
  p.model_space_only = true;
  p.crtn = v.crtn, p.pref = v.pref;
  p.reversed_loop = v.outer_reversed;
  p.generatrix_transformed = v.pref % 2 == 1;
  p.arc_meridians = v.crtn / 2 == 1;
  p.split_at_equator = v.crtn % 2 == 1;
  for (SphereHole h : holes) {
    h.reversed = v.hole_reversed;
    p.holes.push_back(h);
  }
  write_sphere_patch(builder, p);
  const double R = p.radius;
  SpherePatch lune = p;
  lune.holes.clear();
  Eigen::Vector3d moment = lune.area() * (patch_centroid(lune) - p.centre);
  for (const SphereHole& h : p.holes) {
    const double cap = 2 * pi * R * R * (1 - std::cos(h.alpha));
    moment -= cap * R * (1 + std::cos(h.alpha)) / 2 * SpherePatch::direction(h.theta, h.phi);
  }
  const Eigen::Vector3d centre = p.centre;
  cases.push_back({p.name() + (v.hole_reversed ? ", holes reversed" : ""), p.area(),
                   [centre](const Eigen::Vector3d& q) { return Eigen::Vector3d(-(q - centre).normalized()); },
                   Eigen::Vector3d(centre + moment / p.area()), 1e-2 * R});
}

}  // namespace

TEST_CASE("CAD import: IGES sphere lunes from pole to pole with holes, bounded by model-space curves only, in every CRTN and PREF") {
  struct Shape {
    double theta0, theta1;
    std::vector<SphereHole> holes;
  };
  const std::vector<Shape> shapes = {
      {0.5, 2.5, {{1.5, 0.1, 0.4}}},                       // a hole in a lune
      {1.0, 2.2, {{1.6, -0.7, 0.3}, {1.6, 0.6, 0.35}}},    // two, south and north
      {0.2, 0.2 + 1.6 * pi, {{pi, 0.0, 0.5}}},             // a lune wider than a half
      {0.3, 1.8, {{1.05, 1.0, 0.3}}},                      // a hole near the pole
  };
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (const Shape& shape : shapes)
    for (const Variant& v : variants()) add_lune(builder, cases, shape.theta0, shape.theta1, shape.holes, v);
  check_case_file(builder, cases, "iges-sphere-model-space-lune-holes", kSpacing);
}

TEST_CASE("CAD import: a sphere lune with a hole that OpenCASCADE splits in two comes in from IGES as one face") {
  // The loop as the writer builds it runs clockwise in the file's (u,v):
  // OpenCASCADE routes its pole edges around the rest of the sphere and
  // splits off the hole's disc as a face of its own (two faces, 193.3 and
  // 11.2 mm^2, for this lune of 79.1 mm^2). Either direction, one face.
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  const std::vector<SphereHole> hole{{1.5, 0.1, 0.4}};
  for (const bool reversed : {false, true}) add_lune(builder, cases, 0.5, 2.5, hole, {0, 2, reversed, false});
  check_case_file(builder, cases, "iges-sphere-split-lune", kSpacing);
}

TEST_CASE("CAD import: IGES cylinder patches with holes, all bounded by model-space curves only, in every CRTN and PREF") {
  struct Shape {
    double theta0, theta1;
    std::vector<double> hole_angles;  // circles of radius 2 mm at mid-height
  };
  const std::vector<Shape> shapes = {
      {0, pi, {pi / 2}},                 // a hole inside a half cylinder
      {-pi / 2, pi / 2, {0.0}},          // ... across the seam, the patch too
      {0, 2 * pi, {0.0, pi}},            // a ring, one hole on its seam
      {0.2, 0.2 + 1.6 * pi, {2.0}},
  };
  constexpr double rho = 2;
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (const Shape& shape : shapes)
    for (const Variant& v : variants()) {
      RevolvedPatch p;
      p.centre = Eigen::Vector3d(kSpacing * static_cast<double>(cases.size()), 0, 0);
      p.theta0 = shape.theta0, p.theta1 = shape.theta1;
      p.model_space_only = true;
      p.crtn = v.crtn, p.pref = v.pref;
      p.reversed_loop = v.outer_reversed;
      const Eigen::Vector3d centre = p.centre;
      const double radius = p.radius;
      auto point = [centre, radius](double angle, double height) {
        return Eigen::Vector3d(centre + Eigen::Vector3d(radius * std::cos(angle), height, -radius * std::sin(angle)));
      };
      std::vector<int> holes;
      for (const double angle : shape.hole_angles)
        holes.push_back(write_unrolled_circle(builder, point, radius, angle, 0.5 * p.height, rho, v.hole_reversed));
      write_revolved_patch(builder, p, holes);
      const double area = p.area() - static_cast<double>(holes.size()) * pi * rho * rho;
      cases.push_back({p.name() + (v.hole_reversed ? ", holes reversed" : ""), area, [centre](const Eigen::Vector3d& q) {
                         const Eigen::Vector3d r = q - centre;
                         return Eigen::Vector3d(-Eigen::Vector3d(r.x(), 0, r.z()).normalized());  // toward the axis
                       }});
    }
  check_case_file(builder, cases, "iges-cylinder-model-space-holes", kSpacing);
}

TEST_CASE("CAD import: an IGES plane as a type 128 B-spline with holes, bounded by model-space curves only") {
  // A 20 x 12 mm rectangle of a plane tilted about x, two circular holes
  // (radius 3 and 1.5) as rational type 126 circles, the outer loop as four
  // type 110 lines; the plane is not periodic, so the import takes
  // OpenCASCADE's own projection of the curves.
  constexpr double w = 20, h = 12, tilt = 0.4;
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (const Variant& v : variants()) {
    const Eigen::Vector3d o(kSpacing * static_cast<double>(cases.size()) - w / 2, -h / 2, 3);
    const Eigen::Vector3d e1(1, 0, 0), e2(0, std::cos(tilt), std::sin(tilt));
    const int surface = builder.bspline_surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1},
                                                {{o, o + h * e2}, {o + w * e1, o + w * e1 + h * e2}},
                                                {{1, 1}, {1, 1}}, false, false);
    std::vector<Eigen::Vector3d> corners{o, o + w * e1, o + w * e1 + h * e2, o + h * e2};
    if (v.outer_reversed) std::swap(corners[1], corners[3]);
    std::vector<int> lines;
    for (std::size_t k = 0; k < 4; ++k) lines.push_back(builder.line(corners[k], corners[(k + 1) % 4]));
    const int outer = builder.curve_on_surface(surface, 0, builder.composite(lines), v.pref, v.crtn);
    std::vector<int> inner;
    for (const auto& [cx, radius] : {std::pair<double, double>{6, 3}, std::pair<double, double>{14.5, 1.5}}) {
      const double a0 = v.hole_reversed ? 2 * pi : 0, a1 = v.hole_reversed ? 0 : 2 * pi;
      const int circle = builder.bspline_arc(o + cx * e1 + 0.5 * h * e2, e1, e2, radius, a0, a1);
      inner.push_back(builder.curve_on_surface(surface, 0, circle, v.pref, v.crtn));
    }
    builder.trimmed_surface(surface, outer, inner);
    const Eigen::Vector3d normal = e1.cross(e2);  // Su x Sv
    char name[120];
    std::snprintf(name, sizeof name, "plane, CRTN %d, PREF %d, outer %s, holes %s", v.crtn, v.pref,
                  v.outer_reversed ? "clockwise" : "counterclockwise", v.hole_reversed ? "clockwise" : "counterclockwise");
    cases.push_back({name, w * h - pi * (9 + 2.25), [normal](const Eigen::Vector3d&) { return normal; }});
  }
  check_case_file(builder, cases, "iges-plane-model-space-holes", kSpacing);
}

TEST_CASE("CAD import: IGES sphere lunes across or on the seam with holes, bounded by model-space curves only, keep the lune") {
  // Two meridians from pole to pole bound the lune and the rest of the
  // sphere alike, and when the lune crosses the seam of the file's
  // rectangle (rotation angles 0..2 pi) only the rest lies in it; a lune
  // with no hole then reads as that rest (test_cad_iges_revolution.cpp).
  // A face holds its holes: a hole inside the lune says the face is the
  // lune, whichever way its loop runs and however the file writes it
  // (docs/formats.md "IGES boundaries"). Oracle as in add_lune(): the
  // lune's area less the holes' caps, the file's normal, the centroid by
  // first moments (the rest of the sphere with the same holes has the same
  // area only by accident, and its centroid on the other side).
  struct Shape {
    double theta0, theta1;
    std::vector<SphereHole> holes;
  };
  const std::vector<Shape> shapes = {
      {-pi / 3, pi / 3, {{0.5, 0.1, 0.4}}},                  // 300 to 60 degrees written below 0, a hole beside the seam
      {5 * pi / 3, 7 * pi / 3, {{2 * pi, -0.2, 0.35}}},      // ... written beyond 2 pi, a hole across the seam
      {0, 0.5 * pi, {{0.8, 0.3, 0.3}}},                      // a meridian on the seam
      {1.5 * pi, 2 * pi, {{1.7 * pi, -0.3, 0.3}}},           // ... at 2 pi
  };
  // Every CRTN and PREF on every shape, the outer loop as built on shapes
  // 0 and 2 and reversed on 1 and 3 (all 32 variants on every shape took
  // twice the time for the same reader paths).
  IgesBuilder builder;
  std::vector<ExpectedFace> cases;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (const Variant& v : variants())
      if (v.outer_reversed == (i % 2 == 1)) add_lune(builder, cases, shapes[i].theta0, shapes[i].theta1, shapes[i].holes, v);
  check_case_file(builder, cases, "iges-sphere-model-space-seam-lune-holes", kSpacing);
}
