#pragma once
// Cutter location (the tool tip) from a cutter-contact point and the part
// normal there (docs/architecture.md "Cutter geometry"), for the generic end mill of
// cutter.hpp with a vertical axis.
//
// With P the contact point, n the unit part normal (out of the material,
// toward the tool) and e = n_xy / |n_xy| the horizontal direction from the
// contact toward the axis:
//   tube centre  C = P + r n
//   axis point   A = C + (R - r) e
//   tip          T = A - r z
// i.e. T = P + o(n) with the tip offset o(n) = r n + (R - r) e - r z. The
// contact angle theta0 = acos(n_z) selects the point of the corner arc that
// touches; the contact lies rho_c = R - r + r sin(theta0) from the axis.
//
// n_z < 0 means the point faces down and cannot be reached from above by a
// 3-axis tool: the result says `reachable = false` and nothing else is
// computed (no exception: a part may well have such points). n_z = 0 (a
// vertical wall) is reachable: the cutter touches it with its side, where
// its outward normal -n is horizontal (theta0 = 90 deg). That contact is not
// unique in height: the end of the corner arc (h = r) and the whole
// cylindrical side above it share the normal. The rule (docs/architecture.md
// "Cutter geometry"): the contact is the lowest of them, the arc's end at
// rho_c = R, h_c = r -- the torus equator of a bull-nose or ball, the rim
// (h = 0, the corner) of a flat end mill -- which is what the formulas above
// give at theta0 = 90 deg, so the tip is T = P + R n - r z. Only the sign
// decides: n_z = -1e-12 is refused, n_z = +1e-300 is a contact a hair below
// the equator.
// When |n_xy| is below `horizontal_tolerance` the direction e is undetermined
// (any horizontal direction touches the same point): `horizontal_side` is
// used, so results are deterministic.
//
// The inverse (the contact point(s) for a given tip) is in
// contact_from_tip.hpp.
#include <Eigen/Core>

#include "machining/cutter/cutter.hpp"

namespace furrow {

struct CutterLocationOptions {
  // |n_xy| at or below this counts as a horizontal tangent plane [unitless].
  // Above rounding noise of computed normals, far below any real slope
  // (1e-9 rad = 2e-7 degrees).
  double horizontal_tolerance = 1e-9;
  // 0 <= n_z at or below this counts as a vertical tangent plane (a wall
  // touched by the cutter's side, theta0 = 90 deg) [unitless]: there the
  // side above the contact is part of the cutting surface (cutter_curvature.hpp).
  double vertical_tolerance = 1e-9;
  // Direction e (contact -> axis) used at horizontal contacts; projected to
  // the horizontal plane and normalised (falls back to +x if it is vertical).
  Eigen::Vector3d horizontal_side = Eigen::Vector3d::UnitX();
};

struct CutterLocation {
  bool reachable = false;  // false when n_z < 0 (or n is zero / not finite)
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();        // unit part normal used
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();            // T [mm]
  Eigen::Vector3d tube_centre = Eigen::Vector3d::Zero();    // C = P + r n [mm]
  Eigen::Vector3d toward_axis = Eigen::Vector3d::UnitX();   // e: unit, horizontal
  double contact_angle = 0;   // theta0 = acos(n_z) [rad], in [0, pi/2]
  double contact_radius = 0;  // rho_c: horizontal distance contact -> axis [mm]
  double contact_height = 0;  // h_c: height of the contact above the tip [mm]
  bool horizontal = false;    // |n_xy| <= horizontal_tolerance: e was chosen
  bool vertical = false;      // n_z <= vertical_tolerance: a side contact (see above)
};

// `normal` need not be exactly unit (it is normalised); a zero or non-finite
// normal is reported as not reachable.
CutterLocation cutter_location(const Cutter& cutter, const Eigen::Vector3d& contact,
                               const Eigen::Vector3d& normal,
                               const CutterLocationOptions& options = {});

// The direction e for a unit normal n (contact -> axis, unit, horizontal):
// n_xy / |n_xy|, or the option's horizontal side at horizontal contacts.
// `horizontal` (optional) receives whether the latter case applied.
Eigen::Vector3d axis_side(const Eigen::Vector3d& unit_normal, const CutterLocationOptions& options,
                          bool* horizontal = nullptr);

// Tip offset o(n) = T - P for a unit normal with n_z >= 0 (precondition).
Eigen::Vector3d tip_offset(const Cutter& cutter, const Eigen::Vector3d& unit_normal,
                           const CutterLocationOptions& options = {});

}  // namespace furrow
