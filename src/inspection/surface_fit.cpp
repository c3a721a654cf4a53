#include "inspection/surface_fit.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <cmath>

#include "inspection/registration.hpp"

namespace furrow {

namespace {

// The residual of one point as a function of the six parameters (rotation
// vector, translation), its foot held: with e = R y + t - f, n . e - r for a
// foot inside a face (point to tangent plane) and sign |e| - r for a foot on
// a face or trim boundary (the probe centre's true distance to the bounded
// surface less the radius, docs/registration.md "Points at an edge").
struct BoundedDistance {
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
    T e[3];
    for (int k = 0; k < 3; ++k) e[k] = ry[k] + x[3 + k] - point->foot[k];
    if (point->boundary) {
      using std::sqrt;
      const T e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      // |e| has no derivative at 0; there the point sits on the boundary
      // and n . e is as good (both vanish).
      if (e2 > T(1e-24)) {
        residual[0] = point->sign * sqrt(e2) - probe_radius;
        return true;
      }
    }
    T along = T(-probe_radius);
    for (int k = 0; k < 3; ++k) along += point->normal[k] * e[k];
    residual[0] = along;
    return true;
  }
};

// x + B delta: the parameters move only within span(B). The locked degrees
// of freedom (B: unit vectors) and the held weak directions
// (observability.hpp) are the same mechanism.
class SubspaceManifold : public ceres::Manifold {
 public:
  explicit SubspaceManifold(const MotionBasis& basis)
      : basis_(basis), left_inverse_(basis.completeOrthogonalDecomposition().pseudoInverse()) {}
  int AmbientSize() const override { return 6; }
  int TangentSize() const override { return static_cast<int>(basis_.cols()); }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    using Vec6 = Eigen::Matrix<double, 6, 1>;
    Eigen::Map<Vec6> out(x_plus_delta);
    out = Eigen::Map<const Vec6>(x) + basis_ * Eigen::Map<const Eigen::VectorXd>(delta, basis_.cols());
    return true;
  }
  bool PlusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> out(jacobian, 6, basis_.cols());
    out = basis_;
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    using Vec6 = Eigen::Matrix<double, 6, 1>;
    Eigen::Map<Eigen::VectorXd> out(y_minus_x, basis_.cols());
    out = left_inverse_ * (Eigen::Map<const Vec6>(y) - Eigen::Map<const Vec6>(x));
    return true;
  }
  bool MinusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> out(jacobian, basis_.cols(), 6);
    out = left_inverse_;
    return true;
  }

 private:
  MotionBasis basis_;
  Eigen::MatrixXd left_inverse_;
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
        new ceres::AutoDiffCostFunction<BoundedDistance, 1, 6>(new BoundedDistance{&p, probe_radius_});
    impl_->costs.push_back(cost);
    impl_->problem->AddResidualBlock(cost, impl_->loss.get(), parameters_.data());
  }
  restrict_motion(free_parameter_basis(dof_.free));
}

void SurfaceFit::restrict_motion(const MotionBasis& basis) {
  basis_ = basis;
  projector_ = basis.cols() > 0 ? Eigen::Matrix<double, 6, 6>(
                                      basis * basis.completeOrthogonalDecomposition().pseudoInverse())
                                : Eigen::Matrix<double, 6, 6>::Zero();
  // All six free: no manifold at all (the plain problem, as fast as can be).
  // Ceres refuses a block with no tangent space; an empty basis is the
  // caller's to avoid (registration.cpp reports it instead of fitting).
  if (basis.cols() == 6)
    impl_->problem->SetManifold(parameters_.data(), nullptr);
  else if (basis.cols() > 0)
    impl_->problem->SetManifold(parameters_.data(), new SubspaceManifold(basis));
}

SurfaceFit::~SurfaceFit() = default;

Eigen::Vector3d SurfaceFit::moved(std::size_t i) const {
  Eigen::Vector3d out;
  ceres::AngleAxisRotatePoint(parameters_.data(), points_[i].y.data(), out.data());
  return out + parameters_.tail<3>();
}

void SurfaceFit::set_foot(std::size_t i, const Eigen::Vector3d& foot, const Eigen::Vector3d& normal,
                          bool active, bool boundary) {
  Point& p = points_[i];
  p.foot = foot;
  p.normal = normal;
  p.active = active;
  p.boundary = boundary;
  // The side of the tangent plane the point is on now: the sign of its
  // bounded distance, held while the foot is (the squared residual, all the
  // fit sees, does not depend on it).
  p.sign = normal.dot(moved(i) - foot) >= 0 ? 1.0 : -1.0;
}

double SurfaceFit::residual(std::size_t i) const {
  Point p = points_[i];
  p.active = true;
  const BoundedDistance f{&p, probe_radius_};
  double r = 0;
  f(parameters_.data(), &r);
  return r;
}

Eigen::Vector3d SurfaceFit::direction(std::size_t i) const {
  const Point& p = points_[i];
  if (!p.boundary) return p.normal;
  const Eigen::Vector3d e = moved(i) - p.foot;
  return e.squaredNorm() > 1e-24 ? Eigen::Vector3d(p.sign * e.normalized()) : p.normal;
}

Eigen::Matrix<double, 1, 6> SurfaceFit::jacobian(std::size_t i) const {
  Eigen::Matrix<double, 1, 6> j;
  if (parameters_.head<3>().isZero()) {
    // At r = 0: d(R(r) y)/dr = -[y]x, so d(u.(R y))/dr = y x u; d/dt = u,
    // with u the residual's direction (direction()).
    const Eigen::Vector3d u = direction(i);
    j << points_[i].y.cross(u).transpose(), u.transpose();
    return j * projector_;
  }
  Point p = points_[i];
  p.active = true;
  ceres::AutoDiffCostFunction<BoundedDistance, 1, 6> cost(new BoundedDistance{&p, probe_radius_});
  const double* params[1] = {parameters_.data()};
  double r = 0;
  double* jac[1] = {j.data()};
  cost.Evaluate(params, &r, jac);
  return j * projector_;
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
  // Rank check first (ceres::Covariance would log to stderr and fail): a
  // motion still allowed whose share of displacement along the normals is
  // below 1e-10 of the largest (observability.hpp) is not fixed at all.
  std::vector<Eigen::Vector3d> x, n;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (points_[i].active) {
      x.push_back(moved(i));
      n.push_back(direction(i));
    }
  if (basis_.cols() == 0) {
    status = "no degree of freedom left to fit";
    return std::nullopt;
  }
  const Observability seen = analyse_observability(x, n, basis_, 1e-10);
  if (!seen.weak.empty()) {
    status = "rank deficient: the measured points do not fix the " + seen.weak.front().describe() +
             "; lock it (--dof) or measure more of the part";
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
