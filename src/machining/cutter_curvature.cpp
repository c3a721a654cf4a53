#include "machining/cutter_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

CutterCurvature cutter_curvature(const Cutter& cutter, const Eigen::Vector3d& normal,
                                 const CutterLocationOptions& options) {
  CutterCurvature c;
  const double len = normal.norm();
  if (!std::isfinite(len) || !(len > 0)) return c;
  const Eigen::Vector3d n = normal / len;
  c.normal = n;
  if (!(n.z() > 0)) return c;
  c.reachable = true;

  bool horizontal = false;
  const Eigen::Vector3d e = axis_side(n, options, &horizontal);
  c.toward_axis = e;
  // sin(theta0) = |n_xy|, cos(theta0) = n_z; at a horizontal contact exactly 0.
  const double sin_t = horizontal ? 0.0 : std::min(1.0, std::hypot(n.x(), n.y()));
  c.contact_angle = horizontal ? 0.0 : std::acos(std::min(1.0, n.z()));
  // Meridian tangent pointing up the profile (away from the axis at the
  // bottom, up the wall on the side). Built from the exact normal so that it
  // stays perpendicular to it even when e was chosen at a horizontal contact.
  // z - n_z n = sin(theta0) (-cos(theta0) e + sin(theta0) z).
  c.dir_max = horizontal ? (-e + e.dot(n) * n).normalized()
                         : (Eigen::Vector3d::UnitZ() - n.z() * n).normalized();
  c.dir_min = n.cross(c.dir_max);

  const ProfileArc& arc = cutter.corner();
  const double rho_c = arc.centre_rho + arc.radius * sin_t;
  c.sharp = !(arc.radius > 0);
  c.k_max = c.sharp ? std::numeric_limits<double>::infinity() : 1.0 / arc.radius;
  // At the tip of a ball (rho_c = 0) the circle degenerates; the limit of
  // sin(theta) / (r sin(theta)) is 1 / r: the ball is umbilic there.
  c.k_min = rho_c > 0 ? sin_t / rho_c : 1.0 / arc.radius;
  c.flat_bottom = horizontal && arc.centre_rho > 0;
  return c;
}

}  // namespace furrow
