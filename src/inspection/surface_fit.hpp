#pragma once
// The inner problem of registration.hpp: with every point's foot point and
// normal held fixed, find the rigid correction (r, t) minimising
// sum rho(d_i^2) with Ceres, some of the six parameters possibly locked; and
// the covariance of (r, t) at the optimum, (J^T J)^-1 as ceres::Covariance's
// dense SVD gives it, from a QR factorisation folded row block by row block
// so that the Jacobian of a million points is never held whole.
//
// The residual d_i, with e_i = R(r) y_i + t - f_i the probe centre's offset
// from its foot (docs/registration.md "Points at an edge"):
//   foot inside a face:            d_i = n_i . e_i - r_probe
//                                  (point to tangent plane)
//   foot on a face/trim boundary:  d_i = s_i |e_i| - r_probe
//                                  (the centre's true distance to the
//                                  bounded surface less the radius: the gap
//                                  between ball and face; s_i = +-1 the side
//                                  of the tangent plane at the last set_foot)
// Both agree where a foot crosses the boundary (e_i is along n_i there), and
// at a fixed point of the re-projection their gradient is that of the true
// bounded distance (the foot moves along the face or the edge curve, to
// first order perpendicular to e_i). The sign flips, and d_i jumps by
// 2 r_probe, only for a centre in the tangent plane beside the edge.
//
// Each point may carry a weight w_i (1 unless set_weight): the solver sees
// w_i d_i, so the fit minimises sum rho((w_i d_i)^2); residual(), direction()
// and jacobian() stay those of d_i itself (the deviation and its
// uncertainty), cost(), loss_weight() and covariance() are the weighted
// problem's.
//
// One Ceres problem lives for the whole registration: the residual blocks
// read the feet from this object, so the outer loop only updates them
// (set_foot) and solves again, warm-started. Points left out of the fit keep
// their block and contribute zero (active = false).
//
// Ceres runs single-threaded: its multi-threaded cost reduction sums in a
// scheduling-dependent order, and Furrow's outputs must be bit-identical run
// to run. The expensive part (projection) is parallel in the caller.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inspection/degrees_of_freedom.hpp"
#include "inspection/motion_manifold.hpp"
#include "inspection/observability.hpp"

namespace furrow {

enum class RobustLoss;

class SurfaceFit {
 public:
  struct Point {
    Eigen::Vector3d y = Eigen::Vector3d::Zero();  // point before the correction
    Eigen::Vector3d foot = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    bool active = false;
    bool boundary = false;  // foot on a face or trim boundary: d = sign |e|
    double sign = 1;        // side of the tangent plane (boundary feet)
    double weight = 1;      // w_i: the solver's residual is w_i d_i
  };

  SurfaceFit(std::vector<Eigen::Vector3d> y, double probe_radius, const DegreesOfFreedom& dof,
             RobustLoss loss, double loss_scale, int max_iterations);
  ~SurfaceFit();
  SurfaceFit(const SurfaceFit&) = delete;
  SurfaceFit& operator=(const SurfaceFit&) = delete;

  std::size_t size() const { return points_.size(); }
  const Eigen::Matrix<double, 6, 1>& parameters() const { return parameters_; }
  // Back to an earlier solution (a trial fit that was not kept).
  void set_parameters(const Eigen::Matrix<double, 6, 1>& p) { parameters_ = p; }
  // R(r) y_i + t with the current parameters.
  Eigen::Vector3d moved(std::size_t i) const;
  // `boundary`: the foot lies on a face or trim boundary (the residual is
  // then the distance to the compensated foot, see above).
  void set_foot(std::size_t i, const Eigen::Vector3d& foot, const Eigen::Vector3d& normal,
                bool active, bool boundary = false);
  // The weight of point i's residual in the fit (positive, finite; 1 by default).
  void set_weight(std::size_t i, double weight) { points_[i].weight = weight; }
  double weight(std::size_t i) const { return points_[i].weight; }
  // Signed residual d_i of point i (active or not) [mm], unweighted.
  double residual(std::size_t i) const;
  // Unit gradient of d_i with respect to the moved point: n_i inside a face,
  // s_i e_i / |e_i| on a boundary.
  Eigen::Vector3d direction(std::size_t i) const;
  // d(residual_i) / d(rx, ry, rz, tx, ty, tz) at the current parameters,
  // projected onto the allowed motions (zero in locked components).
  Eigen::Matrix<double, 1, 6> jacobian(std::size_t i) const;

  // Restricts the correction to the motions span(basis) from now on (the
  // columns: rx ry rz tx ty tz; a subset of the free degrees of freedom's
  // span), in the sense `frame` (motion_manifold.hpp): changes of the
  // parameters (locked degrees of freedom) or motions of the corrected
  // points about the part origin (the weak directions of registration.hpp,
  // found at the current correction). The motions left out stay where they
  // are.
  void restrict_motion(const MotionBasis& basis, MotionFrame frame = MotionFrame::parameters);
  const MotionBasis& motion_basis() const { return basis_; }
  MotionFrame motion_frame() const { return frame_; }

  // Replaces the robust loss (the outlier-free final fit is plain least
  // squares, see registration.hpp).
  void set_loss(RobustLoss loss, double loss_scale);

  // Half the sum over the active points of the loss of their residuals, as
  // Ceres counts cost: with feet just projected, the true distances' cost.
  double cost() const;
  // The parameters a share `t` of the way from `from` to `to` along the
  // allowed motions (a straight line in the parameters, or the twist
  // scaled, motion_manifold.hpp).
  Eigen::Matrix<double, 6, 1> between(const Eigen::Matrix<double, 6, 1>& from,
                                      const Eigen::Matrix<double, 6, 1>& to, double t) const;

  // Solves from the current parameters; returns the Ceres iterations used.
  // `message` receives Ceres' termination text when it is not a success.
  int solve(std::string& message);

  // Moves every y_i by the current correction and zeroes the parameters, so
  // that the covariance is that of a small correction on the final transform.
  void rebase();

  // (J^T J)^-1 of the active residuals at the current parameters (unit
  // residual variance; the caller scales), J as the solver sees it: loss
  // corrected, in the allowed motions' tangent space, lifted back to the
  // six parameters (zero rows and columns outside span(basis)). nullopt
  // with `status` saying why (rank deficiency: the surface does not fix
  // every free parameter, or a singular value below 1e-7 of the largest).
  std::optional<Eigen::Matrix<double, 6, 6>> covariance(std::string& status) const;
  // The weight point i's row has in covariance() at the current parameters:
  // its own weight squared times the loss's correction at w_i d_i (1 for an
  // unweighted point without a loss): its leverage in the fit is
  // loss_weight(i) jacobian(i) C jacobian(i)^T, C = covariance().
  double loss_weight(std::size_t i) const;

 private:
  struct Impl;
  std::vector<Point> points_;
  double probe_radius_;
  DegreesOfFreedom dof_;
  // The allowed parameter changes at the current parameters: basis_, or
  // for twists their image (twist_to_parameters); and the projector on them.
  MotionBasis plus_basis() const;
  Eigen::Matrix<double, 6, 6> projector() const;

  MotionBasis basis_;  // the allowed motions (columns)
  MotionFrame frame_ = MotionFrame::parameters;
  int max_iterations_;
  double trust_radius_ = 1e4;  // the next solve's first trust region (surface_fit.cpp solve())
  Eigen::Matrix<double, 6, 1> parameters_ = Eigen::Matrix<double, 6, 1>::Zero();
  std::unique_ptr<Impl> impl_;
};

}  // namespace furrow
