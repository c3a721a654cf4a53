#include "planning/ball_contact.hpp"

#include <cmath>

namespace furrow {

const char* to_string(ContactProblem problem) {
  switch (problem) {
    case ContactProblem::none: return "none";
    case ContactProblem::elsewhere: return "the ball touches the part elsewhere first";
    case ContactProblem::second_touch: return "the ball also touches another face";
    case ContactProblem::leaves_region: return "the contact leaves the region when the ball is slightly off";
  }
  return "?";
}

namespace {

// Two unit tangents of the plane normal to n.
void tangents(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  const Eigen::Vector3d axis = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  t1 = n.cross(axis).normalized();
  t2 = n.cross(t1);
}

}  // namespace

ContactProblem check_ball_contact(const ClosestPointFinder& finder, std::size_t face, const Eigen::Vector3d& p,
                                  const Eigen::Vector3d& n, double radius, const InRegion& in_region,
                                  const BallContactOptions& options) {
  const Eigen::Vector3d c = p + radius * n;
  const ClosestPoint q = finder.project(c);
  if (q.face != face || (q.point - p).norm() > options.tolerance || q.distance < radius - options.tolerance)
    return ContactProblem::elsewhere;
  if (const std::optional<ClosestPoint> other = finder.project_to_other_faces(c, face))
    if (other->distance < radius + options.tolerance) return ContactProblem::second_touch;
  if (options.shift > 0) {
    Eigen::Vector3d t1, t2;
    tangents(n, t1, t2);
    for (const Eigen::Vector3d& t : {t1, Eigen::Vector3d(-t1), t2, Eigen::Vector3d(-t2)}) {
      const ClosestPoint s = finder.project(c + options.shift * t, q);
      if (s.face != face || !in_region(face, s.uv)) return ContactProblem::leaves_region;
    }
  }
  return ContactProblem::none;
}

double largest_fitting_ball(const ClosestPointFinder& finder, const std::vector<ContactCandidate>& candidates,
                            double radius, const InRegion& in_region, const BallContactOptions& options,
                            double resolution) {
  auto fits = [&](double r) {
    for (const ContactCandidate& k : candidates)
      if (check_ball_contact(finder, k.face, k.point, k.normal, r, in_region, options) == ContactProblem::none)
        return true;
    return false;
  };
  if (candidates.empty() || !(radius > 0) || !fits(std::min(resolution, radius))) return 0;
  if (fits(radius)) return radius;
  double lo = std::min(resolution, radius), hi = radius;  // fits(lo), !fits(hi)
  while (hi - lo > resolution) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace furrow
