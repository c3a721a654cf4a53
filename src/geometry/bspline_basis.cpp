#include "geometry/bspline_basis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "base/limits.hpp"

namespace furrow {

int find_span(const std::vector<double>& knots, int degree, int num_control_points, double u) {
  const int n = num_control_points;  // valid range is [knots[degree], knots[n]]
  const double lo = knots[degree];
  const double hi = knots[n];
  if (!(u > lo)) u = lo;  // also catches NaN: it evaluates the range start
  if (u >= hi) {
    // Last non-empty span: walk down over repeated end knots.
    int k = n - 1;
    while (k > degree && knots[k] >= hi) --k;
    return k;
  }
  // Largest k in [degree, n-1] with knots[k] <= u.
  auto first = knots.begin() + degree;
  auto last = knots.begin() + n;
  auto it = std::upper_bound(first, last, u);
  return static_cast<int>(it - knots.begin()) - 1;
}

namespace {

// P > 0 fixes the degree at compile time (loops unroll); P == 0 is the
// general case with the degree from `degree`.
template <int P>
void basis_impl(const std::vector<double>& knots, int degree, int span, double u, int max_order,
                double ders[3][kMaxDegree + 1]) {
  // Cox-de Boor triangle, level by level. Level d holds N_{span-d+j, d}, j =
  // 0..d. Its denominators u_{span+r+1} - u_{span+r+1-d} (r = 0..d-1) serve
  // both the recurrence and the derivative formula
  //   N'_{i,d} = d (N_{i,d-1} / (u_{i+d} - u_i) - N_{i+1,d-1} / (u_{i+d+1} - u_{i+1})),
  // so each level costs d divisions; the second derivative applies the same
  // formula to the first derivatives of level p-1.
  const int p = P > 0 ? P : degree;
  const double* U = knots.data();
  u = std::clamp(u, U[p], U[knots.size() - 1 - p]);
  double level[kMaxDegree + 1];
  double next[kMaxDegree + 1];
  double inv[kMaxDegree + 1];
  double first_below[kMaxDegree + 1];  // N' of level p-1
  for (int j = 0; j <= p; ++j) first_below[j] = 0.0;
  level[0] = 1.0;
  auto derive = [&](const double* lower, int d, double* out) {
    for (int j = 0; j <= d; ++j) {
      const double left = j >= 1 ? inv[j - 1] * lower[j - 1] : 0.0;
      const double right = j <= d - 1 ? inv[j] * lower[j] : 0.0;
      out[j] = d * (left - right);
    }
  };
  for (int d = 1; d <= p; ++d) {
    for (int r = 0; r < d; ++r) {
      const double den = U[span + r + 1] - U[span + r + 1 - d];
      inv[r] = den > 0.0 ? 1.0 / den : 0.0;  // zero-length support: N is 0 there
    }
    if (d == p - 1 && max_order >= 2) derive(level, d, first_below);
    if (d == p) {
      if (max_order >= 1) derive(level, d, ders[1]);
      if (max_order >= 2) derive(first_below, d, ders[2]);
    }
    for (int j = 0; j <= d; ++j) {
      double value = 0.0;
      if (j >= 1) value += (u - U[span - d + j]) * inv[j - 1] * level[j - 1];
      if (j <= d - 1) value += (U[span + j + 1] - u) * inv[j] * level[j];
      next[j] = value;
    }
    for (int j = 0; j <= d; ++j) level[j] = next[j];
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = level[j];
}

}  // namespace

void basis_functions_with_derivatives(const std::vector<double>& knots, int degree, int span,
                                      double u, int max_order, double ders[3][kMaxDegree + 1]) {
  switch (degree) {
    case 1: return basis_impl<1>(knots, degree, span, u, max_order, ders);
    case 2: return basis_impl<2>(knots, degree, span, u, max_order, ders);
    case 3: return basis_impl<3>(knots, degree, span, u, max_order, ders);
    case 4: return basis_impl<4>(knots, degree, span, u, max_order, ders);
    case 5: return basis_impl<5>(knots, degree, span, u, max_order, ders);
    default: return basis_impl<0>(knots, degree, span, u, max_order, ders);
  }
}

void validate_knot_vector(const std::vector<double>& knots, int degree, int num_control_points,
                          const std::string& field) {
  auto fail = [&](const std::string& what) { throw InputError(field + ": " + what); };
  if (degree < 1 || degree > kMaxDegree) {
    std::ostringstream s;
    s << "degree " << degree << " is outside the supported range 1.." << kMaxDegree;
    fail(s.str());
  }
  if (num_control_points < degree + 1) {
    std::ostringstream s;
    s << num_control_points << " control points are too few for degree " << degree
      << " (at least " << degree + 1 << " needed)";
    fail(s.str());
  }
  const std::size_t expected = static_cast<std::size_t>(num_control_points + degree + 1);
  if (knots.size() != expected) {
    std::ostringstream s;
    s << "expected " << expected << " knots (" << num_control_points << " control points + degree "
      << degree << " + 1), got " << knots.size();
    fail(s.str());
  }
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) fail("knot " + std::to_string(i) + " is not a finite number");
    // Bounded so knot differences and their reciprocals stay finite
    // (docs/formats.md "Limits").
    if (std::abs(knots[i]) > limits::kMaxKnot) {
      std::ostringstream s;
      s << "knot " << i << " (" << knots[i] << ") is outside ±" << limits::kMaxKnot;
      fail(s.str());
    }
    if (i > 0 && knots[i] < knots[i - 1]) {
      std::ostringstream s;
      s << "knots decrease at index " << i << " (" << knots[i - 1] << " then " << knots[i] << ")";
      fail(s.str());
    }
  }
  // Interior multiplicity above the degree disconnects the surface.
  const int n = num_control_points;
  for (int i = degree + 1; i < n;) {
    int j = i;
    while (j + 1 < n && knots[j + 1] == knots[i]) ++j;
    if (j - i + 1 > degree) {
      std::ostringstream s;
      s << "interior knot " << knots[i] << " repeats " << (j - i + 1)
        << " times, more than the degree " << degree;
      fail(s.str());
    }
    i = j + 1;
  }
  if (!(knots[n] > knots[degree])) fail("the parameter range [u_p, u_n] is empty");
}

}  // namespace furrow
