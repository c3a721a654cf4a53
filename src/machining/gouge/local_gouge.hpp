#pragma once
// Local gouge check at a cutter-contact point (docs/architecture.md "Cutter geometry").
//
// The cutter gouges locally when, in some tangent direction t, the part's
// normal curvature exceeds the cutter's: the part bends toward the tool
// faster than the cutting surface bends away. Principal curvatures alone do
// not decide it because the two principal frames are not aligned, so every
// direction is compared. With angles a measured from the cutter's
// max-curvature direction (CutterCurvature::dir_max) counter-clockwise about
// the contact normal, Euler's formula for both surfaces gives in closed form
//   f(a) = k_part(a) - k_tool(a) = A + B cos 2a + C sin 2a
//        = A + D cos(2a - psi),
//   A = (k1 + k2)/2 - (k_max + k_min)/2,
//   B = (k1 - k2)/2 cos 2phi - (k_max - k_min)/2,   C = (k1 - k2)/2 sin 2phi,
// with phi the angle of the part's d1 and D = hypot(B, C), psi = atan2(C, B).
// So the largest excess is A + D and the gouge ranges {f(a) > tol} are
// exact: the arcs psi/2 +- acos((tol - A)/D)/2 and their opposites (no sweep,
// no root finding; rounding only).
//
// Gouge means max f > `curvature_tolerance`: exact ties (a ball of radius R
// in a concave cylinder of radius R) touch and do not gouge.
//
// Quick accept: when the part's largest curvature k1 does not exceed the
// cutter's smallest, k1 <= k_min + tol (every convex point qualifies), no
// direction can gouge and the frames are not looked at; `max_excess` is then
// the bound k1 - k_min, not the exact maximum.
//
// Flat end mill (r = 0), the cutting-circle comparison: the contact lies on
// the sharp rim, the edge between the bottom and the side, whose meridian
// curvature is infinite; near the contact both the bottom plane and the side
// leave the part's tangent plane at first order (for 0 < theta0 < 90 deg), so
// only the rim itself, the bottom circle of radius R in the horizontal plane,
// can cut in. The part's section by that plane has curvature
// kappa = k_part(dir_min) / sin(theta0) (Meusnier); it gouges when
// kappa > 1/R, compared as normal curvatures:
//   k_part(dir_min) > sin(theta0) / R + tol.
// The gouge "ranges" are then the two single directions +-dir_min (90 and
// 270 degrees), reported as zero-width arcs.
//
// Horizontal contact of a cutter with a flat bottom (bull, flat; theta0 = 0):
// the directions toward the axis (90..270 degrees) lie on the flat bottom,
// curvature 0, and are compared with it; the others with the corner.
//
// Side contact (theta0 = 90 deg, a vertical wall, cutter_curvature.hpp): the
// upward directions (-90..90 degrees) are compared with the cylindrical
// side (0 along the vertical, 1/R around), the downward ones with the corner
// arc at its equator (1/r along the vertical, 1/R around; for a flat end
// mill only the horizontal circle, as above).
//
// Windows: a surface can be compared over only part of the circle (at a
// border between faces each face over the directions that point into it,
// compound_border.hpp); ranges and the largest excess are then taken over the
// window only.
#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "geometry/differential_geometry.hpp"
#include "machining/gouge/angular_ranges.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_curvature.hpp"

namespace furrow {

struct GougeOptions {
  // A part curvature must exceed the cutter's by more than this to count as
  // a gouge [1/mm]: touching is not gouging, and curvatures computed from a
  // NURBS carry rounding noise (1e-6 /mm is a radius change of 0.1 um at
  // R = 300 mm).
  double curvature_tolerance = 1e-6;
  // Decide from principal curvatures alone when they suffice.
  bool quick_accept = true;
  CutterLocationOptions location;
};

enum class GougeStatus : unsigned char {
  clear = 0,           // no direction gouges
  gouge = 1,           // some direction gouges (see ranges)
  unreachable = 2,     // contact normal n_z < 0: not reachable from above
  degenerate = 3,      // the part's normal is undefined there
  concave_crease = 4,  // a concave edge between faces (compound_border.hpp)
};
const char* to_string(GougeStatus status);

struct LocalGouge {
  GougeStatus status = GougeStatus::unreachable;
  CutterCurvature cutter;  // at the contact (its frame defines the angles)
  // Directions where k_part - k_tool > tolerance: angles [rad] from
  // cutter.dir_max counter-clockwise about the normal; empty unless gouge.
  AngularRanges ranges;
  // Largest k_part - k_tool over the compared directions [1/mm] (negative:
  // the margin of a clear point). An upper bound when `quick`.
  double max_excess = 0;
  double max_excess_angle = 0;  // [rad] where it occurs (0 when quick)
  bool quick = false;           // decided by the quick-accept path

  bool gouges() const { return status == GougeStatus::gouge; }
  // Unit tangent direction (part coordinates) of an angle.
  Eigen::Vector3d direction(double angle) const {
    return std::cos(angle) * cutter.dir_max + std::sin(angle) * cutter.dir_min;
  }
};

// One surface at the contact, compared over the tangent directions t with
// t . inward[i] >= 0 for every i < inward_count (all directions when 0).
struct SurfaceSide {
  const DifferentialGeometry* geometry = nullptr;
  std::array<Eigen::Vector3d, 2> inward{};
  int inward_count = 0;
};

// An interior contact point: the whole circle of directions, contact normal
// = the part normal.
LocalGouge check_local_gouge(const Cutter& cutter, const DifferentialGeometry& part,
                             const GougeOptions& options = {});

// Several surfaces meeting at the contact (1 or 2 sides), each over its
// window; `contact_normal` is the normal the cutter is located with. Each
// side's curvature is taken in its own principal frame, projected to the
// contact's tangent plane.
LocalGouge check_local_gouge(const Cutter& cutter, const Eigen::Vector3d& contact_normal,
                             const SurfaceSide* sides, std::size_t side_count,
                             const GougeOptions& options = {});

}  // namespace furrow
