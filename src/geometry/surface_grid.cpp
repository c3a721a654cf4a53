#include "geometry/surface_grid.hpp"

#include <algorithm>

#include "geometry/bspline_basis.hpp"
#include "geometry/rational_derivatives.hpp"

namespace furrow {

namespace {

// Basis rows are stored as 3 x stride doubles (value, 1st, 2nd derivative).
constexpr int kBasisStride = kMaxDegree + 1;

// T_c for control columns c = first..last: the v basis of this row applied to
// the q+1 control points of column c in the row's v span. Same expression and
// order as NurbsSurface::evaluate's inner loop. Q > 0 fixes the loop length at
// compile time; Q == 0 means "use q".
template <int Q, int Order>
void contract_columns(const Eigen::Vector4d* net, int num_v, int first, int last, int q, int span_v,
                      const double Nv[3][kMaxDegree + 1], Eigen::Vector4d* T) {
  const int len = Q > 0 ? Q : q;
  for (int c = first; c <= last; ++c) {
    const Eigen::Vector4d* row = net + static_cast<std::size_t>(c) * num_v + (span_v - len);
    Eigen::Vector4d T0 = Eigen::Vector4d::Zero(), T1 = T0, T2 = T0;
    for (int j = 0; j <= len; ++j) {
      T0 += Nv[0][j] * row[j];
      if constexpr (Order >= 1) T1 += Nv[1][j] * row[j];
      if constexpr (Order >= 2) T2 += Nv[2][j] * row[j];
    }
    Eigen::Vector4d* out = T + static_cast<std::size_t>(c - first) * (Order + 1);
    out[0] = T0;
    if constexpr (Order >= 1) out[1] = T1;
    if constexpr (Order >= 2) out[2] = T2;
  }
}

// Every grid point of the row: contract p+1 column sums with the point's u
// basis. P > 0 fixes the loop length at compile time; P == 0 means "use p".
template <int P, int Order>
void contract_points(const Eigen::Vector4d* T, int first, int p, const int* span_u,
                     const double* basis_u, int nu, SurfaceDerivatives* out) {
  const int len = P > 0 ? P : p;
  for (int i = 0; i < nu; ++i) {
    const double* Nu0 = basis_u + static_cast<std::size_t>(i) * 3 * kBasisStride;
    const double* Nu1 = Nu0 + kBasisStride;
    const double* Nu2 = Nu1 + kBasisStride;
    const Eigen::Vector4d* col = T + static_cast<std::size_t>(span_u[i] - len - first) * (Order + 1);
    Eigen::Vector4d A[6];
    for (int k = 0; k < 6; ++k) A[k].setZero();
    for (int a = 0; a <= len; ++a) {
      const Eigen::Vector4d* t = col + a * (Order + 1);
      A[0] += Nu0[a] * t[0];
      if constexpr (Order >= 1) {
        A[1] += Nu1[a] * t[0];
        A[2] += Nu0[a] * t[1];
      }
      if constexpr (Order >= 2) {
        A[3] += Nu2[a] * t[0];
        A[4] += Nu1[a] * t[1];
        A[5] += Nu0[a] * t[2];
      }
    }
    out[i] = quotient_rule(A, Order);
  }
}

template <int Order>
void contract_columns_for(int q, const Eigen::Vector4d* net, int num_v, int first, int last,
                          int span_v, const double Nv[3][kMaxDegree + 1], Eigen::Vector4d* T) {
  switch (q) {
    case 1: return contract_columns<1, Order>(net, num_v, first, last, q, span_v, Nv, T);
    case 2: return contract_columns<2, Order>(net, num_v, first, last, q, span_v, Nv, T);
    case 3: return contract_columns<3, Order>(net, num_v, first, last, q, span_v, Nv, T);
    case 4: return contract_columns<4, Order>(net, num_v, first, last, q, span_v, Nv, T);
    case 5: return contract_columns<5, Order>(net, num_v, first, last, q, span_v, Nv, T);
    default: return contract_columns<0, Order>(net, num_v, first, last, q, span_v, Nv, T);
  }
}

template <int Order>
void contract_points_for(int p, const Eigen::Vector4d* T, int first, const int* span_u,
                         const double* basis_u, int nu, SurfaceDerivatives* out) {
  switch (p) {
    case 1: return contract_points<1, Order>(T, first, p, span_u, basis_u, nu, out);
    case 2: return contract_points<2, Order>(T, first, p, span_u, basis_u, nu, out);
    case 3: return contract_points<3, Order>(T, first, p, span_u, basis_u, nu, out);
    case 4: return contract_points<4, Order>(T, first, p, span_u, basis_u, nu, out);
    case 5: return contract_points<5, Order>(T, first, p, span_u, basis_u, nu, out);
    default: return contract_points<0, Order>(T, first, p, span_u, basis_u, nu, out);
  }
}

}  // namespace

SurfaceGrid::SurfaceGrid(const NurbsSurface& surface, std::vector<double> u, std::vector<double> v,
                         int order)
    : surface_(&surface), u_(std::move(u)), v_(std::move(v)), order_(std::clamp(order, 0, 2)) {
  const int p = surface.degree_u();
  span_u_.resize(u_.size());
  basis_u_.assign(u_.size() * 3 * kBasisStride, 0.0);
  // The homogeneous net exactly as NurbsSurface builds it (w x, w y, w z, w).
  net_.resize(static_cast<std::size_t>(surface.num_u()) * surface.num_v());
  for (int a = 0; a < surface.num_u(); ++a)
    for (int b = 0; b < surface.num_v(); ++b) {
      const double w = surface.weight(a, b);
      net_[static_cast<std::size_t>(a) * surface.num_v() + b] << w * surface.control_point(a, b), w;
    }
  first_column_ = surface.num_u();
  last_column_ = -1;
  for (std::size_t i = 0; i < u_.size(); ++i) {
    // find_span and the basis routine clamp u to the domain themselves.
    const int span = find_span(surface.knots_u(), p, surface.num_u(), u_[i]);
    span_u_[i] = span;
    double ders[3][kMaxDegree + 1];
    basis_functions_with_derivatives(surface.knots_u(), p, span, u_[i], order_, ders);
    for (int k = 0; k <= order_; ++k)
      std::copy(ders[k], ders[k] + p + 1, basis_u_.begin() + (i * 3 + k) * kBasisStride);
    first_column_ = std::min(first_column_, span - p);
    last_column_ = std::max(last_column_, span);
  }
}

void SurfaceGrid::evaluate_row(int j, SurfaceDerivatives* out, SurfaceGridScratch& scratch) const {
  const NurbsSurface& s = *surface_;
  if (u_.empty()) return;
  const int p = s.degree_u(), q = s.degree_v();
  const int span_v = find_span(s.knots_v(), q, s.num_v(), v_[j]);
  double Nv[3][kMaxDegree + 1];
  basis_functions_with_derivatives(s.knots_v(), q, span_v, v_[j], order_, Nv);
  const std::size_t need =
      static_cast<std::size_t>(last_column_ - first_column_ + 1) * (order_ + 1);
  if (scratch.columns.size() < need) scratch.columns.resize(need);
  Eigen::Vector4d* T = scratch.columns.data();
  const Eigen::Vector4d* net = net_.data();
  const int nu = static_cast<int>(u_.size());
  switch (order_) {
    case 0:
      contract_columns_for<0>(q, net, s.num_v(), first_column_, last_column_, span_v, Nv, T);
      contract_points_for<0>(p, T, first_column_, span_u_.data(), basis_u_.data(), nu, out);
      break;
    case 1:
      contract_columns_for<1>(q, net, s.num_v(), first_column_, last_column_, span_v, Nv, T);
      contract_points_for<1>(p, T, first_column_, span_u_.data(), basis_u_.data(), nu, out);
      break;
    default:
      contract_columns_for<2>(q, net, s.num_v(), first_column_, last_column_, span_v, Nv, T);
      contract_points_for<2>(p, T, first_column_, span_u_.data(), basis_u_.data(), nu, out);
      break;
  }
}

}  // namespace furrow
