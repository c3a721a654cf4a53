#pragma once
// Whether a probe ball standing on a surface point measures that point and
// only it: the contact rule of narrow regions (docs/cmm.md "Narrow regions").
//
// The ball of radius r stands on point p of face f with its centre at
// c = p + r·n. The contact is not assumed to be p: it is the part's closest
// point from c (ClosestPointFinder, global over all faces), checked:
//   - it is p (within `tolerance`) on face f, and nothing of the part is
//     nearer than r − tolerance (the ball does not cut into the part);
//   - no other face comes within r + tolerance of c (the ball touches
//     nothing else: not a wall beside a floor, not the far side of a groove);
//   - with the centre off by `shift` sideways (along either tangent, either
//     way: the ball placed a little wrong, the part a little off its nominal)
//     the closest point from the moved centre still lies on face f and in the
//     region. So the margin a contact keeps from the region's edges follows
//     the surface and the ball: a contact on a convex fillet of radius rho
//     moves by shift·rho/(rho + r), on a concave one by shift·rho/(rho − r),
//     on a plane by shift.
// A region whose points all fail is one no ball position can measure;
// largest_fitting_ball() says which ball would.
//
// Units: mm. Thread safety: pure functions of a const finder.
#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "geometry/closest_point.hpp"

namespace furrow {

struct BallContactOptions {
  double shift = 0.25;      // sideways error of the ball's centre the contact must survive [mm], >= 0
  double tolerance = 1e-3;  // the contact found must be the planned point within this [mm], > 0
};

enum class ContactProblem {
  none,
  elsewhere,     // the closest point from the centre is not the planned point (the ball touches elsewhere first)
  second_touch,  // another face is within the ball's radius (+ tolerance) of the centre
  leaves_region  // with the centre off by `shift`, the contact leaves the face or the region
};
const char* to_string(ContactProblem problem);

// Whether (face, uv) is in the region whose point is checked.
using InRegion = std::function<bool(std::size_t face, const Eigen::Vector2d& uv)>;

// `p` on face `face` with unit outward normal `n`; `radius` > 0.
ContactProblem check_ball_contact(const ClosestPointFinder& finder, std::size_t face, const Eigen::Vector3d& p,
                                  const Eigen::Vector3d& n, double radius, const InRegion& in_region,
                                  const BallContactOptions& options);

struct ContactCandidate {
  std::size_t face = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// The largest ball radius in [resolution, radius] for which some candidate
// passes check_ball_contact, by bisection to `resolution` (the answer is
// within `resolution` below the true largest radius, assuming a ball that
// fits has every smaller ball fit at the same point: true where the part
// near the contact is a plane, a cylinder, a sphere or a groove); 0 when no
// candidate passes even at `resolution`.
double largest_fitting_ball(const ClosestPointFinder& finder, const std::vector<ContactCandidate>& candidates,
                            double radius, const InRegion& in_region, const BallContactOptions& options,
                            double resolution = 0.005);

}  // namespace furrow
