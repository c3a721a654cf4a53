#include "inspection/registration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "inspection/outlier_detection.hpp"
#include "inspection/surface_fit.hpp"

namespace furrow {

const char* to_string(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::none:
      return "none";
    case RobustLoss::huber:
      return "huber";
    case RobustLoss::cauchy:
      return "cauchy";
  }
  return "?";
}

RobustLoss parse_robust_loss(const std::string& text, const std::string& where) {
  if (text == "none" || text == "least-squares") return RobustLoss::none;
  if (text == "huber") return RobustLoss::huber;
  if (text == "cauchy") return RobustLoss::cauchy;
  throw InputError(where + ": \"" + text + "\" is not a loss (none, huber, cauchy)");
}

const char* to_string(OutlierReason reason) {
  switch (reason) {
    case OutlierReason::none:
      return "none";
    case OutlierReason::beyond_edge:
      return "beyond_edge";
    case OutlierReason::no_foot_point:
      return "no_foot_point";
    case OutlierReason::blunder:
      return "blunder";
    case OutlierReason::large_deviation:
      return "large_deviation";
  }
  return "?";
}

std::size_t RegistrationResult::in_fit_count() const {
  return static_cast<std::size_t>(std::count_if(points.begin(), points.end(),
                                                [](const RegisteredPoint& p) { return p.in_fit; }));
}

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

// Sideways distance of q from the surface at a boundary foot point [mm].
double sideways(const Eigen::Vector3d& q, const ClosestPoint& c) {
  const Eigen::Vector3d r = q - c.point;
  return (r - r.dot(c.normal) * c.normal).norm();
}

struct Workspace {
  const ClosestPointFinder& finder;
  const MeasurementSet& set;
  const RegistrationOptions& options;
  SurfaceFit& fit;
  std::vector<ClosestPoint> feet;
  std::vector<OutlierReason> geometric;  // beyond_edge / no_foot_point per projection
  std::vector<bool> excluded;            // left out of the fit by the outlier rule
  bool projected_once = false;

  // Projects every moved point (in parallel, warm-started at its last foot)
  // and hands feet and activity to the fit.
  void project() {
    const std::size_t n = fit.size();
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d x = fit.moved(i);
      feet[i] = projected_once ? finder.project(x, feet[i]) : finder.project(x);
      OutlierReason reason = OutlierReason::none;
      if (!feet[i].converged)
        reason = OutlierReason::no_foot_point;
      else if (feet[i].location != FootLocation::interior &&
               sideways(x, feet[i]) > options.edge_tolerance)
        reason = OutlierReason::beyond_edge;
      geometric[i] = reason;
      fit.set_foot(i, feet[i].point, feet[i].normal, reason == OutlierReason::none && !excluded[i]);
    }
    projected_once = true;
  }
};

// The correction x = R(r) y + t of a parameter vector (r, t).
Eigen::Isometry3d rigid_motion(const Eigen::Matrix<double, 6, 1>& p) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d r = p.head<3>();
  if (r.norm() > 0) m.linear() = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix();
  m.translation() = p.tail<3>();
  return m;
}

// Bound on the largest displacement between two corrections of points at
// most `reach` from the origin [mm].
double motion(const Eigen::Matrix<double, 6, 1>& a, const Eigen::Matrix<double, 6, 1>& b,
              double reach) {
  const Eigen::Isometry3d ma = rigid_motion(a), mb = rigid_motion(b);
  const double angle = Eigen::AngleAxisd(ma.linear().transpose() * mb.linear()).angle();
  return (ma.translation() - mb.translation()).norm() + angle * reach;
};

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0 : std::sqrt(s / static_cast<double>(v.size()));
}

}  // namespace

RegistrationResult register_measurements(const ClosestPointFinder& finder,
                                         const MeasurementSet& set, const InspectionPlan* plan,
                                         const RegistrationOptions& options) {
  const std::size_t n = set.points.size();
  const int dof = options.dof.count();
  if (static_cast<int>(n) < dof)
    throw InputError(set.source + ": " + std::to_string(n) + " points cannot fix " +
                     std::to_string(dof) + " degrees of freedom");
  RegistrationResult result;
  auto note = [&](const std::string& what) {
    if (options.progress) options.progress(what);
  };
  note("coarse start");
  if (options.dof.all_free()) {
    result.coarse = coarse_alignment(finder, set, plan, options.coarse);
  } else {
    result.coarse.method = CoarseMethod::identity;
    result.coarse.median_distance = median_surface_distance(
        finder, set, Eigen::Isometry3d::Identity(), options.coarse.refine_points);
  }
  note("fit setup");
  std::vector<Eigen::Vector3d> y(n);
  double reach = 0;
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = result.coarse.transform * set.points[i].xyz;
    reach = std::max(reach, y[i].norm());
  }
  SurfaceFit fit(y, set.probe_radius, options.dof, options.loss, options.loss_scale,
                 options.max_solver_iterations);
  Workspace ws{finder,
               set,
               options,
               fit,
               std::vector<ClosestPoint>(n),
               std::vector<OutlierReason>(n, OutlierReason::none),
               std::vector<bool>(n, false)};

  ws.project();
  {
    std::vector<double> d;
    for (std::size_t i = 0; i < n; ++i)
      if (ws.geometric[i] == OutlierReason::none) d.push_back(fit.residual(i));
    result.rms_before = rms(d);
  }
  std::vector<OutlierReason> verdict(n, OutlierReason::none);
  OutlierVerdict numbers;
  const OutlierRule rule{options.outlier_sigma, options.outlier_floor, options.confirm_neighbours,
                         options.neighbour_radius};
  std::string solver_message;
  for (int pass = 1; pass <= std::max(1, options.max_outlier_passes); ++pass) {
    result.outlier_passes = pass;
    result.converged = false;
    for (int outer = 1; outer <= options.max_outer_iterations; ++outer) {
      ++result.outer_iterations;
      note("fit " + std::to_string(pass) + "." + std::to_string(outer));
      const Eigen::Matrix<double, 6, 1> before = fit.parameters();
      std::size_t active = 0;
      for (std::size_t i = 0; i < n; ++i)
        active += ws.geometric[i] == OutlierReason::none && !ws.excluded[i];
      if (static_cast<int>(active) < dof)
        throw InputError(set.source + ": only " + std::to_string(active) +
                         " points lie on the part after alignment; " + std::to_string(dof) +
                         " degrees of freedom cannot be fitted");
      result.solver_iterations += fit.solve(solver_message);
      ws.project();
      if (!solver_message.empty()) break;
      if (motion(before, fit.parameters(), reach) <= options.motion_tolerance) {
        result.converged = true;
        break;
      }
    }
    if (!options.flag_outliers || !solver_message.empty()) break;
    std::vector<Eigen::Vector3d> positions(n);
    std::vector<double> deviation(n);
    std::vector<bool> usable(n);
    for (std::size_t i = 0; i < n; ++i) {
      // Neighbours on the surface: at the foot points, not the measured
      // points - blunders off the same side of a dense scan are closer to
      // each other than to the surface and would vouch for each other.
      positions[i] = ws.feet[i].point;
      deviation[i] = fit.residual(i);
      usable[i] = ws.geometric[i] == OutlierReason::none;
    }
    numbers = classify_deviations(positions, deviation, usable, rule, verdict);
    std::vector<bool> excluded(n);
    for (std::size_t i = 0; i < n; ++i)
      excluded[i] = usable[i] && verdict[i] != OutlierReason::none;
    if (excluded == ws.excluded) break;
    if (static_cast<int>(std::count(excluded.begin(), excluded.end(), false)) < dof) break;
    ws.excluded = excluded;
    fit.set_loss(RobustLoss::none, options.loss_scale);
    for (std::size_t i = 0; i < n; ++i)
      fit.set_foot(i, ws.feet[i].point, ws.feet[i].normal, usable[i] && !excluded[i]);
  }
  result.status = !solver_message.empty() ? "solver failed: " + solver_message
                  : result.converged      ? "converged"
                                          : "outer iteration limit reached";

  // Results per point at the final transform.
  result.points.resize(n);
  std::vector<double> fitted;
  for (std::size_t i = 0; i < n; ++i) {
    RegisteredPoint& p = result.points[i];
    p.registered = fit.moved(i);
    p.foot = ws.feet[i];
    p.deviation = fit.residual(i);
    p.outlier = ws.geometric[i] != OutlierReason::none ? ws.geometric[i]
                : ws.excluded[i]                       ? verdict[i]
                                                       : OutlierReason::none;
    p.in_fit = p.outlier == OutlierReason::none;
    p.evaluated = p.outlier == OutlierReason::none || p.outlier == OutlierReason::large_deviation;
    if (p.outlier == OutlierReason::beyond_edge)
      p.outlier_detail = "foot on the " + std::string(to_string(p.foot.location)) + ", point " +
                         number(sideways(p.registered, p.foot)) + " mm beside the surface";
    else if (p.outlier == OutlierReason::no_foot_point)
      p.outlier_detail = "closest-point search did not converge";
    else if (p.outlier != OutlierReason::none)
      p.outlier_detail =
          "|d - median| = " + number(std::abs(p.deviation - numbers.median)) + " mm > " +
          number(numbers.limit) + " mm (" + number(options.outlier_sigma) + " x robust sigma " +
          number(numbers.robust_sigma) + " mm, floor " + number(options.outlier_floor) + " mm)";
    if (p.in_fit) fitted.push_back(p.deviation);
  }
  result.rms_after = rms(fitted);
  const double redundancy = static_cast<double>(fitted.size()) - dof;
  result.sigma = redundancy > 0 ? rms(fitted) * std::sqrt(fitted.size() / redundancy) : 0;

  result.parameters = fit.parameters();
  result.transform = rigid_motion(fit.parameters()) * result.coarse.transform;
  // With all six DOF free, the covariance is that of a small correction on
  // the final transform: re-base the points on it first.
  if (options.dof.all_free()) fit.rebase();
  result.covariance_status = "not computed";
  note("covariance");
  if (options.compute_covariance) {
    if (auto c = fit.covariance(result.covariance_status)) {
      result.covariance = (*c) * (result.sigma * result.sigma);
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Matrix<double, 1, 6> j = fit.jacobian(i);
        result.points[i].uncertainty =
            std::sqrt(std::max(0.0, (j * (*result.covariance) * j.transpose())(0)));
      }
    }
  }
  return result;
}

}  // namespace furrow
