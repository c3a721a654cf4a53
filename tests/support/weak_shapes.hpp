#pragma once
// The weakly constrained shapes of docs/registration.md "Weakly constrained
// directions", each with the free motions it has analytically: shared by
// the registration tests and bench_registration.
#include <string>
#include <vector>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"

namespace furrow::test {

struct WeakShape {
  const char* name;
  Part part;
  int translations, rotations;  // the analytic free motions
  // Exact symmetries (held for good) rather than motions the surface barely
  // sees (released for the last fit, docs/registration.md).
  bool exact = true;
};

// A part of one untrimmed face (`reversed` flips its normals).
inline Part one_face(const char* name, NurbsSurface s, bool reversed = false) {
  Part p;
  p.faces.emplace_back(name, std::move(s), Trim{}, reversed);
  return p;
}

inline std::vector<WeakShape> weak_shapes(const std::string& mould_path) {
  std::vector<WeakShape> out;
  out.push_back({"plane", one_face("plane", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0})), 2, 1});
  // A hyperbolic paraboloid rising 2 mm at one corner of 100 x 60 mm: slopes
  // below 0.02, so the slides and the turn about z are seen by less than
  // 1e-3 of their displacement - weak, though not exactly free.
  out.push_back(
      {"ruled", one_face("ruled", make_bilinear({-50, -30, 0}, {50, -30, 0}, {-50, 30, 0}, {50, 30, 2})), 2, 1, false});
  // The outside of a cylinder segment (the builder's face is the inside of a tube).
  out.push_back({"cylinder", one_face("cylinder", make_cylinder(25, 80, 0, 2.0), true), 1, 1});
  // A full bore: the material is outside, the normals point to the axis.
  out.push_back({"bore", one_face("bore", make_cylinder(15, 40, 0, 2 * 3.141592653589793)), 1, 1});
  out.push_back({"sphere", one_face("sphere", make_sphere(30, 0, 2 * 3.141592653589793, 0.3, 1.3)), 0, 3});
  // A surface of revolution whose profile is a parabola, no circle about any
  // point: only the turn about its axis is free.
  RationalCurve2d profile;
  profile.knots = {0, 0, 0, 1, 1, 1};
  profile.points = {{20, 0}, {38, 12}, {30, 40}};
  profile.weights = {1, 1, 1};
  out.push_back({"revolution", one_face("revolution", make_revolution(profile, 0, 1.5)), 0, 1});
  out.push_back({"mould", read_part(mould_path), 0, 0});
  return out;
}

}  // namespace furrow::test
