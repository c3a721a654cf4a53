#include "geometry/bezier_patch.hpp"

#include <algorithm>

#include "geometry/bspline_basis.hpp"
#include "geometry/rational_derivatives.hpp"

namespace furrow {

static_assert(kMaxDegree + 1 == 16, "bernstein_with_derivatives' array size follows kMaxDegree");

namespace {

// Row n of the Bernstein triangle from row n-1 (n entries): B^n_i =
// (1-t) B^(n-1)_i + t B^(n-1)_(i-1).
inline void raise_degree(const double* below, int n, double t, double* row) {
  const double s = 1.0 - t;
  row[0] = s * below[0];
  for (int i = 1; i < n; ++i) row[i] = s * below[i] + t * below[i - 1];
  row[n] = t * below[n - 1];
}

// The basis of degree P (fixed at compile time where P >= 0, so the loops
// unroll; p at run time otherwise) and its derivatives: the first from the
// row of degree p-1, the second from the row of degree p-2.
template <int P>
void bernstein(int p_run, double t, int max_order, double ders[3][16]) {
  const int p = P >= 0 ? P : p_run;
  double rows[kMaxDegree + 1][kMaxDegree + 1];
  rows[0][0] = 1.0;
  for (int n = 1; n <= p; ++n) raise_degree(rows[n - 1], n, t, rows[n]);
  for (int i = 0; i <= p; ++i) ders[0][i] = rows[p][i];
  if (max_order < 1) return;
  const double* r1 = rows[p - 1];
  ders[1][0] = -p * r1[0];
  for (int i = 1; i < p; ++i) ders[1][i] = p * (r1[i - 1] - r1[i]);
  ders[1][p] = p * r1[p - 1];
  if (max_order < 2) return;
  if (p < 2) {
    for (int i = 0; i <= p; ++i) ders[2][i] = 0;
    return;
  }
  const double* r2 = rows[p - 2];
  const double c = p * (p - 1);
  for (int i = 0; i <= p; ++i) {
    const double a = i >= 2 ? r2[i - 2] : 0.0, b = i >= 1 && i - 1 <= p - 2 ? r2[i - 1] : 0.0,
                 d = i <= p - 2 ? r2[i] : 0.0;
    ders[2][i] = c * (a - 2.0 * b + d);
  }
}

}  // namespace

void bernstein_with_derivatives(int p, double t, int max_order, double ders[3][16]) {
  bernstein<-1>(p, t, max_order, ders);
}

namespace {

// Span k of `knots` (degree p, n control points) holding [a, b], or -1.
int span_holding(const std::vector<double>& knots, int p, int n, double a, double b) {
  const int k = find_span(knots, p, n, 0.5 * (a + b));
  return knots[k] <= a && b <= knots[k + 1] && a < b ? k : -1;
}

// Blossom of the span-k polynomial with control points d[0..p] (P_(k-p) ..
// P_k) at the arguments t[0..p-1]: de Boor's algorithm with the r-th
// argument at level r. Overwrites d.
Eigen::Vector4d blossom(const std::vector<double>& U, int p, int k, Eigen::Vector4d* d,
                        const double* t) {
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double left = U[j + k - p], right = U[j + 1 + k - r];  // right > left: span k is not empty
      const double alpha = (t[r - 1] - left) / (right - left);
      d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
    }
  return d[p];
}

// The p+1 Bezier control points over [a, b] of the span-k polynomial with
// B-spline control points P_(k-p) .. P_k (given as `points`, p+1 of them).
void bezier_points(const std::vector<double>& U, int p, int k, const Eigen::Vector4d* points,
                   double a, double b, Eigen::Vector4d* out) {
  Eigen::Vector4d d[kMaxDegree + 1];
  double t[kMaxDegree];
  for (int i = 0; i <= p; ++i) {
    for (int r = 0; r < p; ++r) t[r] = r < p - i ? a : b;
    std::copy(points, points + p + 1, d);
    out[i] = blossom(U, p, k, d, t);
  }
}

}  // namespace

std::optional<BezierPatch> BezierPatch::within_span(const NurbsSurface& surface,
                                                    const Eigen::Vector2d& lo,
                                                    const Eigen::Vector2d& hi) {
  const int p = surface.degree_u(), q = surface.degree_v();
  const int ku = span_holding(surface.knots_u(), p, surface.num_u(), lo.x(), hi.x());
  const int kv = span_holding(surface.knots_v(), q, surface.num_v(), lo.y(), hi.y());
  if (ku < 0 || kv < 0) return std::nullopt;
  auto homogeneous = [&](int i, int j) {
    const double w = surface.weight(i, j);
    const Eigen::Vector3d wp = w * surface.control_point(i, j);
    return Eigen::Vector4d(wp.x(), wp.y(), wp.z(), w);
  };
  // Along u for each of the q+1 rows of the v span, then along v.
  std::vector<Eigen::Vector4d> along_u((p + 1) * (q + 1));  // [i * (q+1) + j]
  Eigen::Vector4d column[kMaxDegree + 1], bezier[kMaxDegree + 1];
  for (int k = 0; k <= kMaxDegree; ++k) column[k] = bezier[k] = Eigen::Vector4d::Zero();
  for (int j = 0; j <= q; ++j) {
    for (int i = 0; i <= p; ++i) column[i] = homogeneous(ku - p + i, kv - q + j);
    bezier_points(surface.knots_u(), p, ku, column, lo.x(), hi.x(), bezier);
    for (int i = 0; i <= p; ++i) along_u[i * (q + 1) + j] = bezier[i];
  }
  BezierPatch patch;
  patch.p_ = p;
  patch.q_ = q;
  patch.lo_ = lo;
  patch.hi_ = hi;
  patch.inv_size_ = (hi - lo).cwiseInverse();
  patch.evaluator_ = evaluator_for(p, q);
  patch.net_.resize(along_u.size());
  for (int i = 0; i <= p; ++i) {
    bezier_points(surface.knots_v(), q, kv, &along_u[i * (q + 1)], lo.y(), hi.y(), bezier);
    std::copy(bezier, bezier + q + 1, &patch.net_[i * (q + 1)]);
  }
  return patch;
}

template <int P, int Q>
SurfaceDerivatives BezierPatch::evaluate_fixed(const BezierPatch& patch, double u, double v,
                                               int order) {
  const int p = P >= 0 ? P : patch.p_, q = Q >= 0 ? Q : patch.q_;
  const Eigen::Vector2d& lo = patch.lo_;
  const Eigen::Vector2d& inv = patch.inv_size_;
  const double s = std::clamp((u - lo.x()) * inv.x(), 0.0, 1.0);
  const double t = std::clamp((v - lo.y()) * inv.y(), 0.0, 1.0);
  double Nu[3][kMaxDegree + 1], Nv[3][kMaxDegree + 1];
  bernstein<P>(p, s, order, Nu);
  bernstein<Q>(q, t, order, Nv);
  // d/du = d/ds / (hi - lo): the derivatives are in the surface's parameters.
  if (order >= 1) {
    for (int i = 0; i <= p; ++i) Nu[1][i] *= inv.x();
    for (int j = 0; j <= q; ++j) Nv[1][j] *= inv.y();
  }
  if (order >= 2) {
    for (int i = 0; i <= p; ++i) Nu[2][i] *= inv.x() * inv.x();
    for (int j = 0; j <= q; ++j) Nv[2][j] *= inv.y() * inv.y();
  }
  Eigen::Vector4d A[6];
  const Eigen::Vector4d* net = patch.net_.data();
  if (order <= 0) homogeneous_sums<0, P, Q>(net, q + 1, p, q, Nu, Nv, A);
  if (order == 1) homogeneous_sums<1, P, Q>(net, q + 1, p, q, Nu, Nv, A);
  if (order >= 2) homogeneous_sums<2, P, Q>(net, q + 1, p, q, Nu, Nv, A);
  return quotient_rule(A, order);
}

BezierPatch::Evaluator BezierPatch::evaluator_for(int p, int q) {
  // The degrees CAD systems write (1 to 3, and 5) get unrolled loops.
#define FURROW_BEZIER_CASE(P, Q) \
  if (p == P && q == Q) return &evaluate_fixed<P, Q>;
#define FURROW_BEZIER_ROW(P) \
  FURROW_BEZIER_CASE(P, 1) FURROW_BEZIER_CASE(P, 2) FURROW_BEZIER_CASE(P, 3) FURROW_BEZIER_CASE(P, 5)
  FURROW_BEZIER_ROW(1) FURROW_BEZIER_ROW(2) FURROW_BEZIER_ROW(3) FURROW_BEZIER_ROW(5)
#undef FURROW_BEZIER_ROW
#undef FURROW_BEZIER_CASE
  return &evaluate_fixed<-1, -1>;
}

}  // namespace furrow
