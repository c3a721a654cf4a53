#include "inspection/registration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "inspection/few_point_search.hpp"
#include "inspection/orientation_check.hpp"
#include "inspection/outlier_detection.hpp"
#include "inspection/registration_run.hpp"
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

// Cells per direction of the grid over each measured face that tells the
// surface's own free motions from those the points leave free.
constexpr int kObservabilityGrid = 24;

// Halvings of an outer step that raised the true cost (backtrack()).
constexpr int kBacktracks = 20;

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
#pragma omp parallel for schedule(dynamic, 256) if (n >= kParallelProjections)
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

// One registration, in the steps docs/registration.md describes: the coarse
// start, the fit with the weak directions held and the points settled on
// their faces, the outlier passes, the weak directions the points do see
// released, then the points classified and the uncertainty. The members are
// what the steps hand on to each other.
class RegistrationRun {
 public:
  // `left_out`: registration_run.hpp.
  RegistrationRun(const ClosestPointFinder& finder, const MeasurementSet& set, const InspectionPlan* plan,
                  const RegistrationOptions& options, std::size_t left_out = kNoPointLeftOut)
      : finder_(finder), set_(set), plan_(plan), options_(options), n_(set.points.size()),
        rule_{options.outlier_sigma, options.outlier_floor, options.confirm_neighbours, options.neighbour_radius},
        verdict_(set.points.size(), OutlierReason::none), left_out_(left_out) {}
  RegistrationRun(const RegistrationRun&) = delete;
  RegistrationRun& operator=(const RegistrationRun&) = delete;

  RegistrationResult run() {
    coarse_start();
    set_up_fit();
    hold_weak_directions();
    judge_start();
    fit_with_outlier_passes();
    // Without outlier flagging every point stays in the fit; the points
    // beyond an edge are still classified, once, by the same rule.
    if (!options_.flag_outliers && fine()) {
      std::vector<bool> usable;
      numbers_ = classify(usable);
    }
    release_weak_directions();
    result_.fitted_dof = fitted_;
    result_.status = !too_few_.empty()          ? too_few_
                     : !solver_message_.empty() ? "solver failed: " + solver_message_
                     : result_.converged        ? "converged"
                                                : "outer iteration limit reached";
    evaluate_points();
    judge_outcome();
    note("observability");
    result_.observability = observability_at_solution(finder_.part(), result_.points, options_);
    // Which of them the fit left where the coarse start put them.
    for (WeakDirection& d : result_.observability.weak) d.held = held(d);
    for (WeakDirection& d : result_.held) d.held = held(d);
    transform_and_uncertainty();
    return std::move(result_);
  }

 private:
  enum class Holding { none, all, exact_only };

  void note(const std::string& what) const {
    if (options_.progress) options_.progress(what);
  }
  bool fine() const { return too_few_.empty() && solver_message_.empty(); }
  bool held(const WeakDirection& d) const {
    return holding_ == Holding::all || (holding_ == Holding::exact_only && d.ratio < kUnseenRatio);
  }

  // Fewer points than free parameters: nothing to fit, and the coarse
  // search needs three. Evaluated as measured, reported as too few.
  bool enough() const { return static_cast<int>(n_) > options_.dof.count(); }

  void coarse_start() {
    note("coarse start");
    if (options_.start) {
      result_.coarse.method = CoarseMethod::frame;
      result_.coarse.transform = *options_.start;
      result_.coarse.median_distance =
          median_surface_distance(finder_, set_, *options_.start, options_.coarse.refine_points);
    } else if (options_.dof.all_free() && enough()) {
      result_.coarse = coarse_alignment(finder_, set_, plan_, options_.coarse);
    } else {
      result_.coarse.method = CoarseMethod::identity;
      result_.coarse.median_distance = median_surface_distance(finder_, set_, Eigen::Isometry3d::Identity(),
                                                               options_.coarse.refine_points);
    }
  }

  void set_up_fit() {
    note("fit setup");
    std::vector<Eigen::Vector3d> y(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      y[i] = result_.coarse.transform * set_.points[i].xyz;
      reach_ = std::max(reach_, y[i].norm());
    }
    // y is handed over, not copied: the fit keeps the only copy.
    fit_ = std::make_unique<SurfaceFit>(std::move(y), set_.probe_radius, options_.dof, options_.loss,
                                        options_.loss_scale, options_.max_solver_iterations);
    for (std::size_t i = 0; i < n_; ++i)
      if (set_.points[i].weight != 1) {
        fit_->set_weight(i, set_.points[i].weight);
        weighted_ = true;
      }
    result_.points.resize(n_);
    ws_.reset(new Workspace{finder_, set_, options_, *fit_, result_.points,
                            std::vector<OutlierReason>(n_, OutlierReason::none), std::vector<bool>(n_, false),
                            std::vector<bool>(n_, false)});
    if (left_out_ < n_) ws_->excluded[left_out_] = true;
    ws_->project();
  }

  // The points on the part at the start decide which motions are weak; with
  // hold_weak those are held, and the ones the points see at all are kept
  // for release once the others have converged.
  void hold_weak_directions() {
    const Observability start = observability_on_part(options_.weak_ratio);
    if (options_.hold_weak && !start.weak.empty()) {
      fit_->restrict_motion(start.constrained, weak_frame());
      result_.held = start.weak;
      held_basis_.resize(6, static_cast<Eigen::Index>(start.weak.size()));
      for (std::size_t k = 0; k < start.weak.size(); ++k)
        held_basis_.col(static_cast<Eigen::Index>(k)) = start.weak[k].parameters;
      holding_ = Holding::all;
    }
  }

  // The weak directions are motions of the points where they are now
  // (motion_manifold.hpp "twist"); with degrees of freedom locked they are
  // combinations of the free parameters, and stay changes of them.
  MotionFrame weak_frame() const {
    return options_.dof.all_free() ? MotionFrame::twist : MotionFrame::parameters;
  }

  // The motions of the points on the part, at their current feet, split at
  // `ratio` (observability.hpp).
  Observability observability_on_part(double ratio) const {
    std::vector<Eigen::Vector3d> x, normal;
    const std::size_t count = on_part_count();
    x.reserve(count);
    normal.reserve(count);
    for (std::size_t i = 0; i < n_; ++i)
      if (ws_->on_part(i)) {
        x.push_back(fit_->moved(i));
        normal.push_back(ws_->foot(i).normal);
      }
    return analyse_observability(x, normal, free_parameter_basis(options_.dof.free), ratio);
  }

  // Too few points or motions fixed; the residuals at the start.
  void judge_start() {
    fitted_ = static_cast<int>(fit_->motion_basis().cols());
    result_.fitted_dof = fitted_;
    if (!enough())
      too_few_ = std::to_string(n_) + " points cannot fix " + std::to_string(options_.dof.count()) +
                 " degrees of freedom";
    else if (fitted_ == 0)
      too_few_ = "the points on the part fix no motion at all";
    std::vector<double> d;
    for (std::size_t i = 0; i < n_; ++i)
      if (ws_->geometric[i] == OutlierReason::none && !ws_->beyond[i]) d.push_back(fit_->residual(i));
    result_.rms_before = rms(d);
  }

  // The outlier rule on the current fit, into verdict_; `usable` says which
  // points it judged (those with a foot point on the part).
  OutlierVerdict classify(std::vector<bool>& usable) {
    std::vector<Eigen::Vector3d> positions(n_);
    std::vector<double> deviation(n_);
    usable.assign(n_, false);
    for (std::size_t i = 0; i < n_; ++i) {
      // Neighbours on the surface: at the foot points, not the measured
      // points - blunders off the same side of a dense scan are closer to
      // each other than to the surface and would vouch for each other.
      positions[i] = ws_->foot(i).point;
      deviation[i] = fit_->residual(i);
      usable[i] = ws_->geometric[i] == OutlierReason::none;
    }
    return classify_deviations(positions, deviation, usable, rule_, verdict_);
  }

  // The points the fit uses: every point with a foot that the outlier rule
  // has not excluded - edges do not take any out.
  std::size_t active_count() const {
    std::size_t active = 0;
    for (std::size_t i = 0; i < n_; ++i) active += ws_->geometric[i] == OutlierReason::none && !ws_->excluded[i];
    return active;
  }
  std::size_t on_part_count() const {
    std::size_t on = 0;
    for (std::size_t i = 0; i < n_; ++i) on += ws_->on_part(i);
    return on;
  }

  // Outer iterations until the motion stops (result_.converged), the solver
  // fails or too few points are left on the part.
  void iterate(const std::string& label) {
    result_.converged = false;
    for (int outer = 1; outer <= options_.max_outer_iterations; ++outer) {
      ++result_.outer_iterations;
      note("fit " + label + "." + std::to_string(outer));
      const Eigen::Matrix<double, 6, 1> before = fit_->parameters();
      const std::size_t active = active_count();
      result_.fitted_per_iteration.push_back(static_cast<int>(active));
      if (static_cast<int>(active) <= fitted_) {
        too_few_ = "only " + std::to_string(active) + " points have a foot on the part, too few to fit " +
                   std::to_string(fitted_) + " degrees of freedom and check the rest";
        return;
      }
      const double cost_before = fit_->cost();
      result_.solver_iterations += fit_->solve(solver_message_);
      ws_->project();
      if (!solver_message_.empty()) return;
      backtrack(before, cost_before);
      if (motion(before, fit_->parameters(), reach_) <= options_.motion_tolerance) {
        result_.converged = true;
        return;
      }
    }
  }

  // The solve minimised the cost with the feet held; re-projected, the true
  // cost can be higher - with few points the tangent planes let a step run
  // far along a motion they barely see, and the next solve runs back: an
  // outer loop that alternated between two placements 5 mm apart for good.
  // So the step is halved, re-projected each time, until the true cost is
  // no higher than before it (up to round-off), at most kBacktracks times;
  // then it is taken back whole (nothing moved: the outer loop stops).
  void backtrack(const Eigen::Matrix<double, 6, 1>& before, double cost_before) {
    const double allowed = cost_before * (1 + 1e-12) + 1e-30;
    if (!(fit_->cost() > allowed)) return;
    const Eigen::Matrix<double, 6, 1> after = fit_->parameters();
    double t = 1;
    for (int k = 0; k < kBacktracks; ++k) {
      t /= 2;
      fit_->set_parameters(fit_->between(before, after, t));
      ws_->project();
      if (!(fit_->cost() > allowed)) return;
    }
    fit_->set_parameters(before);
    ws_->project();
  }

  void fit_with_outlier_passes() {
    for (int pass = 1; too_few_.empty() && pass <= std::max(1, options_.max_outlier_passes); ++pass) {
      result_.outlier_passes = pass;
      iterate(std::to_string(pass));
      // Points left beyond a face edge by where the start put the held
      // directions: those directions moved to bring them back, then the
      // constrained ones re-fitted, before any point is classified.
      // Edge points stay in the constrained fit, so it can move them off
      // again: alternate until the settling moves nothing.
      for (int round = 1; round <= kSettleRounds && result_.converged && fine(); ++round) {
        const Eigen::Matrix<double, 6, 1> before = fit_->parameters();
        if (!settle_on_faces(*ws_, held_basis_, set_.probe_radius, reach_, options_.motion_tolerance)) break;
        if (motion(before, fit_->parameters(), reach_) <= options_.motion_tolerance) break;
        iterate(std::to_string(pass) + " settled");
      }
      if (!options_.flag_outliers || !fine() || !reclassify()) break;
    }
  }

  // The outlier rule on the converged fit; true when it changed which
  // points are left out (they are then, and the rest re-fitted by plain
  // least squares), false when it leaves them as they are - or would leave
  // too few to check anything.
  bool reclassify() {
    std::vector<bool> usable;
    numbers_ = classify(usable);
    std::vector<bool> excluded(n_);
    for (std::size_t i = 0; i < n_; ++i) excluded[i] = usable[i] && verdict_[i] != OutlierReason::none;
    if (excluded == ws_->excluded) return false;
    if (static_cast<int>(std::count(excluded.begin(), excluded.end(), false)) <= fitted_) return false;
    ws_->excluded = excluded;
    fit_->set_loss(RobustLoss::none, options_.loss_scale);
    for (std::size_t i = 0; i < n_; ++i)
      fit_->set_foot(i, ws_->foot(i).point, ws_->foot(i).normal, usable[i] && !excluded[i],
                     ws_->foot(i).converged && ws_->foot(i).location != FootLocation::interior);
    return true;
  }

  // The weak directions the points do see, released: the data decide them
  // now that every point has settled on the part. Kept only if no point
  // leaves the part and the fit converges; otherwise the held fit stands
  // (docs/registration.md "Weakly constrained directions").
  void release_weak_directions() {
    if (holding_ != Holding::all || !result_.converged || !fine()) return;
    // Which motions are exactly free is decided where the points have
    // settled: at the start, off the surface by the misplacement, an exact
    // symmetry (the turn about a bore's axis) comes out mixed with motions
    // the points do see, and holding that mixture would keep part of them
    // from the fit.
    const MotionBasis release = observability_on_part(kUnseenRatio).constrained;
    if (release.cols() == fit_->motion_basis().cols()) return;
    const Eigen::Matrix<double, 6, 1> held_parameters = fit_->parameters();
    const MotionBasis held_motion = fit_->motion_basis();
    const MotionFrame held_frame = fit_->motion_frame();
    const std::size_t held_active = on_part_count();
    // The sum of squared residuals of the points in the fit: more freedom
    // cannot raise it at a true minimum, so a released fit that ends higher
    // has wandered (edge points pull the slides a nearly flat panel barely
    // sees) and is not kept.
    auto squares = [&] {
      double sum = 0;
      for (std::size_t i = 0; i < n_; ++i)
        if (ws_->geometric[i] == OutlierReason::none && !ws_->excluded[i]) {
          const double r = fit_->weight(i) * fit_->residual(i);  // the weighted problem's
          sum += r * r;
        }
      return sum;
    };
    const double held_squares = squares();
    const int held_fitted = fitted_;
    const int outer_before = result_.outer_iterations;
    fit_->restrict_motion(release, weak_frame());
    fitted_ = static_cast<int>(release.cols());
    iterate("released");
    if (result_.converged && on_part_count() >= held_active && squares() <= held_squares * (1 + 1e-9)) {
      holding_ = Holding::exact_only;
      // The released fit moved: its points are classified again, as the
      // held fit's were. A point the held fit absorbed (few points: a
      // blunder spread over the rest) can stand out only now, and would
      // otherwise stay in the fit unflagged, whatever its residual.
      for (int pass = 1; options_.flag_outliers && pass <= options_.max_outlier_passes; ++pass) {
        if (!reclassify()) break;
        ++result_.outlier_passes;
        iterate("released." + std::to_string(pass));
        if (!result_.converged || !fine()) break;
      }
      return;
    }
    too_few_.clear();
    solver_message_.clear();
    fit_->restrict_motion(held_motion, held_frame);
    fit_->set_parameters(held_parameters);
    fitted_ = held_fitted;
    ws_->project();
    result_.converged = true;
    result_.outer_iterations = outer_before;
  }

  // Results per point at the final transform (the feet are there already).
  void evaluate_points() {
    in_fit_.reserve(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      RegisteredPoint& p = result_.points[i];
      p.registered = fit_->moved(i);
      p.deviation = fit_->residual(i);
      // Classified once, at the final transform (docs/registration.md
      // "Points at an edge"): a point the deviation rule flags whose foot is
      // on a boundary with the point beside the surface is off the part.
      const bool flagged = options_.flag_outliers ? ws_->excluded[i]
                                                  : ws_->beyond[i] && verdict_[i] != OutlierReason::none;
      p.outlier = ws_->geometric[i] != OutlierReason::none ? ws_->geometric[i]
                  : !flagged                               ? OutlierReason::none
                  : ws_->beyond[i]                         ? OutlierReason::beyond_edge
                                                           : verdict_[i];
      p.in_fit = ws_->geometric[i] == OutlierReason::none && !ws_->excluded[i];
      p.evaluated = p.outlier == OutlierReason::none || p.outlier == OutlierReason::large_deviation;
      p.outlier_detail = outlier_detail(p);
      if (p.in_fit) {
        in_fit_.push_back(p.deviation);
        weighted_squares_ += (fit_->weight(i) * p.deviation) * (fit_->weight(i) * p.deviation);
      }
    }
  }

  std::string outlier_detail(const RegisteredPoint& p) const {
    if (p.outlier == OutlierReason::beyond_edge)
      return "foot on the " + std::string(to_string(p.foot.location)) + ", point " +
             number(sideways(p.registered, p.foot)) + " mm beside the surface, " + number(std::abs(p.deviation)) +
             " mm from it, |d - median| > " + number(numbers_.limit) + " mm";
    if (p.outlier == OutlierReason::no_foot_point) return "closest-point search did not converge";
    if (p.outlier != OutlierReason::none)
      return "|d - median| = " + number(std::abs(p.deviation - numbers_.median)) + " mm > " +
             number(numbers_.limit) + " mm (" + number(options_.outlier_sigma) + " x robust sigma " +
             number(numbers_.robust_sigma) + " mm, floor " + number(options_.outlier_floor) + " mm)";
    return "";
  }

  // The spread of the points in the fit and what the fit can claim.
  void judge_outcome() {
    result_.rms_after = rms(in_fit_);
    const double redundancy = static_cast<double>(in_fit_.size()) - fitted_;
    result_.sigma = redundancy > 0 ? rms(in_fit_) * std::sqrt(in_fit_.size() / redundancy) : 0;
    // Weighted points: the covariance scales by the variance of unit weight,
    // sum (w d)^2 / (n - dof), the weighted least squares' estimate.
    unit_sigma_ = !weighted_ ? result_.sigma : redundancy > 0 ? std::sqrt(weighted_squares_ / redundancy) : 0;
    if (too_few_.empty() && redundancy <= 0) {
      too_few_ = std::to_string(in_fit_.size()) + " points in the fit for " + std::to_string(fitted_) +
                 " degrees of freedom: they fit exactly and verify nothing";
      result_.status = too_few_;
    }
    if (!too_few_.empty()) {
      result_.converged = false;
      result_.outcome = FitOutcome::too_few_points;
    } else {
      result_.outcome = result_.converged ? FitOutcome::converged : FitOutcome::not_converged;
    }
  }

  void transform_and_uncertainty() {
    result_.parameters = fit_->parameters();
    result_.transform = rigid_motion(fit_->parameters()) * result_.coarse.transform;
    // With all six DOF free, the covariance is that of a small correction on
    // the final transform: re-base the points on it first.
    if (options_.dof.all_free()) fit_->rebase();
    result_.covariance_status = "not computed";
    note("covariance");
    if (!options_.compute_covariance) return;
    if (auto c = fit_->covariance(result_.covariance_status)) {
      result_.covariance = (*c) * (unit_sigma_ * unit_sigma_);
      for (std::size_t i = 0; i < n_; ++i) {
        RegisteredPoint& p = result_.points[i];
        const Eigen::Matrix<double, 1, 6> j = fit_->jacobian(i);
        p.uncertainty = std::sqrt(std::max(0.0, (j * (*result_.covariance) * j.transpose())(0)));
        // Leverage h = w J C J^T: a deviation delta at the point moves the
        // fit so that its own d changes by (1 - h) delta (docs/registration.md
        // "Points the fit cannot check"). One that is not a number checks
        // nothing: 0.
        if (!p.in_fit) continue;
        const double leverage = fit_->loss_weight(i) * (j * (*c) * j.transpose())(0);
        p.redundancy = std::isfinite(leverage) ? std::clamp(1 - leverage, 0.0, 1.0) : 0.0;
      }
    }
  }

  const ClosestPointFinder& finder_;
  const MeasurementSet& set_;
  const InspectionPlan* plan_;
  const RegistrationOptions& options_;
  const std::size_t n_;
  const OutlierRule rule_;
  RegistrationResult result_;
  std::unique_ptr<SurfaceFit> fit_;
  std::unique_ptr<Workspace> ws_;  // refers to *fit_ and result_.points
  double reach_ = 0;               // largest |point| after the coarse start [mm]
  MotionBasis held_basis_{6, 0};   // the weak directions held (columns)
  Holding holding_ = Holding::none;
  int fitted_ = 0;
  std::string too_few_, solver_message_;
  std::vector<OutlierReason> verdict_;
  OutlierVerdict numbers_;
  std::vector<double> in_fit_;
  bool weighted_ = false;         // some point's weight is not 1 (MeasuredPoint::weight)
  double weighted_squares_ = 0;   // sum (w d)^2 over the points in the fit
  double unit_sigma_ = 0;         // what the covariance is scaled by
  std::size_t left_out_;
};

}  // namespace

RegistrationResult run_registration(const ClosestPointFinder& finder, const MeasurementSet& set,
                                    const InspectionPlan* plan, const RegistrationOptions& options,
                                    std::size_t left_out) {
  return RegistrationRun(finder, set, plan, options, left_out).run();
}

RegistrationResult register_measurements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                         const InspectionPlan* plan, const RegistrationOptions& options) {
  if (!(options.weak_ratio > 0 && options.weak_ratio < 1))
    throw InputError("the weak-direction ratio must lie in (0, 1)");
  for (const MeasuredPoint& p : set.points)
    if (!(std::isfinite(p.weight) && p.weight > 0))
      throw InputError(set.source + ": point " + p.id + " has weight " + general(p.weight) +
                       "; a weight must be positive and finite");
  RegistrationResult first = run_registration(finder, set, plan, options);
  if (!options.multi_start_few || set.points.size() >= options.coarse.few_points)
    return settle_orientation(std::move(first), finder, set, plan, options);
  return search_few_points(std::move(first), finder, set, plan, options);
}

}  // namespace furrow
