#include "machining/cutter/cutter_curvature.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

CutterCurvature cutter_curvature(const Cutter& cutter, const Eigen::Vector3d& normal,
                                 const CutterLocationOptions& options) {
  CutterCurvature c;
  // Normals from DifferentialGeometry are unit to rounding: skip the sqrt.
  const double len2 = normal.squaredNorm();
  if (!std::isfinite(len2) || !(len2 > 0)) return c;
  const Eigen::Vector3d n = std::abs(len2 - 1) < 1e-14 ? normal : Eigen::Vector3d(normal / std::sqrt(len2));
  c.normal = n;
  if (!(n.z() >= 0)) return c;  // facing down; n_z = 0 is a side contact
  c.reachable = true;

  // n = sin(theta0) e + cos(theta0) z; at a horizontal contact sin is 0 and e
  // is the option's (cutter_location.hpp).
  const double nxy = std::sqrt(n.x() * n.x() + n.y() * n.y());
  const bool horizontal = !(nxy > options.horizontal_tolerance);
  const Eigen::Vector3d e = horizontal ? axis_side(n, options) : Eigen::Vector3d(n.x() / nxy, n.y() / nxy, 0.0);
  c.toward_axis = e;
  const double sin_t = horizontal ? 0.0 : std::min(1.0, nxy);
  c.sin_contact = sin_t;
  c.cos_contact = horizontal ? 1.0 : n.z();
  // The meridian tangent pointing up the profile (away from the axis at the
  // bottom, up the wall on the side): -cos(theta0) e + sin(theta0) z, which
  // is exactly perpendicular to n. At a horizontal contact e was chosen and
  // n may carry a rounding-level tilt: project to stay perpendicular.
  if (horizontal) {
    c.dir_max = (-e + e.dot(n) * n).normalized();
    c.dir_min = n.cross(c.dir_max);
  } else {
    c.dir_max = Eigen::Vector3d(-n.z() * e.x(), -n.z() * e.y(), nxy);
    c.dir_min = Eigen::Vector3d(e.y(), -e.x(), 0.0);  // n x dir_max = e x z
  }

  const ProfileArc& arc = cutter.corner();
  const double rho_c = arc.centre_rho + arc.radius * sin_t;
  c.sharp = !(arc.radius > 0);
  c.k_max = c.sharp ? std::numeric_limits<double>::infinity() : 1.0 / arc.radius;
  // At the tip of a ball (rho_c = 0) the circle degenerates; the limit of
  // sin(theta) / (r sin(theta)) is 1 / r: the ball is umbilic there.
  c.k_min = rho_c > 0 ? sin_t / rho_c : 1.0 / arc.radius;
  c.flat_bottom = horizontal && arc.centre_rho > 0;
  // At a vertical wall dir_max is +z (to rounding) and the cylinder of
  // radius R rises from the contact (the header): its meridian is straight,
  // its parallel the circle of radius R seen face on.
  c.side = n.z() <= options.vertical_tolerance;
  c.side_k_min = 1.0 / cutter.radius();
  return c;
}

}  // namespace furrow
