#include "inspection/orientation_check.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "base/numbers.hpp"
#include "inspection/registration_run.hpp"

namespace furrow {

namespace {

double turn_between(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace

double fit_cost(const RegistrationResult& r, const RegistrationOptions& options) {
  const double t2 = options.outlier_floor * options.outlier_floor;
  double cost = 0;
  for (const RegisteredPoint& p : r.points) {
    const bool footless = p.outlier == OutlierReason::no_foot_point || !std::isfinite(p.deviation);
    cost += footless ? t2 : std::min(p.deviation * p.deviation, t2);
  }
  return cost;
}

OtherOrientation orientation_of(const RegistrationResult& fit) {
  OtherOrientation o;
  o.transform = fit.transform;
  o.deviation.reserve(fit.points.size());
  for (const RegisteredPoint& p : fit.points)
    o.deviation.push_back(p.evaluated ? std::optional<double>(p.deviation) : std::nullopt);
  return o;
}

bool another_orientation(const Eigen::Isometry3d& kept, double kept_cost, const Eigen::Isometry3d& other,
                         double other_cost, const CoarseOptions& options) {
  return turn_between(kept, other) > radians(options.ambiguity_angle_deg) &&
         other_cost <= options.ambiguity_ratio * kept_cost;
}

RegistrationResult settle_orientation(RegistrationResult first, const ClosestPointFinder& finder,
                                      const MeasurementSet& set, const InspectionPlan* plan,
                                      const RegistrationOptions& options) {
  const CoarseResult coarse = first.coarse;
  if (options.start || coarse.method != CoarseMethod::global_search || !coarse.ambiguous || !first.converged)
    return first;
  // The runner-up: the best other placement turned more than the angle
  // (the alternatives come best first).
  const Eigen::Isometry3d* runner_up = nullptr;
  for (const Eigen::Isometry3d& t : coarse.alternatives)
    if (turn_between(coarse.transform, t) > radians(options.coarse.ambiguity_angle_deg)) {
      runner_up = &t;
      break;
    }
  first.coarse.ambiguous = false;
  if (!runner_up) return first;
  RegistrationOptions o = options;
  o.start = *runner_up;
  o.progress = nullptr;
  RegistrationResult other = run_registration(finder, set, plan, o);
  if (!other.converged) return first;
  const double first_cost = fit_cost(first, options), other_cost = fit_cost(other, options);
  if (!(other_cost < first_cost * (1 - 1e-9))) {
    first.coarse.ambiguous =
        another_orientation(first.transform, first_cost, other.transform, other_cost, options.coarse);
    if (first.coarse.ambiguous) first.other_orientation = orientation_of(other);
    return first;
  }
  // The runner-up's fit explains the points better: it is the result, with
  // the search's record and its own start.
  const double median = other.coarse.median_distance;
  other.coarse = coarse;
  other.coarse.transform = *runner_up;
  other.coarse.median_distance = median;
  other.coarse.ambiguous =
      another_orientation(other.transform, other_cost, first.transform, first_cost, options.coarse);
  if (other.coarse.ambiguous) other.other_orientation = orientation_of(first);
  return other;
}

}  // namespace furrow
