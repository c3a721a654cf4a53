#pragma once
// A smoothing thin-plate spline in the plane with its smoothing chosen by
// generalised cross-validation (docs/compensation.md "The fit").
//
// Given n samples (x_i, y_i) in R^2 [mm] with values z_i, the spline
//   f(x) = sum_i w_i phi(|x - x_i|) + a0 + a1 x + a2 y,   phi(r) = r^2 log r
// minimises (1/n) sum (z_i - f(x_i))^2 + lambda J(f), J the bending energy
// (up to the constant of phi). Its coefficients solve
//   [K + n lambda I   P] [w]   [z]
//   [P^T             0] [a] = [0],   K_ij = phi(|x_i - x_j|), P = [1 x y].
// How it is solved: P = [Q1 Q2] [R; 0] (Householder QR), w = Q2 g with
// (B + n lambda I) g = Q2^T z, B = Q2^T K Q2 (positive semi-definite on the
// space Q2 spans: phi is conditionally positive definite of order 2), and
// R a = Q1^T (z - K w). B = U diag(mu) U^T once (symmetric eigensolver), so
// every lambda costs O(n) afterwards: with c = U^T Q2^T z and rho = n lambda
//   residual  (I - A) z = Q2 U diag(rho / (mu_j + rho)) c
//   trace     tr(I - A) = sum_j rho / (mu_j + rho)
//   GCV(lambda) = n |(I - A) z|^2 / tr(I - A)^2
// where A is the influence (hat) matrix, fitted = A z.
//
// The search: log10(rho) on a grid from log10(mu_max) - decades_below to
// log10(mu_max) + decades_above (`grid_points` values), then Brent's minimisation (base/scalar_search.hpp)
// over the two grid cells around the best grid value, stopped when
// the bracket is below `tolerance` decades or after `max_iterations`
// (converged false then, the best value found kept). The top of the range is
// the least-squares plane (the smoothest field, what GCV picks on pure
// noise); the bottom is interpolation. `at_bound` says the minimum lies on
// either end of the range.
//
// Uncertainty: the residual variance sigma^2 = |(I - A) z|^2 / tr(I - A)
// (Wahba's estimate), and the standard error of the fitted value at x,
// sigma |l(x)|, with f(x) = l(x)^T z. l(x) costs O(n^2) per point (the
// factors are kept), f(x) O(n).
//
// Cost: the eigen-decomposition, O(n^3), is the fit's one cubic step (Q is
// applied as its 3 reflectors); measured on this project's 2-core machine,
// 0.1 s for 300 samples, 2.7 s for 1000, 27 s for 2000, and memory ~4 n^2
// doubles (the cap on samples per face is error_field.hpp's).
//
// Preconditions, failure: fewer than 4 samples, or samples all on one line
// (P of rank < 3), cannot fix the plane and its bending at once: the result
// says `fitted` false with the reason, no exception. Non-finite input is a
// programming error (std::invalid_argument): callers check user data first.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace furrow {

struct GcvSearchOptions {
  // A fixed lambda (> 0) instead of GCV's choice; unset: GCV.
  std::optional<double> lambda;
  double decades_below = 10;  // search range below the largest eigenvalue of B
  double decades_above = 4;   // and above it (beyond, the field is the plane)
  int grid_points = 57;       // 0.25 decade steps over the default range, >= 3
  int max_iterations = 100;   // Brent steps
  double tolerance = 1e-4;    // bracket width that ends the search [decades of lambda]
};

struct GcvResult {
  double lambda = 0;       // chosen smoothing (see above)
  double gcv = 0;          // GCV score there [value unit^2]
  double trace = 0;        // tr(I - A): residual degrees of freedom
  double sigma = 0;        // residual standard deviation estimate [value unit]
  int iterations = 0;      // Brent steps taken
  bool converged = false;  // bracket below tolerance (or lambda given)
  bool at_bound = false;   // minimum on an end of the search range
};

class ThinPlateSpline {
 public:
  // Fits; see the header comment. `points` and `values` have equal lengths.
  ThinPlateSpline(std::vector<Eigen::Vector2d> points, const std::vector<double>& values,
                  const GcvSearchOptions& options = {});

  bool fitted() const { return fitted_; }
  const std::string& status() const { return status_; }  // "fitted" or why not
  const GcvResult& gcv() const { return gcv_; }
  std::size_t size() const { return points_.size(); }
  const Eigen::Vector2d& point(std::size_t i) const { return points_[i]; }

  // f(x); 0 when not fitted.
  double value(const Eigen::Vector2d& x) const;
  // Its gradient (df/dx, df/dy) [value unit per mm]; zero when not fitted.
  // grad phi = (x - x_i)(log r^2 + 1), 0 at a sample (its limit).
  Eigen::Vector2d gradient(const Eigen::Vector2d& x) const;
  // Both at once, one logarithm per sample instead of two.
  double value(const Eigen::Vector2d& x, Eigen::Vector2d& gradient) const;
  // Fitted values at the samples (A z) and the influence diagonal A_ii.
  const Eigen::VectorXd& fitted_values() const { return fitted_values_; }
  const Eigen::VectorXd& leverage() const { return leverage_; }
  // sigma |l(x)|: one standard error of f(x) [value unit]; 0 when not fitted.
  double standard_error(const Eigen::Vector2d& x) const;

  // GCV score at a given lambda (> 0), for tests and reports.
  double gcv_score(double lambda) const;

 private:
  Eigen::VectorXd kernel_row(const Eigen::Vector2d& x) const;
  void solve(double rho);

  std::vector<Eigen::Vector2d> points_;
  Eigen::Vector2d centre_ = Eigen::Vector2d::Zero();  // polynomial part about it (conditioning)
  bool fitted_ = false;
  std::string status_;
  GcvResult gcv_;
  // Factorisation kept for every lambda and the standard errors.
  Eigen::MatrixXd K_, Q1_, Q2U_, Rinv_, Q1tK_;
  Eigen::VectorXd z_, mu_, c_;
  Eigen::VectorXd inverse_;  // 1 / (mu_j + rho) at the chosen lambda
  // Coefficients at the chosen lambda.
  Eigen::VectorXd w_, fitted_values_, leverage_;
  Eigen::Vector3d a_ = Eigen::Vector3d::Zero();
  // a = G z; l(x)^T = k(x)^T M + p(x)^T G (standard errors).
  Eigen::MatrixXd G_;
};

}  // namespace furrow
