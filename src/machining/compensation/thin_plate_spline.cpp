#include "machining/compensation/thin_plate_spline.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/scalar_search.hpp"

namespace furrow {

namespace {

// phi(r) = r^2 log r written with r^2 so no square root is taken; 0 at r = 0
// (its limit).
double phi_of_squared(double r2) { return r2 > 0 ? 0.5 * r2 * std::log(r2) : 0.0; }

}  // namespace

ThinPlateSpline::ThinPlateSpline(std::vector<Eigen::Vector2d> points,
                                 const std::vector<double>& values,
                                 const GcvSearchOptions& options)
    : points_(std::move(points)) {
  const std::size_t n = points_.size();
  if (values.size() != n) throw std::invalid_argument("ThinPlateSpline: points and values differ in length");
  for (std::size_t i = 0; i < n; ++i)
    if (!points_[i].allFinite() || !std::isfinite(values[i]))
      throw std::invalid_argument("ThinPlateSpline: non-finite sample");
  if (options.grid_points < 3 || options.max_iterations < 0 || !(options.tolerance > 0) ||
      (options.lambda && !(*options.lambda > 0)))
    throw std::invalid_argument("ThinPlateSpline: bad search options");
  if (n < 4) {
    status_ = "fewer than 4 samples";
    return;
  }
  for (const Eigen::Vector2d& p : points_) centre_ += p;
  centre_ /= double(n);
  // Collinear samples leave the plane's tilt across their line free.
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& p : points_) scatter += (p - centre_) * (p - centre_).transpose();
  const Eigen::Vector2d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvalues();
  if (!(spread(0) > 1e-12 * spread(1))) {
    status_ = "samples on one line";
    return;
  }

  const Eigen::Index N = Eigen::Index(n);
  K_.resize(N, N);
  Eigen::MatrixXd P(N, 3);
  for (Eigen::Index i = 0; i < N; ++i) {
    P.row(i) << 1, points_[i].x() - centre_.x(), points_[i].y() - centre_.y();
    for (Eigen::Index j = 0; j <= i; ++j)
      K_(i, j) = K_(j, i) = phi_of_squared((points_[i] - points_[j]).squaredNorm());
  }
  z_ = Eigen::Map<const Eigen::VectorXd>(values.data(), N);

  // Q has only 3 Householder reflectors: applying it costs O(n^2), so
  // Q^T K Q and Q2 U are formed by reflections, never by n x n products;
  // the eigen-decomposition is the one O(n^3) step.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(P);
  const auto Q = qr.householderQ();
  Eigen::MatrixXd QtKQ = K_;
  QtKQ.applyOnTheLeft(Q.transpose());
  QtKQ.applyOnTheRight(Q);
  Q1_ = Q * Eigen::MatrixXd::Identity(N, 3);
  Rinv_ = qr.matrixQR().topLeftCorner(3, 3).triangularView<Eigen::Upper>().solve(
      Eigen::Matrix3d::Identity());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(QtKQ.bottomRightCorner(N - 3, N - 3));
  if (eig.info() != Eigen::Success) {
    status_ = "eigen-decomposition of the spline system failed";
    return;
  }
  // Rounding leaves eigenvalues of a semi-definite matrix a hair below 0.
  mu_ = eig.eigenvalues().cwiseMax(0.0);
  Q2U_ = Eigen::MatrixXd::Zero(N, N - 3);
  Q2U_.bottomRows(N - 3) = eig.eigenvectors();
  Q2U_.applyOnTheLeft(Q);
  Q1tK_ = Q1_.transpose() * K_;
  c_ = Q2U_.transpose() * z_;

  if (options.lambda) {
    gcv_.lambda = *options.lambda;
    gcv_.converged = true;
  } else {
    // log10(rho) over the range, rho = n lambda.
    const double top = std::log10(std::max(mu_.maxCoeff(), 1e-300));
    const double lo = top - options.decades_below, hi = top + options.decades_above;
    const double step = (hi - lo) / (options.grid_points - 1);
    auto score = [&](double log_rho) { return gcv_score(std::pow(10.0, log_rho) / double(n)); };
    int best = 0;
    double best_score = score(lo);
    for (int k = 1; k < options.grid_points; ++k) {
      const double s = score(lo + k * step);
      if (s < best_score) best = k, best_score = s;
    }
    gcv_.at_bound = best == 0 || best == options.grid_points - 1;
    // Brent's search (golden section with parabolic steps) over the two grid
    // cells around the grid's best; GCV is unimodal there in practice, and
    // the grid's best stays the answer unless the search found lower.
    const double a = lo + std::max(best - 1, 0) * step;
    const double b = lo + std::min(best + 1, options.grid_points - 1) * step;
    ScalarSearchOptions search;
    search.tolerance = options.tolerance;
    search.max_iterations = options.max_iterations;
    const ScalarSearchResult found = minimize_unimodal(score, a, b, search);
    gcv_.iterations = found.iterations;
    gcv_.converged = found.converged;
    const double best_x = found.value < best_score ? found.x : lo + best * step;
    gcv_.lambda = std::pow(10.0, best_x) / double(n);
  }
  solve(gcv_.lambda * double(n));
  fitted_ = true;
  status_ = "fitted";
}

double ThinPlateSpline::gcv_score(double lambda) const {
  const double n = double(z_.size());
  const double rho = lambda * n;
  double rss = 0, trace = 0;
  for (Eigen::Index j = 0; j < mu_.size(); ++j) {
    const double s = rho / (mu_(j) + rho);
    rss += (s * c_(j)) * (s * c_(j));
    trace += s;
  }
  return trace > 0 ? n * rss / (trace * trace) : 0.0;
}

void ThinPlateSpline::solve(double rho) {
  const Eigen::Index N = z_.size();
  inverse_ = (mu_.array() + rho).inverse().matrix();
  // w = M z with M = Q2 U diag(inverse) (Q2 U)^T; a = G z with
  // G = R^-1 Q1^T (I - K M) = R^-1 (Q1^T - ((Q1^T K) Q2 U) diag(inverse) (Q2 U)^T).
  w_ = Q2U_ * inverse_.cwiseProduct(c_);
  G_ = Rinv_ * (Q1_.transpose() - (Q1tK_ * Q2U_) * inverse_.asDiagonal() * Q2U_.transpose());
  a_ = G_ * z_;
  // (I - A) z and tr(I - A) from the eigen-expansion (see the header).
  const Eigen::VectorXd shrink = (rho * inverse_.array()).matrix();
  const Eigen::VectorXd residual = Q2U_ * shrink.cwiseProduct(c_);
  fitted_values_ = z_ - residual;
  gcv_.trace = shrink.sum();
  const double n = double(N);
  gcv_.gcv = gcv_.trace > 0 ? n * residual.squaredNorm() / (gcv_.trace * gcv_.trace) : 0.0;
  gcv_.sigma = gcv_.trace > 0 ? std::sqrt(residual.squaredNorm() / gcv_.trace) : 0.0;
  leverage_.resize(N);
  for (Eigen::Index i = 0; i < N; ++i)
    leverage_(i) = 1 - (Q2U_.row(i).array().square() * shrink.transpose().array()).sum();
}

Eigen::VectorXd ThinPlateSpline::kernel_row(const Eigen::Vector2d& x) const {
  Eigen::VectorXd k(Eigen::Index(points_.size()));
  for (std::size_t i = 0; i < points_.size(); ++i)
    k(Eigen::Index(i)) = phi_of_squared((x - points_[i]).squaredNorm());
  return k;
}

double ThinPlateSpline::value(const Eigen::Vector2d& x) const {
  if (!fitted_) return 0.0;
  double f = a_(0) + a_(1) * (x.x() - centre_.x()) + a_(2) * (x.y() - centre_.y());
  for (std::size_t i = 0; i < points_.size(); ++i)
    f += w_(Eigen::Index(i)) * phi_of_squared((x - points_[i]).squaredNorm());
  return f;
}

Eigen::Vector2d ThinPlateSpline::gradient(const Eigen::Vector2d& x) const {
  Eigen::Vector2d g;
  value(x, g);
  return g;
}

double ThinPlateSpline::value(const Eigen::Vector2d& x, Eigen::Vector2d& gradient) const {
  gradient.setZero();
  if (!fitted_) return 0.0;
  double f = a_(0) + a_(1) * (x.x() - centre_.x()) + a_(2) * (x.y() - centre_.y());
  gradient << a_(1), a_(2);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Eigen::Vector2d d = x - points_[i];
    const double r2 = d.squaredNorm();
    if (!(r2 > 0)) continue;  // phi and its gradient vanish at the sample
    const double lg = std::log(r2), w = w_(Eigen::Index(i));
    f += w * 0.5 * r2 * lg;
    gradient += w * (lg + 1) * d;
  }
  return f;
}

double ThinPlateSpline::standard_error(const Eigen::Vector2d& x) const {
  if (!fitted_) return 0.0;
  const Eigen::Vector3d p(1, x.x() - centre_.x(), x.y() - centre_.y());
  // l = M k(x) + G^T p(x), M applied through its factors: O(n^2).
  const Eigen::VectorXd l =
      Q2U_ * inverse_.cwiseProduct(Q2U_.transpose() * kernel_row(x)) + G_.transpose() * p;
  return gcv_.sigma * l.norm();
}

}  // namespace furrow
