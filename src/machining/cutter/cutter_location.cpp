#include "machining/cutter/cutter_location.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

Eigen::Vector3d axis_side(const Eigen::Vector3d& n, const CutterLocationOptions& options,
                          bool* horizontal) {
  const double nxy = std::sqrt(n.x() * n.x() + n.y() * n.y());
  const bool flat = !(nxy > options.horizontal_tolerance);
  if (horizontal) *horizontal = flat;
  if (!flat) return {n.x() / nxy, n.y() / nxy, 0.0};
  const Eigen::Vector3d& hint = options.horizontal_side;
  const double hxy = std::sqrt(hint.x() * hint.x() + hint.y() * hint.y());
  if (!(hxy > 0) || !std::isfinite(hxy)) return Eigen::Vector3d::UnitX();
  return {hint.x() / hxy, hint.y() / hxy, 0.0};
}

Eigen::Vector3d tip_offset(const Cutter& cutter, const Eigen::Vector3d& n,
                           const CutterLocationOptions& options) {
  const ProfileArc& arc = cutter.corner();
  // Centre of the arc's circle in the contact's meridian plane, then down to
  // the tip: o = r n + rho0 e - h0 z (rho0 = R - r, h0 = r for the corner).
  Eigen::Vector3d o = arc.radius * n + arc.centre_rho * axis_side(n, options);
  o.z() -= arc.centre_h;
  return o;
}

CutterLocation cutter_location(const Cutter& cutter, const Eigen::Vector3d& contact,
                               const Eigen::Vector3d& normal,
                               const CutterLocationOptions& options) {
  CutterLocation loc;
  loc.contact = contact;
  const double len = normal.norm();
  if (!std::isfinite(len) || !(len > 0) || !contact.allFinite()) return loc;
  const Eigen::Vector3d n = normal / len;
  loc.normal = n;
  // Facing down: not reachable from above, nothing computed. n_z = 0 is a
  // side contact (see the header): the same formulas, theta0 = 90 deg.
  if (!(n.z() >= 0)) return loc;
  loc.reachable = true;
  loc.toward_axis = axis_side(n, options, &loc.horizontal);
  loc.vertical = n.z() <= options.vertical_tolerance;
  loc.contact_angle = std::acos(std::min(1.0, n.z()));
  const Eigen::Vector2d profile = cutter.profile_point(loc.contact_angle);
  loc.contact_radius = profile.x();
  loc.contact_height = profile.y();
  loc.tube_centre = contact + cutter.corner_radius() * n;
  loc.tip = contact + tip_offset(cutter, n, options);
  return loc;
}

}  // namespace furrow
