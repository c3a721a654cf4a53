#include "inspection/registration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "inspection/outlier_detection.hpp"
#include "inspection/surface_sampling.hpp"
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

const char* to_string(FitOutcome outcome) {
  switch (outcome) {
    case FitOutcome::converged:
      return "converged";
    case FitOutcome::not_converged:
      return "not_converged";
    case FitOutcome::too_few_points:
      return "too_few_points";
  }
  return "?";
}

std::size_t RegistrationResult::in_fit_count() const {
  return static_cast<std::size_t>(std::count_if(points.begin(), points.end(),
                                                [](const RegisteredPoint& p) { return p.in_fit; }));
}

namespace {

// Below this share (observability.hpp) a motion is not seen at all: an
// exact symmetry of the measured surface, held for good.
constexpr double kExactlyFree = 1e-8;

// Cells per direction of the grid over each measured face that tells the
// surface's own free motions from those the points leave free.
constexpr int kObservabilityGrid = 24;

// Rounds of settling the held directions and re-fitting the others.
constexpr int kSettleRounds = 20;

std::string number(double v) { return general(v, 3); }

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
  // The feet live in the result's points (their `foot`), filled from the
  // first projection on: one copy of a million feet, not two.
  std::vector<RegisteredPoint>& points;
  std::vector<OutlierReason> geometric;  // no_foot_point per projection
  // Foot on a boundary, point more than edge_tolerance beside the surface:
  // still in the fit (its bounded distance is its residual); only the
  // classification after convergence and the start's observability use it.
  std::vector<bool> beyond;
  std::vector<bool> excluded;            // left out of the fit by the outlier rule
  bool projected_once = false;

  ClosestPoint& foot(std::size_t i) { return points[i].foot; }
  const ClosestPoint& foot(std::size_t i) const { return points[i].foot; }

  // Projects every moved point (in parallel, warm-started at its last foot)
  // and hands feet and activity to the fit.
  void project() {
    const std::size_t n = fit.size();
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d x = fit.moved(i);
      ClosestPoint& f = foot(i);
      f = projected_once ? finder.project(x, f) : finder.project(x);
      const bool found = f.converged;
      const bool boundary = found && f.location != FootLocation::interior;
      geometric[i] = found ? OutlierReason::none : OutlierReason::no_foot_point;
      beyond[i] = boundary && sideways(x, f) > options.edge_tolerance;
      fit.set_foot(i, f.point, f.normal, found && !excluded[i], boundary);
    }
    projected_once = true;
  }
  // On the part in the sense of the start's analysis: a foot, not beyond an
  // edge, not excluded.
  bool on_part(std::size_t i) const {
    return geometric[i] == OutlierReason::none && !beyond[i] && !excluded[i];
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

// The held weak directions (`held`: origin motions, columns) moved so that
// the points whose foot lies on a face or trim boundary come back onto the
// bounded face: for those the whole offset from the probe-compensated foot,
// x - (f + r n), is the residual (sideways part included: it brings them
// back in proportion to how far off they are, where the fit's bounded
// distance of a ball beside the edge grows only with the square of it), for
// the others the signed deviation.
// Linear least squares in the held directions only, re-projected until no
// point moves more than `tolerance`. The held motions are those the surface
// does not see, so only the edges decide them; without this the coarse
// start alone would, and a start turned a few degrees about a plane's
// normal keeps its corner points off the face for good. Returns whether
// anything moved.
bool settle_on_faces(Workspace& ws, const MotionBasis& held, double probe_radius, double reach,
                     double tolerance) {
  const std::size_t n = ws.fit.size();
  const Eigen::Index m = held.cols();
  if (m == 0) return false;
  bool moved = false;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
    std::size_t on_edge = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const ClosestPoint& f = ws.foot(i);
      if (!f.converged || ws.excluded[i]) continue;
      const Eigen::Vector3d x = ws.fit.moved(i);
      Eigen::Matrix<double, 3, 6> d;  // displacement w x x + t of an origin motion (w, t)
      d << 0, x.z(), -x.y(), 1, 0, 0, -x.z(), 0, x.x(), 0, 1, 0, x.y(), -x.x(), 0, 0, 0, 1;
      const Eigen::Matrix<double, 3, Eigen::Dynamic> dm = d * held;
      const Eigen::Vector3d e = x - (f.point + probe_radius * f.normal);
      if (f.location == FootLocation::interior) {
        const Eigen::RowVectorXd j = f.normal.transpose() * dm;
        a += j.transpose() * j;
        b += j.transpose() * f.normal.dot(e);
      } else {
        ++on_edge;
        a += dm.transpose() * dm;
        b += dm.transpose() * e;
      }
    }
    if (on_edge == 0) break;
    const Eigen::VectorXd step = -a.completeOrthogonalDecomposition().solve(b);
    Eigen::Matrix<double, 6, 1> w = held * step;
    const Eigen::Matrix<double, 6, 1> before = ws.fit.parameters();
    // Compose: x' = exp(w) x + t_w applied after the current correction.
    const Eigen::Isometry3d after = rigid_motion(w) * rigid_motion(before);
    const Eigen::AngleAxisd aa(after.linear());
    Eigen::Matrix<double, 6, 1> p;
    p.head<3>() = aa.angle() * aa.axis();
    p.tail<3>() = after.translation();
    ws.fit.set_parameters(p);
    ws.project();
    moved = true;
    if (motion(before, p, reach) <= tolerance) break;
  }
  return moved;
}

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0 : std::sqrt(s / static_cast<double>(v.size()));
}

// The observability at the solution over the points in the fit, with the
// directions that only the points leave free told apart: a grid over every
// face that holds one of their feet is the surface they were measured on.
Observability observability_at_solution(const Part& part, const std::vector<RegisteredPoint>& points,
                                        const RegistrationOptions& options) {
  std::vector<Eigen::Vector3d> x, normal;
  // Sized exactly: growing them would double them at a million points.
  std::size_t count = 0;
  for (const RegisteredPoint& p : points) count += p.in_fit;
  x.reserve(count);
  normal.reserve(count);
  std::vector<bool> measured_face(part.faces.size(), false);
  for (const RegisteredPoint& p : points)
    if (p.in_fit) {
      x.push_back(p.registered);
      normal.push_back(p.foot.normal);
      if (p.foot.face < measured_face.size()) measured_face[p.foot.face] = true;
    }
  Observability o = analyse_observability(x, normal, free_parameter_basis(options.dof.free), options.weak_ratio);
  if (o.weak.empty()) return o;
  std::vector<Eigen::Vector3d> sx, sn;
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    if (measured_face[f])
      for (const SurfaceSample& s : sample_face_grid(part, f, kObservabilityGrid, kObservabilityGrid)) {
        sx.push_back(s.point);
        sn.push_back(s.normal);
      }
  mark_weak_by_points(o, x, normal, sx, sn);
  return o;
}

}  // namespace

RegistrationResult register_measurements(const ClosestPointFinder& finder,
                                         const MeasurementSet& set, const InspectionPlan* plan,
                                         const RegistrationOptions& options) {
  const std::size_t n = set.points.size();
  const int dof = options.dof.count();
  if (!(options.weak_ratio > 0 && options.weak_ratio < 1))
    throw InputError("the weak-direction ratio must lie in (0, 1)");
  RegistrationResult result;
  // Fewer points than free parameters: nothing to fit, and the coarse
  // search needs three. Evaluated as measured, reported as too few.
  const bool enough = static_cast<int>(n) > dof;
  auto note = [&](const std::string& what) {
    if (options.progress) options.progress(what);
  };
  note("coarse start");
  if (options.dof.all_free() && enough) {
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
  // y is handed over, not copied: the fit keeps the only copy.
  SurfaceFit fit(std::move(y), set.probe_radius, options.dof, options.loss, options.loss_scale,
                 options.max_solver_iterations);
  result.points.resize(n);
  Workspace ws{finder,
               set,
               options,
               fit,
               result.points,
               std::vector<OutlierReason>(n, OutlierReason::none),
               std::vector<bool>(n, false),
               std::vector<bool>(n, false)};

  ws.project();
  // The points on the part at the start decide which motions are weak.
  MotionBasis release(6, 0);
  MotionBasis held_basis(6, 0);  // the weak directions held (columns)
  enum class Holding { none, all, exact_only } holding = Holding::none;
  auto points_in_fit = [&](std::vector<Eigen::Vector3d>& x, std::vector<Eigen::Vector3d>& normal) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) count += ws.on_part(i);
    x.reserve(count);
    normal.reserve(count);
    for (std::size_t i = 0; i < n; ++i)
      if (ws.on_part(i)) {
        x.push_back(fit.moved(i));
        normal.push_back(ws.foot(i).normal);
      }
  };
  {
    std::vector<Eigen::Vector3d> x, normal;
    points_in_fit(x, normal);
    const MotionBasis allowed = free_parameter_basis(options.dof.free);
    const Observability start = analyse_observability(x, normal, allowed, options.weak_ratio);
    if (options.hold_weak && !start.weak.empty()) {
      fit.restrict_motion(start.constrained);
      result.held = start.weak;
      held_basis.resize(6, static_cast<Eigen::Index>(start.weak.size()));
      for (std::size_t k = 0; k < start.weak.size(); ++k)
        held_basis.col(static_cast<Eigen::Index>(k)) = start.weak[k].parameters;
      holding = Holding::all;
      // The motions the points see at all (not exact symmetries): released
      // for a last fit once the others have converged.
      release = analyse_observability(x, normal, allowed, kExactlyFree).constrained;
      if (release.cols() == start.constrained.cols()) release.resize(6, 0);
    }
  }
  int fitted = static_cast<int>(fit.motion_basis().cols());
  result.fitted_dof = fitted;
  std::string too_few;
  if (!enough)
    too_few = std::to_string(n) + " points cannot fix " + std::to_string(dof) + " degrees of freedom";
  else if (fitted == 0)
    too_few = "the points on the part fix no motion at all";
  {
    std::vector<double> d;
    for (std::size_t i = 0; i < n; ++i)
      if (ws.geometric[i] == OutlierReason::none && !ws.beyond[i]) d.push_back(fit.residual(i));
    result.rms_before = rms(d);
  }
  std::vector<OutlierReason> verdict(n, OutlierReason::none);
  OutlierVerdict numbers;
  const OutlierRule rule{options.outlier_sigma, options.outlier_floor, options.confirm_neighbours,
                         options.neighbour_radius};
  // The outlier rule on the current fit, into `verdict`; `usable` says which
  // points it judged (those with a foot point on the part).
  const auto classify = [&](std::vector<bool>& usable) {
    std::vector<Eigen::Vector3d> positions(n);
    std::vector<double> deviation(n);
    usable.assign(n, false);
    for (std::size_t i = 0; i < n; ++i) {
      // Neighbours on the surface: at the foot points, not the measured
      // points - blunders off the same side of a dense scan are closer to
      // each other than to the surface and would vouch for each other.
      positions[i] = ws.foot(i).point;
      deviation[i] = fit.residual(i);
      usable[i] = ws.geometric[i] == OutlierReason::none;
    }
    return classify_deviations(positions, deviation, usable, rule, verdict);
  };
  std::string solver_message;
  // The points the fit uses: every point with a foot that the outlier rule
  // has not excluded - edges do not take any out.
  auto active_count = [&] {
    std::size_t active = 0;
    for (std::size_t i = 0; i < n; ++i) active += ws.geometric[i] == OutlierReason::none && !ws.excluded[i];
    return active;
  };
  auto on_part_count = [&] {
    std::size_t on = 0;
    for (std::size_t i = 0; i < n; ++i) on += ws.on_part(i);
    return on;
  };
  // Outer iterations until the motion stops (result.converged), the solver
  // fails or too few points are left on the part.
  auto iterate = [&](const std::string& label) {
    result.converged = false;
    for (int outer = 1; outer <= options.max_outer_iterations; ++outer) {
      ++result.outer_iterations;
      note("fit " + label + "." + std::to_string(outer));
      const Eigen::Matrix<double, 6, 1> before = fit.parameters();
      const std::size_t active = active_count();
      result.fitted_per_iteration.push_back(static_cast<int>(active));
      if (static_cast<int>(active) <= fitted) {
        too_few = "only " + std::to_string(active) + " points have a foot on the part, too few to fit " +
                  std::to_string(fitted) + " degrees of freedom and check the rest";
        return;
      }
      result.solver_iterations += fit.solve(solver_message);
      ws.project();
      if (!solver_message.empty()) return;
      if (motion(before, fit.parameters(), reach) <= options.motion_tolerance) {
        result.converged = true;
        return;
      }
    }
  };
  for (int pass = 1; too_few.empty() && pass <= std::max(1, options.max_outlier_passes); ++pass) {
    result.outlier_passes = pass;
    iterate(std::to_string(pass));
    // Points left beyond a face edge by where the start put the held
    // directions: those directions moved to bring them back, then the
    // constrained ones re-fitted, before any point is classified.
    // Edge points stay in the constrained fit, so it can move them off
    // again: alternate until the settling moves nothing.
    for (int round = 1; round <= kSettleRounds && result.converged && too_few.empty() && solver_message.empty();
         ++round) {
      const Eigen::Matrix<double, 6, 1> before = fit.parameters();
      if (!settle_on_faces(ws, held_basis, set.probe_radius, reach, options.motion_tolerance)) break;
      if (motion(before, fit.parameters(), reach) <= options.motion_tolerance) break;
      iterate(std::to_string(pass) + " settled");
    }
    if (!options.flag_outliers || !solver_message.empty() || !too_few.empty()) break;
    std::vector<bool> usable;
    numbers = classify(usable);
    std::vector<bool> excluded(n);
    for (std::size_t i = 0; i < n; ++i)
      excluded[i] = usable[i] && verdict[i] != OutlierReason::none;
    if (excluded == ws.excluded) break;
    if (static_cast<int>(std::count(excluded.begin(), excluded.end(), false)) <= fitted) break;
    ws.excluded = excluded;
    fit.set_loss(RobustLoss::none, options.loss_scale);
    for (std::size_t i = 0; i < n; ++i)
      fit.set_foot(i, ws.foot(i).point, ws.foot(i).normal, usable[i] && !excluded[i],
                   ws.foot(i).converged && ws.foot(i).location != FootLocation::interior);
  }
  // Without outlier flagging every point stays in the fit; the points
  // beyond an edge are still classified, once, by the same rule.
  if (!options.flag_outliers && too_few.empty() && solver_message.empty()) {
    std::vector<bool> usable;
    numbers = classify(usable);
  }
  // The weak directions the points do see, released: the data decide them
  // now that every point has settled on the part. Kept only if no point
  // leaves the part and the fit converges; otherwise the held fit stands
  // (docs/registration.md "Weakly constrained directions").
  if (release.cols() > 0 && result.converged && too_few.empty() && solver_message.empty()) {
    const Eigen::Matrix<double, 6, 1> held_parameters = fit.parameters();
    const MotionBasis held_basis = fit.motion_basis();
    const std::size_t held_active = on_part_count();
    // The sum of squared residuals of the points in the fit: more freedom
    // cannot raise it at a true minimum, so a released fit that ends higher
    // has wandered (edge points pull the slides a nearly flat panel barely
    // sees) and is not kept.
    auto squares = [&] {
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (ws.geometric[i] == OutlierReason::none && !ws.excluded[i]) sum += fit.residual(i) * fit.residual(i);
      return sum;
    };
    const double held_squares = squares();
    const int held_fitted = fitted;
    const int outer_before = result.outer_iterations;
    fit.restrict_motion(release);
    fitted = static_cast<int>(release.cols());
    iterate("released");
    if (result.converged && on_part_count() >= held_active && squares() <= held_squares * (1 + 1e-9)) {
      holding = Holding::exact_only;
    } else {
      too_few.clear();
      solver_message.clear();
      fit.restrict_motion(held_basis);
      fit.set_parameters(held_parameters);
      fitted = held_fitted;
      ws.project();
      result.converged = true;
      result.outer_iterations = outer_before;
    }
  }
  result.fitted_dof = fitted;
  result.status = !too_few.empty()          ? too_few
                  : !solver_message.empty() ? "solver failed: " + solver_message
                  : result.converged        ? "converged"
                                            : "outer iteration limit reached";

  // Results per point at the final transform (the feet are there already).
  std::vector<double> in_fit;
  in_fit.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    RegisteredPoint& p = result.points[i];
    p.registered = fit.moved(i);
    p.deviation = fit.residual(i);
    // Classified once, at the final transform (docs/registration.md
    // "Points at an edge"): a point the deviation rule flags whose foot is
    // on a boundary with the point beside the surface is off the part.
    const bool flagged = options.flag_outliers ? ws.excluded[i]
                                               : ws.beyond[i] && verdict[i] != OutlierReason::none;
    p.outlier = ws.geometric[i] != OutlierReason::none ? ws.geometric[i]
                : !flagged                             ? OutlierReason::none
                : ws.beyond[i]                         ? OutlierReason::beyond_edge
                                                       : verdict[i];
    p.in_fit = ws.geometric[i] == OutlierReason::none && !ws.excluded[i];
    p.evaluated = p.outlier == OutlierReason::none || p.outlier == OutlierReason::large_deviation;
    if (p.outlier == OutlierReason::beyond_edge)
      p.outlier_detail = "foot on the " + std::string(to_string(p.foot.location)) + ", point " +
                         number(sideways(p.registered, p.foot)) + " mm beside the surface, " +
                         number(std::abs(p.deviation)) + " mm from it, |d - median| > " +
                         number(numbers.limit) + " mm";
    else if (p.outlier == OutlierReason::no_foot_point)
      p.outlier_detail = "closest-point search did not converge";
    else if (p.outlier != OutlierReason::none)
      p.outlier_detail =
          "|d - median| = " + number(std::abs(p.deviation - numbers.median)) + " mm > " +
          number(numbers.limit) + " mm (" + number(options.outlier_sigma) + " x robust sigma " +
          number(numbers.robust_sigma) + " mm, floor " + number(options.outlier_floor) + " mm)";
    if (p.in_fit) in_fit.push_back(p.deviation);
  }
  result.rms_after = rms(in_fit);
  const double redundancy = static_cast<double>(in_fit.size()) - fitted;
  result.sigma = redundancy > 0 ? rms(in_fit) * std::sqrt(in_fit.size() / redundancy) : 0;
  if (too_few.empty() && redundancy <= 0) {
    too_few = std::to_string(in_fit.size()) + " points in the fit for " + std::to_string(fitted) +
              " degrees of freedom: they fit exactly and verify nothing";
    result.status = too_few;
  }
  if (!too_few.empty()) {
    result.converged = false;
    result.outcome = FitOutcome::too_few_points;
  } else {
    result.outcome = result.converged ? FitOutcome::converged : FitOutcome::not_converged;
  }
  note("observability");
  result.observability = observability_at_solution(finder.part(), result.points, options);
  // Which of them the fit left where the coarse start put them.
  for (WeakDirection& d : result.observability.weak)
    d.held = holding == Holding::all || (holding == Holding::exact_only && d.ratio < kExactlyFree);
  for (WeakDirection& d : result.held)
    d.held = holding == Holding::all || (holding == Holding::exact_only && d.ratio < kExactlyFree);

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
