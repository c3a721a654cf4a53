#pragma once
// Student's t distribution, for the confidence interval of a trend slope
// (docs/spc.md "Trend"): its distribution function through the regularized
// incomplete beta function, and its quantile by inverting that function
// numerically.
//
// Why computed here: the interval must hold for any number of parts (3 and
// up), so a table of a few degrees of freedom is not enough, and no
// statistics library is among the project's dependencies. The continued
// fraction and the root search each have a visible iteration cap and
// tolerance; the quantile says whether it converged.
#include "base/scalar_search.hpp"

namespace furrow {

struct IncompleteBetaResult {
  double value = 0;  // I_x(a, b) in [0, 1]
  bool converged = false;
  int iterations = 0;  // continued-fraction terms used
};

struct IncompleteBetaOptions {
  double tolerance = 1e-15;  // relative change of the continued fraction at which it stops
  int max_iterations = 500;  // terms; a few dozen suffice for the t quantiles used here
};

// I_x(a, b) = B(x; a, b) / B(a, b) for a, b > 0 and 0 <= x <= 1, by the
// continued fraction of the incomplete beta (evaluated with the modified
// Lentz method) on the side of x where it converges fast, using
// I_x(a, b) = 1 - I_{1-x}(b, a) on the other side.
// Preconditions (logic_error otherwise): a > 0, b > 0, x in [0, 1].
IncompleteBetaResult regularized_incomplete_beta(double a, double b, double x,
                                                 const IncompleteBetaOptions& options = {});

// P(T <= t) for Student's t with `dof` > 0 degrees of freedom:
// 1 - I_{dof/(dof+t^2)}(dof/2, 1/2) / 2 for t >= 0, by symmetry below.
double student_t_cdf(double t, double dof);

struct StudentQuantileResult {
  double value = 0;  // t with P(T <= t) = p
  bool converged = false;
  int iterations = 0;
};

// The p-quantile of Student's t with `dof` > 0 degrees of freedom, for
// 0 < p < 1: the root of student_t_cdf(t) - p, bracketed by doubling from
// [0, 1] (the quantile is odd around p = 1/2) and found with
// find_bracketed_root. `options.tolerance` is absolute on t. Not
// converged when the root search or any incomplete beta it evaluated
// stopped at its cap.
StudentQuantileResult student_t_quantile(double p, double dof, const ScalarSearchOptions& options = {1e-12, 200});

}  // namespace furrow
