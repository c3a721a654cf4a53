#pragma once
// Can a CMM with a vertical stylus take this point? (docs/cmm.md)
//
// The probe is a ball of radius r on a vertical cylindrical shaft (radius
// r_s <= r, from the ball up to `stylus_length` above the ball centre, where
// the probe body starts). A point p with outward unit normal n is measured
// with the ball centre at c = p + r n, moving along -n from the approach
// point c + approach n and backing off to c + retract n. The point is
// accessible when
//   1. tilt: the angle between n and +z is at most max_tilt (a vertical
//      stylus reaches points facing up or sideways, not undercuts);
//   2. ball: the ball touches the part only at p: the distance from c to
//      the whole part (global closest point) is r, nothing nearer (a groove
//      narrower than the ball, a neighbouring wall);
//   3. approach path: the ball, moved from c along n to the farther of the
//      approach and retract points, stays clear (distance >= r);
//   4. stylus: the shaft, from where it leaves the ball up to the probe
//      body, stays clear of the part (distance >= r_s);
//   5. vertical access: the ball can come straight down from the clearance
//      plane to the approach point and go straight up from the retract point
//      (how the moves reach and leave every point, moves.hpp).
//
// Segments are checked by sphere tracing with the exact distance to the
// part (ClosestPointFinder): from a sample at distance d, nothing closer
// than the allowed radius can be nearer than d - radius along the segment,
// so the march steps by that amount (at least `min_step`). A contact deeper
// than about min_step / 2 cannot be missed. Distances from the part's
// control box (which contains it) bound the distance from below where no
// query is needed, e.g. high above the part.
//
// Units: mm, radians. Thread safety: pure functions of a const finder.
#include <Eigen/Core>
#include <optional>

#include "geometry/closest_point.hpp"
#include "base/numbers.hpp"

namespace furrow {

struct ProbeGeometry {
  double ball_radius = 1;     // r [mm], > 0
  double stylus_radius = 0.5; // r_s [mm], 0 < r_s <= r
  double stylus_length = 20;  // ball centre to probe body [mm], > r
};

struct AccessOptions {
  double approach = 3;   // [mm] ball surface to the part where the touch starts, > 0
  double retract = 3;    // [mm] ball surface to the part after the touch, > 0
  double max_tilt = 75 * kPi / 180;  // [rad]
  double clearance_z = 0;  // ball-centre height of the clearance plane [mm]
  // How much nearer than r (r_s) the part may come to the ball centre (the
  // shaft axis) and still count as clear: closest-point round-off [mm].
  double contact_tolerance = 1e-6;
  double min_step = 0.01;  // smallest sphere-tracing step [mm]
  int max_steps = 20000;   // per segment; beyond it the segment counts as blocked
};

enum class AccessProblem { none, tilt, ball, approach_path, stylus, vertical_access };
const char* to_string(AccessProblem problem);

struct AccessResult {
  AccessProblem problem = AccessProblem::none;
  double tilt = 0;   // angle between n and +z [rad]
  // For a collision: where (probe centre or shaft point) and how far the
  // part is from it there [mm]; the march-step cap counts as a collision
  // with `step_cap` set.
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
  double distance = 0;
  bool step_cap = false;
  bool ok() const { return problem == AccessProblem::none; }
};

// First point of the segment [a, b] where a sphere of `radius` centred on
// it would come nearer the part than radius - tolerance, with the distance
// there; nullopt when the whole segment is clear. `step_cap` is set when the
// march gave up after max_steps (then the segment counts as blocked at the
// last sample).
struct SegmentContact {
  double t = 0;            // position along the segment [mm from a]
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
  double distance = 0;     // part distance at `where` [mm]
  bool step_cap = false;
};
std::optional<SegmentContact> first_contact(const ClosestPointFinder& finder, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, double radius, double tolerance,
                                            double min_step, int max_steps);

// Probe-centre positions of a point (plan.json approach / retract).
Eigen::Vector3d probe_centre(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe);
Eigen::Vector3d approach_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                               const AccessOptions& options);
Eigen::Vector3d retract_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                              const AccessOptions& options);

// Checks 1-5 in that order and returns the first failure.
AccessResult check_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                          const ProbeGeometry& probe, const AccessOptions& options);

}  // namespace furrow
