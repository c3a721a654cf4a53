#include "planning/moves.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

double clearance_plane(const Part& part, double ball_radius, double clearance) {
  return part.control_box().max().z() + ball_radius + clearance;
}

Move plan_move(const ClosestPointFinder& finder, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
               double ball_radius, const MoveOptions& options) {
  Move move;
  if (!first_contact(finder, from, to, ball_radius + options.clearance, options.contact_tolerance, options.min_step,
                     options.max_steps)) {
    move.waypoints = {to};
    move.length = (to - from).norm();
    return move;
  }
  return plane_move(from, to, options.clearance_z);
}

Move plane_move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double clearance_z) {
  Move move;
  move.straight = false;
  const double z = std::max({clearance_z, from.z(), to.z()});
  const Eigen::Vector3d up(from.x(), from.y(), z), over(to.x(), to.y(), z);
  move.waypoints = {up, over, to};
  move.length = (up - from).norm() + (over - up).norm() + (to - over).norm();
  return move;
}

double leg_time(double length, double speed, double acceleration) {
  if (!(length > 0)) return 0;
  if (length >= speed * speed / acceleration) return length / speed + speed / acceleration;
  return 2 * std::sqrt(length / acceleration);
}

CycleEstimate estimate_cycle(const Eigen::Vector3d& start, const std::vector<Move>& moves,
                             const std::vector<Eigen::Vector3d>& retract_points,
                             const std::vector<Eigen::Vector3d>& final_moves, double approach, double retract,
                             const MotionModel& model) {
  CycleEstimate e;
  Eigen::Vector3d at = start;
  auto leg = [&](const Eigen::Vector3d& to) {
    const double length = (to - at).norm();
    e.positioning_length += length;
    e.seconds += leg_time(length, model.move_speed, model.acceleration);
    at = to;
  };
  for (std::size_t k = 0; k < moves.size(); ++k) {
    for (const Eigen::Vector3d& w : moves[k].waypoints) leg(w);
    if (k > 0) ++(moves[k].straight ? e.straight_moves : e.plane_moves);
    // Touch: approach distance at measuring speed, then back off.
    e.touch_length += approach + retract;
    e.seconds += leg_time(approach, model.touch_speed, model.acceleration) +
                 leg_time(retract, model.move_speed, model.acceleration) + model.dwell;
    at = retract_points[k];
  }
  for (const Eigen::Vector3d& w : final_moves) leg(w);
  return e;
}

}  // namespace furrow
