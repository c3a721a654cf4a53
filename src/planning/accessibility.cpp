#include "planning/accessibility.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

const char* to_string(AccessProblem problem) {
  switch (problem) {
    case AccessProblem::none: return "accessible";
    case AccessProblem::tilt: return "normal tilted beyond --max-tilt from vertical";
    case AccessProblem::ball: return "probe ball would touch the part elsewhere";
    case AccessProblem::approach_path: return "approach/retract path along the normal hits the part";
    case AccessProblem::stylus: return "stylus shaft would hit the part";
    case AccessProblem::vertical_access: return "no vertical access from the clearance plane";
  }
  return "?";
}

std::optional<SegmentContact> first_contact(const ClosestPointFinder& finder, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, double radius, double tolerance,
                                            double min_step, int max_steps) {
  const double length = (b - a).norm();
  const Eigen::Vector3d dir = length > 0 ? Eigen::Vector3d((b - a) / length) : Eigen::Vector3d::Zero();
  const Eigen::AlignedBox3d box = finder.part().control_box();
  const double allowed = radius - tolerance;
  double t = 0;
  for (int step = 0; step < max_steps; ++step) {
    const Eigen::Vector3d q = a + t * dir;
    // The control box contains the part: its distance is a lower bound.
    double d = box.exteriorDistance(q);
    if (d < radius) d = finder.project(q).distance;
    if (d < allowed) return SegmentContact{t, q, d, false};
    if (t >= length) return std::nullopt;
    t = std::min(length, t + std::max(d - allowed, min_step));
  }
  const Eigen::Vector3d q = a + t * dir;
  return SegmentContact{t, q, finder.project(q).distance, true};
}

Eigen::Vector3d probe_centre(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe) {
  return p + probe.ball_radius * n;
}

Eigen::Vector3d approach_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                               const AccessOptions& options) {
  return p + (probe.ball_radius + options.approach) * n;
}

Eigen::Vector3d retract_point(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                              const AccessOptions& options) {
  return p + (probe.ball_radius + options.retract) * n;
}

AccessResult check_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                          const ProbeGeometry& probe, const AccessOptions& options) {
  AccessResult result;
  result.tilt = std::acos(std::clamp(n.z(), -1.0, 1.0));
  auto fail = [&](AccessProblem problem, const SegmentContact& c) {
    result.problem = problem;
    result.where = c.where;
    result.distance = c.distance;
    result.step_cap = c.step_cap;
    return result;
  };
  if (result.tilt > options.max_tilt) {
    result.problem = AccessProblem::tilt;
    result.where = p;
    return result;
  }
  const double r = probe.ball_radius;
  const double tol = options.contact_tolerance;
  const Eigen::Vector3d c = probe_centre(p, n, probe);
  // 2. The ball at contact.
  const double dc = finder.project(c).distance;
  if (dc < r - tol) return fail(AccessProblem::ball, {0, c, dc, false});
  // 3. Along the normal to the farther of approach and retract.
  const Eigen::Vector3d out = p + (r + std::max(options.approach, options.retract)) * n;
  if (auto hit = first_contact(finder, c, out, r, tol, options.min_step, options.max_steps))
    return fail(AccessProblem::approach_path, *hit);
  // 4. The shaft, from where it leaves the ball to the probe body.
  const double rs = probe.stylus_radius;
  const double leave = std::sqrt(std::max(0.0, r * r - rs * rs));
  if (probe.stylus_length > leave) {
    const Eigen::Vector3d s0 = c + leave * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d s1 = c + probe.stylus_length * Eigen::Vector3d::UnitZ();
    if (auto hit = first_contact(finder, s0, s1, rs, tol, options.min_step, options.max_steps))
      return fail(AccessProblem::stylus, *hit);
  }
  // 5. Straight down to the approach point, straight up from the retract point.
  for (const Eigen::Vector3d& q : {approach_point(p, n, probe, options), retract_point(p, n, probe, options)}) {
    if (q.z() >= options.clearance_z) continue;
    const Eigen::Vector3d top(q.x(), q.y(), options.clearance_z);
    if (auto hit = first_contact(finder, q, top, r, tol, options.min_step, options.max_steps))
      return fail(AccessProblem::vertical_access, *hit);
  }
  return result;
}

}  // namespace furrow
