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
    case AccessProblem::probe_body: return "probe body or extension would hit the part";
    case AccessProblem::head: return "probe head would hit the part";
    case AccessProblem::fixture: return "probe would go below the fixture plane the part rests on";
  }
  return "?";
}

std::optional<SegmentContact> first_contact(const ClosestPointFinder& finder, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, double radius, double tolerance,
                                            double min_step, int max_steps) {
  const double length = (b - a).norm();
  const Eigen::Vector3d dir = length > 0 ? Eigen::Vector3d((b - a) / length) : Eigen::Vector3d::Zero();
  const Eigen::AlignedBox3d& box = finder.control_box();
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

std::optional<SegmentContact> swept_contact(const ClosestPointFinder& finder, const Eigen::Vector3d& s0,
                                            const Eigen::Vector3d& s1, const Eigen::Vector3d& motion, double radius,
                                            double tolerance, double min_step, int max_steps) {
  const double h = std::max(radius / 2, min_step);
  const double length = (s1 - s0).norm();
  const int samples = static_cast<int>(std::ceil(length / h)) + 1;
  for (int k = 0; k < samples; ++k) {
    const double f = samples == 1 ? 0.0 : static_cast<double>(k) / (samples - 1);
    const Eigen::Vector3d q = s0 + f * (s1 - s0);
    if (auto hit = first_contact(finder, q, q + motion, radius + h / 2, tolerance, min_step, max_steps)) return hit;
  }
  return std::nullopt;
}

std::vector<ProbeCapsule> probe_capsules(const Eigen::Vector3d& c, const ProbeGeometry& probe) {
  std::vector<ProbeCapsule> out;
  if (!probe.articulated()) return out;
  const double r = probe.ball_radius, rs = probe.stylus_radius;
  const double leave = std::sqrt(std::max(0.0, r * r - rs * rs));
  out.push_back({c + leave * probe.axis, c + probe.stylus_length * probe.axis, rs, AccessProblem::stylus});
  double along = probe.stylus_length;
  for (const ProbeSection& s : probe.sections) {
    out.push_back({c + along * probe.axis, c + (along + s.length) * probe.axis, s.radius, AccessProblem::probe_body});
    along += s.length;
  }
  if (probe.housing.length > 0) {
    const Eigen::Vector3d pivot = c + along * probe.axis;
    out.push_back({pivot, pivot + probe.housing.length * Eigen::Vector3d::UnitZ(), probe.housing.radius, AccessProblem::head});
  }
  return out;
}

double assembly_drop(const ProbeGeometry& probe, double max_a_degrees) {
  double reach = probe.stylus_length, radius = probe.stylus_radius;
  for (const ProbeSection& s : probe.sections) {
    reach += s.length;
    radius = std::max(radius, s.radius);
  }
  radius = std::max(radius, probe.housing.radius);
  // The axis leaves the ball at angle A from +z: its far end sinks by
  // -reach cos A below the centre when A > 90 degrees, and a cylinder's rim
  // lies at most its radius (sin A <= 1) below its axis.
  const double a = std::min(max_a_degrees, 180.0) * kPi / 180;
  const double rim = max_a_degrees >= 90 ? radius : radius * std::sin(a);
  return std::max(probe.ball_radius, std::max(0.0, -reach * std::cos(a)) + rim);
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

namespace {

AccessResult failure(AccessResult result, AccessProblem problem, const SegmentContact& c) {
  result.problem = problem;
  result.where = c.where;
  result.distance = c.distance;
  result.step_cap = c.step_cap;
  return result;
}

// Checks 2 and 3: the ball at contact and along the normal.
AccessResult ball_checks(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                         const ProbeGeometry& probe, const AccessOptions& options, AccessResult result) {
  const double r = probe.ball_radius;
  const double tol = options.contact_tolerance;
  const Eigen::Vector3d c = probe_centre(p, n, probe);
  const double dc = finder.project(c).distance;
  if (dc < r - tol) return failure(result, AccessProblem::ball, {0, c, dc, false});
  const Eigen::Vector3d out = p + (r + std::max(options.approach, options.retract)) * n;
  if (auto hit = first_contact(finder, c, out, r, tol, options.min_step, options.max_steps))
    return failure(result, AccessProblem::approach_path, *hit);
  return result;
}

// Check 4: the shaft, from where it leaves the ball to the probe body.
AccessResult shaft_check(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                         const ProbeGeometry& probe, const AccessOptions& options, AccessResult result) {
  const double r = probe.ball_radius, rs = probe.stylus_radius;
  const Eigen::Vector3d c = probe_centre(p, n, probe);
  const double leave = std::sqrt(std::max(0.0, r * r - rs * rs));
  if (probe.stylus_length > leave) {
    const Eigen::Vector3d s0 = c + leave * probe.axis;
    const Eigen::Vector3d s1 = c + probe.stylus_length * probe.axis;
    if (auto hit = first_contact(finder, s0, s1, rs, options.contact_tolerance, options.min_step, options.max_steps))
      return failure(result, AccessProblem::stylus, *hit);
  }
  return result;
}

// Check 5: straight down to the approach point, straight up from the retract point.
AccessResult vertical_check(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                            const ProbeGeometry& probe, const AccessOptions& options, AccessResult result) {
  for (const Eigen::Vector3d& q : {approach_point(p, n, probe, options), retract_point(p, n, probe, options)}) {
    if (q.z() >= options.clearance_z) continue;
    const Eigen::Vector3d top(q.x(), q.y(), options.clearance_z);
    if (auto hit = first_contact(finder, q, top, probe.ball_radius, options.contact_tolerance, options.min_step,
                                 options.max_steps))
      return failure(result, AccessProblem::vertical_access, *hit);
  }
  return result;
}

// Check 6: the whole assembly of an indexable head, along the touch and the
// vertical legs.
AccessResult assembly_check(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                            const ProbeGeometry& probe, const AccessOptions& options, AccessResult result) {
  const double r = probe.ball_radius, tol = options.contact_tolerance;
  const Eigen::Vector3d c = probe_centre(p, n, probe);
  const Eigen::Vector3d out = p + (r + std::max(options.approach, options.retract)) * n;
  for (const ProbeCapsule& k : probe_capsules(c, probe))
    if (auto hit = swept_contact(finder, k.a, k.b, out - c, k.radius, tol, options.min_step, options.max_steps))
      return failure(result, k.part, *hit);
  for (const Eigen::Vector3d& q : {approach_point(p, n, probe, options), retract_point(p, n, probe, options)}) {
    if (q.z() >= options.clearance_z || !probe.articulated()) continue;
    const Eigen::Vector3d rise(0, 0, options.clearance_z - q.z());
    for (const ProbeCapsule& k : probe_capsules(q, probe))
      if (auto hit = swept_contact(finder, k.a, k.b, rise, k.radius, tol, options.min_step, options.max_steps))
        return failure(result, AccessProblem::vertical_access, *hit);
  }
  return result;
}

// Check 6, the ball: at the contact, approach and retract points its lowest
// point stays above the fixture plane.
AccessResult fixture_ball_check(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                                const AccessOptions& options, AccessResult result) {
  if (!options.fixture_z) return result;
  const double floor = *options.fixture_z - options.contact_tolerance;
  for (const Eigen::Vector3d& q :
       {probe_centre(p, n, probe), approach_point(p, n, probe, options), retract_point(p, n, probe, options)})
    if (q.z() - probe.ball_radius < floor)
      return failure(result, AccessProblem::fixture, {0, q, q.z() - *options.fixture_z, false});
  return result;
}

// Check 6, the assembly: the head's capsules at the same three places
// (the vertical stylus's shaft rises from the ball: the ball is its lowest part).
AccessResult fixture_assembly_check(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                                    const AccessOptions& options, AccessResult result) {
  if (!options.fixture_z) return result;
  const double floor = *options.fixture_z - options.contact_tolerance;
  for (const Eigen::Vector3d& q :
       {probe_centre(p, n, probe), approach_point(p, n, probe, options), retract_point(p, n, probe, options)})
    for (const ProbeCapsule& k : probe_capsules(q, probe)) {
      const Eigen::Vector3d& low = k.a.z() < k.b.z() ? k.a : k.b;
      if (low.z() - k.radius < floor)
        return failure(result, AccessProblem::fixture, {0, low, low.z() - *options.fixture_z, false});
    }
  return result;
}

AccessResult tilt_check(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const ProbeGeometry& probe,
                        const AccessOptions& options) {
  AccessResult result;
  result.tilt = std::acos(std::clamp(n.dot(probe.axis), -1.0, 1.0));
  if (result.tilt > options.max_tilt) {
    result.problem = AccessProblem::tilt;
    result.where = p;
  }
  return result;
}

}  // namespace

AccessResult check_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                          const ProbeGeometry& probe, const AccessOptions& options) {
  AccessResult result = tilt_check(p, n, probe, options);
  if (!result.ok()) return result;
  if (result = ball_checks(finder, p, n, probe, options, result); !result.ok()) return result;
  if (result = shaft_check(finder, p, n, probe, options, result); !result.ok()) return result;
  if (result = vertical_check(finder, p, n, probe, options, result); !result.ok()) return result;
  if (result = fixture_ball_check(p, n, probe, options, result); !result.ok()) return result;
  if (result = fixture_assembly_check(p, n, probe, options, result); !result.ok()) return result;
  return assembly_check(finder, p, n, probe, options, result);
}

AccessResult check_point_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                const ProbeGeometry& probe, const AccessOptions& options) {
  AccessResult result;
  if (result = fixture_ball_check(p, n, probe, options, result); !result.ok()) return result;
  if (result = ball_checks(finder, p, n, probe, options, result); !result.ok()) return result;
  return vertical_check(finder, p, n, probe, options, result);
}

AccessResult check_axis_access(const ClosestPointFinder& finder, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                               const ProbeGeometry& probe, const AccessOptions& options) {
  AccessResult result = tilt_check(p, n, probe, options);
  if (!result.ok()) return result;
  if (result = fixture_assembly_check(p, n, probe, options, result); !result.ok()) return result;
  if (result = shaft_check(finder, p, n, probe, options, result); !result.ok()) return result;
  return assembly_check(finder, p, n, probe, options, result);
}

}  // namespace furrow
