#include "inspection/surface_fit.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "inspection/registration.hpp"

namespace furrow {

namespace {

// Signed point-to-tangent-plane distance minus the probe radius, as a
// function of the six parameters (rotation vector, translation).
struct PointToPlane {
  const SurfaceFit::Point* point;
  double probe_radius;

  template <class T>
  bool operator()(const T* const x, T* residual) const {
    if (!point->active) {
      residual[0] = T(0);
      return true;
    }
    const T y[3] = {T(point->y.x()), T(point->y.y()), T(point->y.z())};
    T ry[3];
    ceres::AngleAxisRotatePoint(x, y, ry);
    T d = T(-probe_radius);
    for (int k = 0; k < 3; ++k) d += point->normal[k] * (ry[k] + x[3 + k] - point->foot[k]);
    residual[0] = d;
    return true;
  }
};

ceres::LossFunction* make_loss(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::none:
      return nullptr;
    case RobustLoss::huber:
      return new ceres::HuberLoss(scale);
    case RobustLoss::cauchy:
      return new ceres::CauchyLoss(scale);
  }
  return nullptr;
}

}  // namespace

struct SurfaceFit::Impl {
  // A wrapper, so that the loss can be swapped without rebuilding the problem.
  std::unique_ptr<ceres::LossFunctionWrapper> loss;
  std::unique_ptr<ceres::Problem> problem;
  std::vector<ceres::CostFunction*> costs;  // owned by the problem
};

SurfaceFit::SurfaceFit(std::vector<Eigen::Vector3d> y, double probe_radius,
                       const DegreesOfFreedom& dof, RobustLoss loss, double loss_scale,
                       int max_iterations)
    : probe_radius_(probe_radius),
      dof_(dof),
      max_iterations_(max_iterations),
      impl_(std::make_unique<Impl>()) {
  points_.resize(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) points_[i].y = y[i];
  impl_->loss = std::make_unique<ceres::LossFunctionWrapper>(make_loss(loss, loss_scale),
                                                             ceres::TAKE_OWNERSHIP);
  ceres::Problem::Options po;
  po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  // One parameter block and well-formed residuals: the per-block checks only
  // cost time (seconds for a million points).
  po.disable_all_safety_checks = true;
  impl_->problem = std::make_unique<ceres::Problem>(po);
  impl_->costs.reserve(points_.size());
  for (const Point& p : points_) {
    auto* cost =
        new ceres::AutoDiffCostFunction<PointToPlane, 1, 6>(new PointToPlane{&p, probe_radius_});
    impl_->costs.push_back(cost);
    impl_->problem->AddResidualBlock(cost, impl_->loss.get(), parameters_.data());
  }
  std::vector<int> locked;
  for (int k = 0; k < 6; ++k)
    if (!dof_.free[k]) locked.push_back(k);
  if (!locked.empty())
    impl_->problem->SetManifold(parameters_.data(), new ceres::SubsetManifold(6, locked));
}

SurfaceFit::~SurfaceFit() = default;

Eigen::Vector3d SurfaceFit::moved(std::size_t i) const {
  Eigen::Vector3d out;
  ceres::AngleAxisRotatePoint(parameters_.data(), points_[i].y.data(), out.data());
  return out + parameters_.tail<3>();
}

void SurfaceFit::set_foot(std::size_t i, const Eigen::Vector3d& foot, const Eigen::Vector3d& normal,
                          bool active) {
  points_[i].foot = foot;
  points_[i].normal = normal;
  points_[i].active = active;
}

double SurfaceFit::residual(std::size_t i) const {
  return points_[i].normal.dot(moved(i) - points_[i].foot) - probe_radius_;
}

Eigen::Matrix<double, 1, 6> SurfaceFit::jacobian(std::size_t i) const {
  Eigen::Matrix<double, 1, 6> j;
  if (parameters_.head<3>().isZero()) {
    // At r = 0: d(R(r) y)/dr = -[y]x, so d(n.(R y))/dr = y x n; d/dt = n.
    const Point& p = points_[i];
    j << p.y.cross(p.normal).transpose(), p.normal.transpose();
    for (int k = 0; k < 6; ++k)
      if (!dof_.free[k]) j(k) = 0;
    return j;
  }
  Point p = points_[i];
  p.active = true;
  ceres::AutoDiffCostFunction<PointToPlane, 1, 6> cost(new PointToPlane{&p, probe_radius_});
  const double* params[1] = {parameters_.data()};
  double r = 0;
  double* jac[1] = {j.data()};
  cost.Evaluate(params, &r, jac);
  for (int k = 0; k < 6; ++k)
    if (!dof_.free[k]) j(k) = 0;
  return j;
}

void SurfaceFit::set_loss(RobustLoss loss, double loss_scale) {
  impl_->loss->Reset(make_loss(loss, loss_scale), ceres::TAKE_OWNERSHIP);
}

int SurfaceFit::solve(std::string& message) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = max_iterations_;
  // The outer loop decides convergence (motion_tolerance) and the iteration
  // cap bounds the work per outer iteration. Ceres' own tolerances must not
  // stop it first: it ends without taking a step below parameter_tolerance
  // (relative to |x|, and x holds tens of mm), which would freeze the last
  // nanometres of the fit.
  o.function_tolerance = 1e-14;
  o.gradient_tolerance = 1e-20;
  o.parameter_tolerance = 1e-14;
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(o, impl_->problem.get(), &summary);
  message = summary.IsSolutionUsable() ? std::string() : summary.message;
  return static_cast<int>(summary.iterations.size()) - 1;  // iteration 0 is the start
}

void SurfaceFit::rebase() {
  for (std::size_t i = 0; i < points_.size(); ++i) points_[i].y = moved(i);
  parameters_.setZero();
}

std::optional<Eigen::Matrix<double, 6, 6>> SurfaceFit::covariance(std::string& status) const {
  // Rank check first (ceres::Covariance would log to stderr and fail): the
  // information matrix of the free parameters with rotations expressed as
  // the motion they cause at the points' RMS distance from the origin, so
  // that all six are lengths and comparable.
  Eigen::Matrix<double, 6, 6> info = Eigen::Matrix<double, 6, 6>::Zero();
  double spread = 0;
  std::size_t active = 0;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (points_[i].active) {
      const Eigen::Matrix<double, 1, 6> j = jacobian(i);
      info += j.transpose() * j;
      spread += points_[i].y.squaredNorm();
      ++active;
    }
  const double lever = active > 0 ? std::sqrt(spread / static_cast<double>(active)) : 1.0;
  std::vector<int> free;
  for (int k = 0; k < 6; ++k)
    if (dof_.free[k]) free.push_back(k);
  Eigen::MatrixXd scaled(free.size(), free.size());
  for (std::size_t a = 0; a < free.size(); ++a)
    for (std::size_t b = 0; b < free.size(); ++b)
      scaled(a, b) =
          info(free[a], free[b]) / ((free[a] < 3 ? lever : 1.0) * (free[b] < 3 ? lever : 1.0));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(scaled);
  if (!(es.eigenvalues()(0) > 1e-10 * es.eigenvalues().maxCoeff())) {
    const Eigen::VectorXd null = es.eigenvectors().col(0);
    Eigen::Index worst = 0;
    null.cwiseAbs().maxCoeff(&worst);
    status = std::string("rank deficient: the measured surface does not fix ") +
             dof_name(free[worst]) +
             " (and what moves with it); lock it or measure more of the part";
    return std::nullopt;
  }
  ceres::Covariance::Options o;
  o.algorithm_type = ceres::DENSE_SVD;
  o.num_threads = 1;
  ceres::Covariance cov(o);
  const double* block = parameters_.data();
  std::vector<std::pair<const double*, const double*>> blocks = {{block, block}};
  if (!cov.Compute(blocks, impl_->problem.get())) {
    status = "ceres::Covariance failed (numerically rank deficient)";
    return std::nullopt;
  }
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> c;
  cov.GetCovarianceBlock(block, block, c.data());
  status = "ok";
  return Eigen::Matrix<double, 6, 6>(c);
}

}  // namespace furrow
