#pragma once
// Registration of measured CMM points to the nominal part: the rigid
// transform T (CMM frame -> part frame) minimising the robust sum of signed
// point-to-surface distances, with probe compensation, outlier flagging and
// the transform's covariance (docs/architecture.md "Inspection").
//
// Model. Point i (CMM) is moved to x_i = R(r) y_i + t with y_i = T0 p_i, T0
// the coarse start (coarse_alignment.hpp; the identity for constrained DOF,
// see degrees_of_freedom.hpp), r a rotation vector about the part origin and
// t a translation: the six parameters (rx, ry, rz, tx, ty, tz). The residual
// is the signed deviation
//     d_i = n_i . (x_i - f_i) - r_probe          (foot inside a face)
//     d_i = s_i |x_i - f_i| - r_probe            (foot on a face/trim boundary)
// with f_i the closest point of x_i on the part (trims respected), n_i the
// outward normal there and s_i = +-1 the side of its tangent plane
// (r_probe = 0 for contact points): probe compensation along the nominal
// normal, re-evaluated with every foot point. On a boundary it is the probe
// centre's true distance to the bounded surface less the radius (the gap
// between ball and part: a ball touching a face's rim has d = 0); the two
// agree where a foot crosses the boundary (docs/registration.md "Points at
// an edge").
//
// Weights: a point's MeasuredPoint::weight w_i multiplies its residual in
// the fit (sum rho((w_i d_i)^2)); 1 for every probe point, cos(incidence)
// for a scan's (docs/scan.md "Weights"). Deviations, outlier rules and
// `sigma` are of d_i itself; the covariance is the weighted fit's, scaled by
// the variance of unit weight sum (w d)^2 / (n - dof).
//
// Solution (defended in docs/registration.md): foot points are re-projected
// globally (closest_point.hpp) in every outer iteration and held fixed while
// Ceres minimises sum rho(d_i^2) over the parameters (point-to-tangent-plane,
// analytic derivatives by autodiff). At the fixed point of this loop the
// gradient is exactly that of the true point-to-surface problem (the foot
// point moves tangentially, to first order it does not change d_i), so the
// answer is the true robust minimum - without (u,v) unknowns per point, and
// with face changes and trim boundaries handled by the projection.
//
// Robustness: a Cauchy (default) or Huber loss with a scale from the
// tolerance carries the first fit, every point with a foot in it (edge
// points too: a projection never drops a point); then outliers are flagged
// and excluded and the fit repeated, by plain least squares on the remaining
// points (the Gaussian best fit a CMM reports, and the estimator whose
// covariance is meaningful), until the flagged set is stable. Outliers,
// classified after each converged pass at its final position:
//   beyond_edge        flagged by the deviation rule below, with its foot on a
//                      face or trim boundary and the point more than
//                      edge_tolerance beside the surface: off the part;
//   no_foot_point      the projection did not converge;
//   blunder            |d - median d| > max(outlier_sigma * robust sigma,
//                      outlier_floor), and its neighbours do not agree;
//   large_deviation    the same size, but neighbours deviate alike (see
//                      outlier_detection.hpp): a real form error (a gouge)
//                      - left out of the fit, yet evaluated against the
//                      tolerance, never hidden.
//
// Uncertainty: the 6x6 covariance of the parameters at the optimum,
// (J^T J)^-1 from the Jacobian's SVD as ceres::Covariance computes it but
// without holding J (surface_fit.hpp), scaled by the residual variance of
// the points in the fit (sum d^2 / (n - dof)); with all six DOF free the
// parameters are re-based on the final transform first, so it is the
// covariance of a small rigid correction applied in the part frame
// (rotation about the part origin). Each point's 1-sigma deviation
// uncertainty is sqrt(J C J^T) with J = d(d_i)/d(parameters): how much the
// alignment alone could move it.
//
// Weakly constrained directions (observability.hpp): after the coarse start
// the motions that the points on the part barely see (lambda below
// weak_ratio of the largest) are held where the start put them, so the fit
// moves only along the others - the same fit as with those directions locked
// by hand, and it cannot slide the part off the measured surface through
// them. Points the start left beyond a face edge move the held directions
// (and only them) back onto the face after each fit pass, weighted by the
// robust loss. At the solution the analysis is repeated over the points in the fit
// and reported; a direction weak only because of where the points are (a
// grid over the measured faces would fix it) is `from_points`, which makes
// the comparison's alignment weakly constrained (comparison.hpp).
//
// Failure is reported, never thrown: converged == false with `outcome` and
// `status` saying why - the outer loop's cap, the solver, or too few points
// on the part to fit what is free (no redundancy left: nothing verified).
// The per-point results are still filled at the last transform.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "inspection/coarse_alignment.hpp"
#include "inspection/degrees_of_freedom.hpp"
#include "inspection/observability.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/plan_file.hpp"

namespace furrow {

enum class RobustLoss { none, huber, cauchy };
const char* to_string(RobustLoss loss);
RobustLoss parse_robust_loss(const std::string& text, const std::string& where);

enum class OutlierReason { none, beyond_edge, no_foot_point, blunder, large_deviation };
const char* to_string(OutlierReason reason);

enum class FitOutcome { converged, not_converged, too_few_points };
const char* to_string(FitOutcome outcome);  // "converged", "not_converged", "too_few_points"

struct RegistrationOptions {
  DegreesOfFreedom dof;
  // Directions whose share of displacement along the normals is below this
  // times the largest are weak (observability.hpp); held when hold_weak.
  double weak_ratio = 1e-3;
  bool hold_weak = true;
  RobustLoss loss = RobustLoss::cauchy;
  double loss_scale = 0.025;        // [mm] (the CLI uses half the tolerance)
  int max_outer_iterations = 50;    // re-projections of all points
  int max_solver_iterations = 5;    // Ceres iterations per outer iteration
  double motion_tolerance = 1e-10;  // [mm] stop when no point moves more than this
  double outlier_sigma = 5;         // robust sigmas for a large residual
  double outlier_floor = 0.025;     // [mm] smallest |d - median| called large
  double edge_tolerance = 0.05;     // [mm] sideways offset that makes a flagged edge point beyond_edge
  int confirm_neighbours = 3;       // agreeing neighbours (of 6) that make a large deviation real
  double neighbour_radius = 10;     // [mm]
  int max_outlier_passes = 4;       // fit / flag rounds
  bool flag_outliers = true;        // false: every point stays in the fit
  bool compute_covariance = true;
  CoarseOptions coarse;
  // A start already known, CMM -> part (the frame of a datum or RPS
  // alignment, when its best fit is computed beside it): used instead of the
  // coarse search; none: coarse_alignment.
  //
  // Few points (fewer than coarse.few_points): the fit is run again from
  // other starts and the one that explains the points best is kept, and
  // outliers the points cannot tell apart are reported
  // (few_point_search.hpp). More points: a search that called its
  // placement ambiguous is checked by a fit from its runner-up
  // (orientation_check.hpp).
  bool multi_start_few = true;
  std::optional<Eigen::Isometry3d> start;
  // Called with a short note at each stage ("coarse start", "fit 1.3", ...)
  // so a terminal can show progress; empty: silent.
  std::function<void(const std::string&)> progress;
};

struct RegisteredPoint {
  Eigen::Vector3d registered = Eigen::Vector3d::Zero();  // T p, part frame [mm]
  ClosestPoint foot;                                     // of `registered`
  double deviation = 0;    // d (above; bounded distance on a boundary) [mm]; + material left, - removed
  double uncertainty = 0;  // 1-sigma of d from the transform's covariance [mm]
  // The share of a deviation at this point that stays in its d: 1 - its
  // leverage in the fit (below). 1 for a point not in the fit, and where
  // the covariance was not computed.
  double redundancy = 1;
  OutlierReason outlier = OutlierReason::none;
  std::string outlier_detail;  // numbers behind the decision
  bool in_fit = true;          // took part in the final fit
  bool evaluated = true;       // counts for the tolerance (false for blunders, beyond_edge, no foot)
};

// The fit of another orientation that explains the points about as well
// as the result's (orientation_check.hpp): its transform and, per point,
// its deviation where it evaluated the point.
struct OtherOrientation {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // CMM -> part
  std::vector<std::optional<double>> deviation;                  // [mm], same order as the points
};

struct RegistrationResult {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();                   // CMM -> part
  Eigen::Matrix<double, 6, 1> parameters = Eigen::Matrix<double, 6, 1>::Zero();  // last correction
  CoarseResult coarse;
  double rms_before = 0;  // RMS deviation of the points at the coarse start [mm]
  double rms_after = 0;   // RMS deviation of the points in the final fit [mm]
  double sigma = 0;       // residual standard deviation sqrt(sum d^2 / (n - dof)) [mm]
  int outer_iterations = 0;
  int solver_iterations = 0;
  int outlier_passes = 0;
  // Points in the fit at each outer iteration, in order: edges never take
  // one out; it falls only between outlier passes, by the flagged points.
  std::vector<int> fitted_per_iteration;
  bool converged = false;
  FitOutcome outcome = FitOutcome::not_converged;
  std::string status;                                     // "converged" or why not
  std::vector<WeakDirection> held;  // weak at the start, held there (not fitted)
  Observability observability;      // at the solution, over the points in the fit
  int fitted_dof = 0;               // motions fitted (free DOF less the held ones)
  std::optional<Eigen::Matrix<double, 6, 6>> covariance;  // rx ry rz [rad], tx ty tz [mm]
  std::string covariance_status;        // "ok", "not computed", or why it is missing
  std::vector<RegisteredPoint> points;  // same order as the measurement set
  // Few points: indices of points that another fit, as good, flags where
  // this one keeps them or keeps where this one flags them - which are the
  // blunders the points cannot tell (few_point_search.hpp). Sorted.
  std::vector<std::size_t> ambiguous_outliers;
  // The other orientation's fit, when fits decided coarse.ambiguous
  // (orientation_check.hpp); empty when not ambiguous, and when no fit
  // checked the search's call (the first did not converge).
  std::optional<OtherOrientation> other_orientation;
  std::size_t in_fit_count() const;
};

// `plan` may be null. Throws InputError only for invalid options and a weight
// that is not positive and finite.
RegistrationResult register_measurements(const ClosestPointFinder& finder,
                                         const MeasurementSet& set, const InspectionPlan* plan,
                                         const RegistrationOptions& options);

}  // namespace furrow
