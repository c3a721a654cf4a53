#pragma once
// Can a CMM probe take this point? (docs/cmm.md)
//
// The probe is a ball of radius r on a cylindrical shaft (radius r_s <= r,
// from the ball up to `stylus_length` from the ball centre, where the probe
// body starts) along the probe's `axis` (unit, from the ball centre towards
// the probe body): +z for the fixed vertical stylus, the reverse of the tip
// direction for an indexable head (io/cmm/probe_head.hpp). A point p with
// outward unit normal n is measured with the ball centre at c = p + r n,
// moving along -n from the approach point c + approach n and backing off to
// c + retract n. The point is accessible when
//   1. tilt: the angle between n and the axis is at most max_tilt (a
//      vertical stylus reaches points facing up or sideways, not undercuts);
//   2. ball: the ball touches the part only at p: the distance from c to
//      the whole part (global closest point) is r, nothing nearer (a groove
//      narrower than the ball, a neighbouring wall);
//   3. approach path: the ball, moved from c along n to the farther of the
//      approach and retract points, stays clear (distance >= r);
//   4. stylus: the shaft, from where it leaves the ball up to the probe
//      body, stays clear of the part (distance >= r_s);
//   5. vertical access: the ball can come straight down from the clearance
//      plane to the approach point and go straight up from the retract point
//      (how the moves reach and leave every point, moves.hpp);
//   6. fixture (only when `fixture_z` is set: a further setup, the part
//      resting on one of its faces on a fixture plane, docs/cmm.md
//      "Setups"): the ball, at the contact and at the approach and retract
//      points, and every capsule of a head's assembly there, stay above the
//      plane. The touch is a straight move between those points and the
//      vertical legs only rise, so their lowest points are these ends;
//   7. with an indexable head only (`sections` not empty): the whole
//      assembly - shaft, extension and probe body along the axis, the head's
//      vertical housing above the centre of rotation, each a capsule (a
//      cylinder with round ends, which contains the cylinder) - stays clear
//      while it moves along the touch (contact to the farther of approach
//      and retract) and along both vertical legs to the clearance plane.
//
// Segments are checked by sphere tracing with the exact distance to the
// part (ClosestPointFinder): from a sample at distance d, nothing closer
// than the allowed radius can be nearer than d - radius along the segment,
// so the march steps by that amount (at least `min_step`). A contact deeper
// than about min_step / 2 cannot be missed. Distances from the part's
// control box (which contains it) bound the distance from below where no
// query is needed, e.g. high above the part. A moving capsule (check 6) is
// sampled along its axis every h = radius / 2 and each sample traced along
// the motion with the radius grown by h / 2: every point of the swept
// volume is within h / 2 of a traced line, so a clear trace means a clear
// volume (conservative by h / 2).
//
// Units: mm, radians. Thread safety: pure functions of a const finder.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "geometry/closest_point.hpp"
#include "base/numbers.hpp"

namespace furrow {

// A cylinder of the probe assembly beyond the stylus.
struct ProbeSection {
  double length = 0;  // [mm] > 0
  double radius = 0;  // [mm] > 0
};

struct ProbeGeometry {
  double ball_radius = 1;     // r [mm], > 0
  double stylus_radius = 0.5; // r_s [mm], 0 < r_s <= r
  double stylus_length = 20;  // ball centre to probe body [mm], > r
  // Unit, from the ball centre towards the probe body.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  // Indexable head: the cylinders after the stylus along the axis
  // (extension, probe body; the last ends at the head's centre of rotation)
  // and the head's housing, vertical above that centre (length 0: none).
  // Empty `sections`: the fixed vertical stylus, checks 1-5 only.
  std::vector<ProbeSection> sections = {};
  ProbeSection housing = {};
  bool articulated() const { return !sections.empty(); }
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
  // The fixture plane the part rests on in a further setup [mm, z in the
  // setup frame]; unset: none (the first setup, the part as imported).
  std::optional<double> fixture_z;
};

enum class AccessProblem { none, tilt, ball, approach_path, stylus, vertical_access, probe_body, head, fixture };
const char* to_string(AccessProblem problem);

struct AccessResult {
  AccessProblem problem = AccessProblem::none;
  double tilt = 0;   // angle between n and the probe axis [rad]
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

// First contact of the capsule (segment [s0, s1], `radius`) while it moves
// by 0..`motion` (check 6: sampled along the segment every radius / 2, each
// sample traced along the motion with the radius grown by a quarter).
std::optional<SegmentContact> swept_contact(const ClosestPointFinder& finder, const Eigen::Vector3d& s0,
                                            const Eigen::Vector3d& s1, const Eigen::Vector3d& motion, double radius,
                                            double tolerance, double min_step, int max_steps);

// The assembly's capsules with the ball centre at `c`: shaft (stylus),
// sections (probe_body), housing (head). Empty for the vertical stylus.
struct ProbeCapsule {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0;
  AccessProblem part = AccessProblem::stylus;
};
std::vector<ProbeCapsule> probe_capsules(const Eigen::Vector3d& c, const ProbeGeometry& probe);

// How far the assembly reaches below its ball centre over any tilt between
// the vertical and `max_a_degrees` (A of an indexable head), for a clearance
// plane the head can turn on [mm, >= ball radius].
double assembly_drop(const ProbeGeometry& probe, double max_a_degrees);

// Probe-centre positions of a point (plan.json approach / retract).
Eigen::Vector3d probe_centre(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe);
Eigen::Vector3d approach_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                               const AccessOptions& options);
Eigen::Vector3d retract_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                              const AccessOptions& options);

// Checks 1-7 in that order and returns the first failure.
AccessResult check_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                          const ProbeGeometry& probe, const AccessOptions& options);

// The same checks split by what depends on the probe's axis, for trying
// many tips of an indexable head at one point (docs/cmm.md "Tips chosen by
// the planner"): check_point_access runs 2, 3 and 5 (the ball alone, the
// same for every tip; `probe.axis` is not read), check_axis_access 1, 4 and
// 6. For every probe, check_access(...).ok() equals
// check_point_access(...).ok() && check_axis_access(...).ok(); only which
// failure is named first may differ.
AccessResult check_point_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                const ProbeGeometry& probe, const AccessOptions& options);
AccessResult check_axis_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                               const ProbeGeometry& probe, const AccessOptions& options);

}  // namespace furrow
