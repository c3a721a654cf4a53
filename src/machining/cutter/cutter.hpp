#pragma once
// One generic end mill for 3-axis machining (docs/architecture.md "Cutter geometry"),
// described by its profile, like OpenCAMLib's cutters.
//
// Frame: the axis is vertical (+z), the tip T is the lowest point on the
// axis. The profile lives in the (rho, h) half-plane: rho = horizontal
// distance from the axis, h = height above the tip. An end mill with shank
// radius R and corner radius r (0 <= r <= R) has
//   - a flat bottom: h = 0 for rho <= R - r (absent for a ball, r = R);
//   - a corner arc: centre (R - r, r), radius r, a quarter circle from the
//     bottom (normal straight down) to the side (normal horizontal); for a
//     flat end mill (r = 0) it shrinks to the sharp rim (R, 0);
//   - the cylindrical side rho = R above h = r.
// Ball (r = R), flat (r = 0) and bull-nose (0 < r < R) are values of R and r,
// not separate code: every function below reads the profile. The contact
// angle theta in [0, pi/2] is the angle between the cutter's outward normal
// and the downward axis (equal to the angle between the part normal and +z
// at a contact); on the corner arc the contact lies at
//   rho_c(theta) = (R - r) + r sin(theta),  h_c(theta) = r (1 - cos(theta)).
//
// Extension point (kept open, not built): a tapered (APT) cutter adds a cone
// between the arc and the side, which ends the arc at theta_max < pi/2 and
// contributes a straight piece to height_at() and a second sharp vertex (a
// zero-radius arc) where the cone meets the shank. ProfileArc carries the
// theta range for that reason.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>

#include "io/machining/tool_file.hpp"

namespace furrow {

// A circular arc of the profile in the (rho, h) half-plane. A zero radius is
// a sharp corner (a vertex whose normals sweep the theta range).
struct ProfileArc {
  double centre_rho = 0;  // [mm]
  double centre_h = 0;    // [mm]
  double radius = 0;      // [mm], >= 0
  double theta_min = 0;   // contact angles covered [rad]
  double theta_max = 0;
};

class Cutter {
 public:
  // Shank radius R > 0, corner radius 0 <= r <= R (finite). Throws
  // InputError naming `where` otherwise.
  Cutter(std::string name, double radius, double corner_radius,
         const std::string& where = "cutter");
  // From a validated tool file entry (diameter = 2 R).
  explicit Cutter(const ToolSpec& spec);

  const std::string& name() const { return name_; }
  double radius() const { return radius_; }                // R [mm]
  double corner_radius() const { return corner_radius_; }  // r [mm]
  double diameter() const { return 2 * radius_; }
  double flat_radius() const { return flat_radius_; }  // R - r: radius of the flat bottom
  ToolType type() const;
  ToolSpec spec() const;

  // The corner arc (centre (R - r, r), radius r, theta in [0, pi/2]).
  const ProfileArc& corner() const { return corner_; }

  // Lower envelope: height above the tip of the lowest cutter point at
  // horizontal distance rho >= 0 from the axis [mm]. Exact (no tessellation):
  // 0 on the flat bottom, r - sqrt(r^2 - (rho - (R - r))^2) on the corner
  // arc, r at rho = R, +infinity beyond R (no cutter there, so the envelope
  // never lowers anything outside the shank). Inline because the z-map and
  // the swept-envelope predictor call it per cell.
  double height_at(double rho) const {
    const double d = rho - flat_radius_;
    if (d <= 0) return 0.0;
    const double r = corner_radius_;
    if (d >= r) return d > r ? std::numeric_limits<double>::infinity() : r;
    return r - std::sqrt((r - d) * (r + d));
  }

  // Slope dh/drho of the lower envelope at rho (tan of the contact angle
  // there): 0 on the flat bottom, +infinity at and beyond the shank radius.
  double slope_at(double rho) const {
    const double d = rho - flat_radius_;
    if (d <= 0) return 0.0;
    const double r = corner_radius_;
    if (d >= r) return std::numeric_limits<double>::infinity();
    return d / std::sqrt((r - d) * (r + d));
  }

  // Contact position on the profile for contact angle theta in [0, pi/2]:
  // (rho_c, h_c) on the corner arc, the formulas above.
  Eigen::Vector2d profile_point(double theta) const {
    return {corner_.centre_rho + corner_.radius * std::sin(theta),
            corner_.centre_h - corner_.radius * std::cos(theta)};
  }

 private:
  std::string name_;
  double radius_ = 0, corner_radius_ = 0, flat_radius_ = 0;
  ProfileArc corner_;
};

}  // namespace furrow
