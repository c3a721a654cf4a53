#include "inspection/fixed_alignment.hpp"

#include <cmath>

namespace furrow {

RegistrationResult evaluate_at_transform(const ClosestPointFinder& finder, const MeasurementSet& set,
                                         const Eigen::Isometry3d& transform, const RegistrationOptions& options,
                                         const std::string& note) {
  RegistrationResult r;
  r.transform = transform;
  r.coarse.method = CoarseMethod::identity;
  r.coarse.transform = transform;
  r.converged = true;
  r.outcome = FitOutcome::converged;
  r.status = note;
  r.fitted_dof = 0;
  r.covariance_status = "not computed: no fit";
  const std::size_t n = set.points.size();
  r.points.resize(n);
#pragma omp parallel for schedule(dynamic, 256) if (n >= kParallelProjections)
  for (std::size_t i = 0; i < n; ++i) {
    RegisteredPoint& p = r.points[i];
    p.registered = transform * set.points[i].xyz;
    p.foot = finder.project(p.registered);
    p.in_fit = false;
    if (!p.foot.converged) {
      p.outlier = OutlierReason::no_foot_point;
      p.outlier_detail = "closest-point search did not converge";
      p.evaluated = false;
      continue;
    }
    p.deviation = p.foot.normal.dot(p.registered - p.foot.point) - set.probe_radius;
    const Eigen::Vector3d off = p.registered - p.foot.point;
    const double beside = (off - off.dot(p.foot.normal) * p.foot.normal).norm();
    if (p.foot.location != FootLocation::interior && beside > options.edge_tolerance) {
      p.outlier = OutlierReason::beyond_edge;
      p.outlier_detail = "foot on the " + std::string(to_string(p.foot.location)) + ", point " +
                         std::to_string(beside) + " mm beside the surface";
      p.evaluated = false;
    }
  }
  double sum = 0;
  std::size_t count = 0;
  for (const RegisteredPoint& p : r.points)
    if (p.evaluated) {
      sum += p.deviation * p.deviation;
      ++count;
    }
  r.rms_before = r.rms_after = count ? std::sqrt(sum / static_cast<double>(count)) : 0;
  r.sigma = 0;
  return r;
}

}  // namespace furrow
