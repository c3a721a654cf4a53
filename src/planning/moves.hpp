#pragma once
// The probe's travel between points, and how long the program takes.
//
// From one point's retract position to the next point's approach position
// the probe goes straight when the straight segment keeps the ball at least
// `clearance` mm from the part (ball surface to part, sphere tracing with the
// exact part distance, accessibility.hpp); otherwise it rises vertically to
// the clearance plane, crosses over and comes down vertically to the
// approach point. The clearance plane is the ball-centre height
// `top of the part + r + clearance`, with the top taken from the control
// box (which contains the part), so every crossing move clears the part by
// at least `clearance`; the vertical legs were checked with each point
// (check_access, vertical access). The program starts above the first
// approach point on the clearance plane and ends above the last retract
// point there.
//
// Cycle time: every straight leg is a rest-to-rest move with a trapezoidal
// speed profile (acceleration a up to speed v, then decelerate):
//   t = L / v + v / a      when L >= v^2 / a,   t = 2 sqrt(L / a) otherwise;
// positioning legs and the retract at `move_speed`, the approach distance at
// `touch_speed` (the CMM switches to measuring speed there), plus `dwell`
// seconds per point (probe trigger, settling, data transfer).
//
// Units: mm, mm/s, mm/s^2, s.
#include <Eigen/Core>
#include <vector>

#include "geometry/closest_point.hpp"
#include "planning/accessibility.hpp"

namespace furrow {

struct MotionModel {
  double move_speed = 50;     // positioning [mm/s]
  double touch_speed = 4;     // measuring, over the approach distance [mm/s]
  double acceleration = 500;  // [mm/s^2]
  double dwell = 0.2;         // per point [s]
};

struct MoveOptions {
  double clearance = 2;    // ball surface to part on straight moves [mm], >= 0
  double clearance_z = 0;  // ball-centre height of the clearance plane [mm]
  double contact_tolerance = 1e-6;
  double min_step = 0.01;
  int max_steps = 20000;
};

struct Move {
  std::vector<Eigen::Vector3d> waypoints;  // after the start, the last is the target
  bool straight = true;
  double length = 0;  // [mm]
};

// Clearance-plane height for a part and probe [mm].
double clearance_plane(const Part& part, double ball_radius, double clearance);

// Move from `from` (a retract point) to `to` (an approach point).
Move plan_move(const ClosestPointFinder& finder, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
               double ball_radius, const MoveOptions& options);

// Up to the clearance plane (or the higher end), over, and down: the move
// plan_move falls back to, and every move across an indexable head's tip
// change (the head turns on the plane, above `from`).
Move plane_move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double clearance_z);

// Rest-to-rest time of a straight leg [s].
double leg_time(double length, double speed, double acceleration);

struct CycleEstimate {
  double positioning_length = 0;  // all positioning legs [mm]
  double touch_length = 0;        // approach + retract legs [mm]
  double seconds = 0;
  int straight_moves = 0, plane_moves = 0;
};

// `moves[k]` is the move before point k (moves[0] starts at the clearance
// point above point 0's approach point: its waypoints are that point's
// descent), `final_moves` the legs after the last point.
CycleEstimate estimate_cycle(const Eigen::Vector3d& start, const std::vector<Move>& moves,
                             const std::vector<Eigen::Vector3d>& retract_points,
                             const std::vector<Eigen::Vector3d>& final_moves, double approach, double retract,
                             const MotionModel& model);

}  // namespace furrow
