#pragma once
// B-spline basis functions and their derivatives up to second order (the
// Cox-de Boor triangle and the derivative recurrence of Piegl & Tiller, "The
// NURBS Book", ch. 2), written for speed: no heap allocation, one division per
// knot difference, the caller owns the output arrays.
//
// A knot vector U = {u_0 .. u_m} of degree p with n = m - p control points has
// the valid parameter range [u_p, u_n]; it may be clamped (p+1 equal end knots)
// or not. Parameters outside the range are clamped to it.
#include <string>
#include <vector>

namespace furrow {

// Highest degree the evaluator supports. Degrees above this are rejected when a
// surface is validated (no CAD system exports them; the bound keeps the
// evaluation on the stack).
constexpr int kMaxDegree = 15;

// Index of the knot span [u_k, u_{k+1}) that contains u, with k in [p, n-1].
// At the upper end of the range the last non-empty span is returned, so that
// u = u_n evaluates the surface's edge rather than falling off it.
// Preconditions: the knot vector is valid (see validate_knot_vector).
int find_span(const std::vector<double>& knots, int degree, int num_control_points, double u);

// Values and derivatives of the p+1 non-zero basis functions at u in span.
// ders[k][j] is the k-th derivative of N_{span-p+j,p}(u), k = 0..max_order,
// max_order <= 2 (the evaluator never needs more).
void basis_functions_with_derivatives(const std::vector<double>& knots, int degree, int span,
                                      double u, int max_order, double ders[3][kMaxDegree + 1]);

// Validates a knot vector for `degree` and `num_control_points`. Throws
// InputError naming `field` when the degree is out of [1, kMaxDegree], the
// count is not num_control_points + degree + 1, a knot is not finite, the knots
// decrease, an interior knot repeats more than `degree` times (the curve would
// break apart), or the valid range [u_p, u_n] is empty.
void validate_knot_vector(const std::vector<double>& knots, int degree, int num_control_points,
                          const std::string& field);

}  // namespace furrow
