#include "machining/prediction/scallop.hpp"

#include <cmath>

#include "base/scalar_search.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

// |k| below this is treated as flat: rho would exceed 1e9 mm, where the
// curved formulas lose all their digits to cancellation.
constexpr double kFlatCurvature = 1e-9;

}  // namespace

std::optional<double> ball_scallop_height(double r, double k, double w) {
  if (!(r > 0) || !(w >= 0) || !std::isfinite(k)) return std::nullopt;
  if (std::fabs(k) < kFlatCurvature) {
    const double half = 0.5 * w;
    if (half >= r) return std::nullopt;
    return r - std::sqrt(r * r - half * half);
  }
  const double rho = 1.0 / std::fabs(k);
  const double phi = w / (2.0 * rho);
  if (k < 0) {  // convex
    const double a = rho + r;
    const double s = a * std::sin(phi);
    if (phi >= kPi / 2 || s >= r) return std::nullopt;
    const double d = a * std::cos(phi) - std::sqrt(r * r - s * s);
    return d - rho;
  }
  if (rho <= r) return std::nullopt;  // the ball does not fit the concave section
  const double a = rho - r;
  const double s = a * std::sin(phi);
  if (phi >= kPi || s >= r) return std::nullopt;
  const double d = a * std::cos(phi) + std::sqrt(r * r - s * s);
  return rho - d;
}

SideStepResult ball_side_step_for_scallop(double r, double k, double height,
                                          const ScallopOptions& options) {
  SideStepResult result;
  if (!(height > 0) || !(r > 0)) return result;
  // Bracket [lo, hi]: h(lo) <= height, and hi beyond it or beyond the cusp's
  // existence. The widest meaningful step is 2r on the flat, 2 rho * pi on
  // the curved cases; start from a bracket that surely contains the answer.
  double lo = 0.0;
  double hi = 2.0 * r;
  if (std::fabs(k) >= kFlatCurvature) hi = std::max(hi, 2.0 * kPi / std::fabs(k));
  auto below = [&](double w) {
    const auto h = ball_scallop_height(r, k, w);
    return h && *h <= height;
  };
  if (!ball_scallop_height(r, k, 0.0)) return result;  // concave section tighter than the ball
  result.feasible = true;
  const ScalarSearchResult s = largest_satisfying(below, lo, hi, {options.tolerance * r, options.max_iterations});
  result.side_step = s.x;
  result.converged = s.converged;
  result.iterations = s.iterations;
  return result;
}

double ball_side_step_estimate(double r, double k, double h) {
  if (std::fabs(k) < kFlatCurvature) return std::sqrt(8.0 * h * r);
  const double rho = 1.0 / std::fabs(k);
  return std::sqrt(8.0 * h * r * rho / (k < 0 ? rho + r : rho - r));
}

}  // namespace furrow
