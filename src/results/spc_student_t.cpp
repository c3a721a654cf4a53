#include "results/spc_student_t.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace furrow {
namespace {

// The continued fraction of B(x; a, b) * (x^a (1-x)^b / (a B(a, b)))^-1,
// converging fast for x < (a + 1) / (a + b + 2); modified Lentz evaluation.
IncompleteBetaResult beta_continued_fraction(double a, double b, double x, const IncompleteBetaOptions& options) {
  constexpr double kTiny = 1e-300;  // keeps Lentz's denominators away from 0
  IncompleteBetaResult r;
  double c = 1;
  double d = 1 - (a + b) * x / (a + 1);
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1 / d;
  double f = d;
  for (int m = 1; m <= options.max_iterations; ++m) {
    r.iterations = m;
    const double m2 = 2.0 * m;
    // Even term d_{2m}, then odd term d_{2m+1} of the fraction.
    double num = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
    d = 1 + num * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1 + num / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    f *= d * c;
    num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
    d = 1 + num * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1 + num / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double delta = d * c;
    f *= delta;
    if (std::abs(delta - 1) < options.tolerance) {
      r.converged = true;
      break;
    }
  }
  r.value = f;
  return r;
}

}  // namespace

IncompleteBetaResult regularized_incomplete_beta(double a, double b, double x, const IncompleteBetaOptions& options) {
  if (!(a > 0) || !(b > 0) || !(x >= 0 && x <= 1))
    throw std::logic_error("regularized_incomplete_beta: needs a > 0, b > 0, 0 <= x <= 1");
  IncompleteBetaResult r;
  if (x == 0 || x == 1) {
    r.value = x;
    r.converged = true;
    return r;
  }
  // x^a (1-x)^b / B(a, b), in logarithms so that large a, b do not overflow.
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) {
    r = beta_continued_fraction(a, b, x, options);
    r.value = front * r.value / a;
  } else {
    r = beta_continued_fraction(b, a, 1 - x, options);
    r.value = 1 - front * r.value / b;
  }
  return r;
}

namespace {

// P(T <= t), and whether the incomplete beta behind it converged.
double t_cdf(double t, double dof, bool& converged) {
  if (std::isinf(t)) return t > 0 ? 1.0 : 0.0;
  const IncompleteBetaResult beta = regularized_incomplete_beta(dof / 2, 0.5, dof / (dof + t * t));
  converged = converged && beta.converged;
  const double tail = 0.5 * beta.value;
  return t >= 0 ? 1 - tail : tail;
}

}  // namespace

double student_t_cdf(double t, double dof) {
  if (!(dof > 0)) throw std::logic_error("student_t_cdf: needs dof > 0");
  bool converged = true;
  return t_cdf(t, dof, converged);
}

StudentQuantileResult student_t_quantile(double p, double dof, const ScalarSearchOptions& options) {
  if (!(p > 0 && p < 1) || !(dof > 0)) throw std::logic_error("student_t_quantile: needs 0 < p < 1, dof > 0");
  StudentQuantileResult result;
  if (p == 0.5) {
    result.converged = true;
    return result;
  }
  // Solve on the upper half and mirror: the distribution is symmetric.
  const double q = p > 0.5 ? p : 1 - p;
  bool cdf_converged = true;  // every distribution value the search used
  auto f = [&](double t) { return t_cdf(t, dof, cdf_converged) - q; };
  double hi = 1;
  double fhi = f(hi);
  // Doubling reaches the 1 - 1e-16 quantile of one degree of freedom (about
  // 3e15) in 52 steps; beyond that the distribution function rounds to 1.
  for (int i = 0; fhi < 0 && i < 64; ++i) {
    hi *= 2;
    fhi = f(hi);
  }
  if (fhi < 0) return result;  // not bracketed: reported, not guessed
  const ScalarSearchResult root = find_bracketed_root(f, 0.0, f(0.0), hi, fhi, options);
  result.value = p > 0.5 ? root.x : -root.x;
  result.converged = root.converged && cdf_converged;
  result.iterations = root.iterations;
  return result;
}

}  // namespace furrow
