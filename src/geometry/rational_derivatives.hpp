#pragma once
// The two halves of evaluating a rational tensor-product surface from the
// basis functions of one parameter box: the homogeneous sums
//   A_ab = d^(a+b)/du^a dv^b  sum_i sum_j Nu_i(u) Nv_j(v) Pw_ij,   a + b <= 2,
// over a (p+1) x (q+1) net of homogeneous points Pw = (w x, w y, w z, w), and
// the quotient rule that turns them into S and its derivatives (Piegl &
// Tiller, "The NURBS Book", eq. 4.20).
//
// Shared by the B-spline evaluator (nurbs_surface.hpp: Cox-de Boor basis over
// the whole knot vector) and the Bezier pieces of the closest-point search
// (bezier_patch.hpp: Bernstein basis over one cell), so both differentiate
// the same way and only the basis differs.
#include <Eigen/Core>

#include "geometry/bspline_basis.hpp"
#include "geometry/nurbs_surface.hpp"

namespace furrow {

// Basis values and derivatives as filled by basis_functions_with_derivatives:
// ders[k][i] is the k-th derivative of the i-th non-zero basis function.
using BasisDerivatives = double[3][kMaxDegree + 1];

// A[0] = A, A[1] = A_u, A[2] = A_v, A[3] = A_uu, A[4] = A_uv, A[5] = A_vv
// (entries above Order are zero). `net` points at Pw_00 of the box; rows
// (fixed i) are `stride` apart. The order is a template argument so that the
// inner loops carry no branches; so may the degrees be (P, Q >= 0: fixed,
// -1: p and q at run time), so that the loops unroll.
template <int Order, int P = -1, int Q = -1>
void homogeneous_sums(const Eigen::Vector4d* net, int stride, int p_run, int q_run,
                      const BasisDerivatives& Nu, const BasisDerivatives& Nv, Eigen::Vector4d A[6]) {
  const int p = P >= 0 ? P : p_run, q = Q >= 0 ? Q : q_run;
  for (int k = 0; k < 6; ++k) A[k].setZero();
  for (int i = 0; i <= p; ++i) {
    const Eigen::Vector4d* row = net + i * stride;
    Eigen::Vector4d T0 = Eigen::Vector4d::Zero(), T1 = T0, T2 = T0;
    for (int j = 0; j <= q; ++j) {
      T0 += Nv[0][j] * row[j];
      if constexpr (Order >= 1) T1 += Nv[1][j] * row[j];
      if constexpr (Order >= 2) T2 += Nv[2][j] * row[j];
    }
    A[0] += Nu[0][i] * T0;
    if constexpr (Order >= 1) {
      A[1] += Nu[1][i] * T0;  // u
      A[2] += Nu[0][i] * T1;  // v
    }
    if constexpr (Order >= 2) {
      A[3] += Nu[2][i] * T0;  // uu
      A[4] += Nu[1][i] * T1;  // uv
      A[5] += Nu[0][i] * T2;  // vv
    }
  }
}

// Sums of the requested order (0, 1 or 2) dispatched to the template above.
inline void homogeneous_sums(int order, const Eigen::Vector4d* net, int stride, int p, int q,
                             const BasisDerivatives& Nu, const BasisDerivatives& Nv,
                             Eigen::Vector4d A[6]) {
  if (order <= 0) homogeneous_sums<0>(net, stride, p, q, Nu, Nv, A);
  if (order == 1) homogeneous_sums<1>(net, stride, p, q, Nu, Nv, A);
  if (order >= 2) homogeneous_sums<2>(net, stride, p, q, Nu, Nv, A);
}

// S and its derivatives up to `order` from the homogeneous sums: the quotient
// rule on A = w S, differentiated term by term.
inline SurfaceDerivatives quotient_rule(const Eigen::Vector4d A[6], int order) {
  SurfaceDerivatives d;
  const double inv_w = 1.0 / A[0].w();
  d.S = A[0].head<3>() * inv_w;
  if (order < 1) return d;
  d.Su = (A[1].head<3>() - A[1].w() * d.S) * inv_w;
  d.Sv = (A[2].head<3>() - A[2].w() * d.S) * inv_w;
  if (order < 2) return d;
  d.Suu = (A[3].head<3>() - 2.0 * A[1].w() * d.Su - A[3].w() * d.S) * inv_w;
  d.Suv = (A[4].head<3>() - A[1].w() * d.Sv - A[2].w() * d.Su - A[4].w() * d.S) * inv_w;
  d.Svv = (A[5].head<3>() - 2.0 * A[2].w() * d.Sv - A[5].w() * d.S) * inv_w;
  return d;
}

}  // namespace furrow
