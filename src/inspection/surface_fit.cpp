#include "inspection/surface_fit.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "base/number_text.hpp"
#include "inspection/motion_manifold.hpp"
#include "inspection/registration.hpp"

namespace furrow {

namespace {

// The square of the factor Ceres' loss correction puts on a one-residual
// block's Jacobian row: J sqrt(rho') (1 - alpha) with alpha = 1 - sqrt(1 +
// 2 s rho'' / rho'), and alpha = 0 where rho'' <= 0 (Cauchy, Huber) or s =
// 0 (s the squared residual). 1 without a loss.
double corrected_weight(const ceres::LossFunction* loss, double residual) {
  const double sq = residual * residual;
  double rho[3] = {sq, 1, 0};
  if (loss) loss->Evaluate(sq, rho);
  double weight = rho[1];
  if (sq > 0 && rho[2] > 0) weight *= 1 + 2 * sq * rho[2] / rho[1];
  return weight;
}

// Ceres iterations of the second attempt of a solve whose every step was
// rejected (solve()): the trust region shrinks by factors 2, 4, 8, ... per
// rejected step, so 40 of them span any scale a step can need.
constexpr int kRejectedStepRetry = 40;

// A model decrease below this share of the cost is round-off (solve()).
constexpr double kNegligibleDecrease = 1e-12;

// The first trust region of a solve (solve()) lies between these: Ceres'
// own default, and one below which the problem has converged for any
// motion a part can make.
constexpr double kFirstTrustRadius = 1e4;
constexpr double kSmallestTrustRadius = 1e-12;

// The residual of one point as a function of the six parameters (rotation
// vector, translation), its foot held: with e = R y + t - f, n . e - r for a
// foot inside a face (point to tangent plane) and sign |e| - r for a foot on
// a face or trim boundary (the probe centre's true distance to the bounded
// surface less the radius, docs/registration.md "Points at an edge").
// `weighted`: the solver's residual w d (the residual blocks), else d itself.
struct BoundedDistance {
  const SurfaceFit::Point* point;
  double probe_radius;
  bool weighted = false;

  template <class T>
  bool operator()(const T* const x, T* residual) const {
    if (!distance(x, residual)) return false;
    if (weighted) residual[0] *= point->weight;  // exact for w = 1: unweighted fits keep their bits
    return true;
  }

  template <class T>
  bool distance(const T* const x, T* residual) const {
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

// One point's residual block: BoundedDistance differentiated exactly as
// ceres::AutoDiffCostFunction<BoundedDistance, 1, 6> does it (same calls,
// so the same bits), but without its heap-allocated functor, so that a
// million of them can live in one array owned by SurfaceFit (the problem
// does not own them: Ceres would otherwise keep a std::map entry per cost
// function to count references; docs/registration.md "Memory").
class PointCost final : public ceres::SizedCostFunction<1, 6> {
 public:
  BoundedDistance functor{nullptr, 0, true};

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!jacobians) return ceres::internal::VariadicEvaluate<ParameterDims>(functor, parameters, residuals);
    return ceres::internal::AutoDifferentiate<1, ParameterDims>(functor, parameters, num_residuals(), residuals,
                                                                jacobians);
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
  // One per point, in point order; Ceres holds pointers to them, so the
  // array is allocated once and never resized. Declared before the problem,
  // which refers to both, so that it is destroyed after it.
  std::unique_ptr<PointCost[]> costs;
  std::unique_ptr<ceres::Problem> problem;
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
  po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  // One parameter block and well-formed residuals: the per-block checks only
  // cost time (seconds for a million points).
  po.disable_all_safety_checks = true;
  impl_->problem = std::make_unique<ceres::Problem>(po);
  impl_->costs = std::make_unique<PointCost[]>(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    PointCost& cost = impl_->costs[i];
    cost.functor = BoundedDistance{&points_[i], probe_radius_, true};
    impl_->problem->AddResidualBlock(&cost, impl_->loss.get(), parameters_.data());
  }
  restrict_motion(free_parameter_basis(dof_.free));
}

MotionBasis SurfaceFit::plus_basis() const {
  return frame_ == MotionFrame::twist ? MotionBasis(twist_to_parameters(parameters_) * basis_) : basis_;
}

Eigen::Matrix<double, 6, 6> SurfaceFit::projector() const {
  const MotionBasis b = plus_basis();
  return b.cols() > 0 ? Eigen::Matrix<double, 6, 6>(b * b.completeOrthogonalDecomposition().pseudoInverse())
                      : Eigen::Matrix<double, 6, 6>::Zero();
}

void SurfaceFit::restrict_motion(const MotionBasis& basis, MotionFrame frame) {
  basis_ = basis;
  frame_ = frame;
  // All six free: no manifold at all (the plain problem, as fast as can be).
  // Ceres refuses a block with no tangent space; an empty basis is the
  // caller's to avoid (registration.cpp reports it instead of fitting).
  if (basis.cols() == 6)
    impl_->problem->SetManifold(parameters_.data(), nullptr);
  else if (basis.cols() > 0)
    impl_->problem->SetManifold(parameters_.data(), make_motion_manifold(basis, frame).release());
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
  Eigen::Matrix<double, 1, 6> j = Eigen::Matrix<double, 1, 6>::Zero();
  if (parameters_.head<3>().isZero()) {
    // At r = 0: d(R(r) y)/dr = -[y]x, so d(u.(R y))/dr = y x u; d/dt = u,
    // with u the residual's direction (direction()).
    const Eigen::Vector3d u = direction(i);
    j << points_[i].y.cross(u).transpose(), u.transpose();
    return basis_.cols() == 6 ? j : j * projector();
  }
  Point p = points_[i];
  p.active = true;
  ceres::AutoDiffCostFunction<BoundedDistance, 1, 6> cost(new BoundedDistance{&p, probe_radius_});
  const double* params[1] = {parameters_.data()};
  double r = 0;
  double* jac[1] = {j.data()};
  cost.Evaluate(params, &r, jac);
  return basis_.cols() == 6 ? j : j * projector();
}

double SurfaceFit::cost() const {
  // Summed in point order: the same bits whatever the threads did before.
  double sum = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].active) continue;
    const double r = points_[i].weight * residual(i);
    double rho[3] = {r * r, 1, 0};
    if (const ceres::LossFunction* loss = impl_->loss.get(); loss) loss->Evaluate(r * r, rho);
    sum += rho[0];
  }
  return sum / 2;
}

Eigen::Matrix<double, 6, 1> SurfaceFit::between(const Eigen::Matrix<double, 6, 1>& from,
                                                 const Eigen::Matrix<double, 6, 1>& to, double t) const {
  if (frame_ == MotionFrame::parameters) return from + t * (to - from);
  return compose_twist(t * twist_between(to, from), from);
}

void SurfaceFit::set_loss(RobustLoss loss, double loss_scale) {
  impl_->loss->Reset(make_loss(loss, loss_scale), ceres::TAKE_OWNERSHIP);
}

int SurfaceFit::solve(std::string& message) {
  ceres::Solver::Options o;
  // Six unknowns: each step from the 6x6 normal equations. Dense QR would
  // copy the million-row Jacobian twice more (docs/registration.md "Memory").
  o.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
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
  // Ceres' first trust region, or the one a solve whose every step was
  // rejected ended with (below).
  o.initial_trust_region_radius = trust_radius_;
  trust_radius_ = kFirstTrustRadius;
  ceres::Solver::Summary summary;
  ceres::Solve(o, impl_->problem.get(), &summary);
  // Iteration 0 is the start; none at all when Ceres refused the problem.
  if (summary.iterations.empty()) {
    message = summary.message;
    return 0;
  }
  int iterations = static_cast<int>(summary.iterations.size()) - 1;
  // Every step rejected: a step along a barely constrained motion can need
  // a trust region far smaller than the first one (its linear model fails
  // within micrometres of the cost), and five halvings need not reach it.
  // The parameters did not move, which the outer loop would read as
  // convergence: the region is let shrink on until a step is taken, and the
  // next solve starts from where it ended. Any other solve leaves the next
  // one Ceres' first region: started small, the steps near the optimum are
  // damped below the motion tolerance before they reach it.
  const auto taken = [&] {  // iteration 0, the start, counts as successful
    return std::any_of(summary.iterations.begin() + 1, summary.iterations.end(),
                       [](const ceres::IterationSummary& it) { return it.step_is_successful; });
  };
  // At the optimum every step is rejected too, for round-off: there the
  // first step's model promised next to nothing (the cost change it
  // predicted, change / relative decrease, below kNegligibleDecrease of the
  // cost), and the parameters standing still is convergence.
  const auto promised = [&] {
    if (summary.iterations.size() < 2) return false;
    const ceres::IterationSummary& first = summary.iterations[1];
    if (!(first.relative_decrease != 0)) return true;
    const double predicted = first.cost_change / first.relative_decrease;
    return predicted > kNegligibleDecrease * summary.iterations[0].cost;
  };
  if (summary.termination_type == ceres::NO_CONVERGENCE && !taken() && promised()) {
    o.max_num_iterations = kRejectedStepRetry;
    o.initial_trust_region_radius =
        std::clamp(summary.iterations.back().trust_region_radius, kSmallestTrustRadius, kFirstTrustRadius);
    ceres::Solve(o, impl_->problem.get(), &summary);
    if (!summary.iterations.empty()) {
      iterations += static_cast<int>(summary.iterations.size()) - 1;
      trust_radius_ =
          std::clamp(summary.iterations.back().trust_region_radius, kSmallestTrustRadius, kFirstTrustRadius);
    }
  }
  message = summary.IsSolutionUsable() ? std::string() : summary.message;
  return iterations;
}

void SurfaceFit::rebase() {
  for (std::size_t i = 0; i < points_.size(); ++i) points_[i].y = moved(i);
  parameters_.setZero();
}

double SurfaceFit::loss_weight(std::size_t i) const {
  const double* params[1] = {parameters_.data()};
  double residual = 0;
  impl_->costs[i].Evaluate(params, &residual, nullptr);  // w_i d_i
  const double w = points_[i].weight;
  return w * w * corrected_weight(impl_->loss.get(), residual);
}

std::optional<Eigen::Matrix<double, 6, 6>> SurfaceFit::covariance(std::string& status) const {
  // Rank check first (ceres::Covariance would log to stderr and fail): a
  // motion still allowed whose share of displacement along the normals is
  // below 1e-10 of the largest (observability.hpp) is not fixed at all.
  if (basis_.cols() == 0) {
    status = "no degree of freedom left to fit";
    return std::nullopt;
  }
  Observability seen;
  {
    // Scoped: a million points' positions and directions are freed before
    // the Jacobian is folded below.
    const std::size_t active = static_cast<std::size_t>(
        std::count_if(points_.begin(), points_.end(), [](const Point& p) { return p.active; }));
    std::vector<Eigen::Vector3d> x, n;
    x.reserve(active);
    n.reserve(active);
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (points_[i].active) {
        x.push_back(moved(i));
        n.push_back(direction(i));
      }
    seen = analyse_observability(x, n, basis_, 1e-10);
  }
  if (!seen.weak.empty()) {
    status = "rank deficient: the measured points do not fix the " + seen.weak.front().describe() +
             "; lock it (--dof) or measure more of the part";
    return std::nullopt;
  }
  // The Jacobian J of the residuals in the tangent space of the allowed
  // motions, as Ceres' solver sees it (each point's autodiff row, corrected
  // for the robust loss in force, times the basis when the motion is
  // restricted), is never held whole: its rows are folded, a few thousand at
  // a time, into the m x m triangle R of a QR factorisation (J = Q R), so a
  // million points cost a 4096-row buffer instead of the several dense and
  // sparse copies of J that ceres::Covariance made (docs/registration.md
  // "Memory"). The covariance (J^T J)^-1 = (R^T R)^-1 then follows from the
  // SVD of R as Ceres' DENSE_SVD takes it from the SVD of J (same singular
  // values and right vectors, the same accuracy: no normal equations).
  const bool restricted = basis_.cols() < 6;  // a Ceres manifold is set (restrict_motion)
  const Eigen::Index m = restricted ? basis_.cols() : 6;
  const MotionBasis tangent_basis = plus_basis();
  constexpr Eigen::Index kChunk = 4096;
  Eigen::MatrixXd stack = Eigen::MatrixXd::Zero(m + kChunk, m);
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(m, m);
  Eigen::Index rows = 0;
  const auto fold = [&] {
    if (rows == 0) return;
    stack.topRows(m) = r;
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack.topRows(m + rows));
    r = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
    rows = 0;
  };
  const double* params[1] = {parameters_.data()};
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].active) continue;  // a zero row
    double residual = 0;
    Eigen::Matrix<double, 1, 6> j = Eigen::Matrix<double, 1, 6>::Zero();
    double* jac[1] = {j.data()};
    impl_->costs[i].Evaluate(params, &residual, jac);
    const double scale = std::sqrt(corrected_weight(impl_->loss.get(), residual));
    if (restricted)
      stack.row(m + rows) = scale * (j * tangent_basis);
    else
      stack.row(m + rows) = scale * j;
    if (++rows == kChunk) fold();
  }
  fold();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(r, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();  // descending
  // Ceres' default test (min_reciprocal_condition_number 1e-14 on the
  // eigenvalues of J^T J): every singular value above 1e-7 of the largest.
  if (!(sv(0) > 0) || sv(m - 1) < 1e-7 * sv(0)) {
    status = "numerically rank deficient (smallest / largest singular value of the Jacobian " +
             general(sv(m - 1) / sv(0), 3) + ")";
    return std::nullopt;
  }
  const Eigen::MatrixXd tangent =
      svd.matrixV() * sv.cwiseProduct(sv).cwiseInverse().asDiagonal() * svd.matrixV().transpose();
  status = "ok";
  if (!restricted) return Eigen::Matrix<double, 6, 6>(tangent);
  return Eigen::Matrix<double, 6, 6>(tangent_basis * tangent * tangent_basis.transpose());
}

}  // namespace furrow
