#pragma once
// Principal curvatures and directions of the cutter's cutting surface at a
// contact point, expressed in part coordinates (docs/architecture.md "Cutter geometry").
//
// Sign: the part's convention (normal n out of the material, toward the
// tool). The cutting surface bends away from the part, so both curvatures are
// >= 0; a part normal curvature above the cutter's in some direction means
// the cutter cuts into the part there (local gouge, local_gouge.hpp).
//
// The cutting surface near the contact is the corner arc swept about the
// axis (a surface of revolution), so its principal directions are
//   dir_max: the meridian, uphill: -cos(theta0) e + sin(theta0) z,
//            curvature k_max = 1 / r (the arc's);
//   dir_min: the horizontal circle, n x dir_max,
//            curvature k_min = sin(theta0) / rho_c (Meusnier: the parallel
//            circle of radius rho_c seen at angle theta0),
//            rho_c = R - r + r sin(theta0).
// (dir_max, dir_min, n) is right-handed; local_gouge.hpp measures tangent
// directions as angles from dir_max, counter-clockwise about n.
// Special cases from the same profile: a ball gives k_max = k_min = 1/R;
// a flat end mill (r = 0) touches with its sharp rim: k_max is infinite
// (`sharp`), and only the bottom circle (k_min = sin(theta0) / R) can be
// compared; at the horizontal contact (theta0 = 0) of a cutter with a flat
// bottom (R > r) the directions toward the axis lie on the flat bottom,
// whose curvature is 0 (`flat_bottom`).
// Side contact (theta0 = 90 deg, n_z = 0: a vertical wall, cutter_location.hpp):
// the contact is the lowest point with a horizontal normal, the end of the
// corner arc (the torus equator; the rim of a flat end mill), and the
// cylindrical side of radius R continues straight up from it. So the
// cutting surface has two halves there (`side`):
//   up   (t . z > 0, angles in (-90, 90) degrees from dir_max = +z): the
//        cylinder, curvature 0 along the vertical meridian and 1/R around;
//   down (angles in (90, 270)): the corner arc, 1/r along the meridian and
//        sin(90 deg) / rho_c = 1/R around (both halves share the horizontal
//        directions); for a flat end mill the sharp rim, compared only
//        along the horizontal circle.
// A ball (r = R) at its equator has the same two halves: the sphere below,
// the shank above.
#include <Eigen/Core>
#include <cmath>

#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_location.hpp"

namespace furrow {

struct CutterCurvature {
  bool reachable = false;  // false when n_z < 0: nothing else is set
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();       // unit part normal at the contact
  Eigen::Vector3d toward_axis = Eigen::Vector3d::UnitX();  // e: contact -> axis, horizontal
  Eigen::Vector3d dir_max = -Eigen::Vector3d::UnitX();     // meridian direction (unit)
  Eigen::Vector3d dir_min = -Eigen::Vector3d::UnitY();     // circumferential direction (unit)
  double k_max = 0;  // [1/mm] meridian curvature 1/r; +infinity when `sharp`
  double k_min = 0;  // [1/mm] circumferential curvature sin(theta0) / rho_c
  double sin_contact = 0, cos_contact = 1;  // sin, cos of the contact angle theta0
  double contact_angle() const { return std::atan2(sin_contact, cos_contact); }  // [rad]
  // The contact is on the sharp rim of a flat end mill (r = 0): compare only
  // along dir_min (the cutting circle), see local_gouge.hpp.
  bool sharp = false;
  // Horizontal contact of a cutter with a flat bottom: the directions t with
  // t . toward_axis > 0 (angles in (90, 270) degrees from dir_max) touch the
  // flat bottom (curvature 0); k_max, k_min, sharp describe the other half.
  bool flat_bottom = false;
  // Side contact (0 <= n_z <= vertical_tolerance): the directions t with
  // t . z > 0 (angles in (-90, 90) degrees from dir_max) touch the
  // cylindrical side (curvature 0 along dir_max, 1/R along dir_min, in
  // `side_k_min`); k_max, k_min, sharp describe the lower half.
  bool side = false;
  double side_k_min = 0;  // [1/mm] 1/R: the side's curvature around the axis
};

CutterCurvature cutter_curvature(const Cutter& cutter, const Eigen::Vector3d& normal,
                                 const CutterLocationOptions& options = {});

}  // namespace furrow
