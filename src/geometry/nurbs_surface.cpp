#include "geometry/nurbs_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry/bspline_basis.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"

namespace furrow {

namespace {
constexpr double kMinDomainWidth = 1e-9;
}  // namespace

NurbsSurface::NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u,
                           std::vector<double> knots_v,
                           const std::vector<std::vector<Eigen::Vector3d>>& control_points,
                           const std::vector<std::vector<double>>& weights,
                           const std::string& field)
    : degree_u_(degree_u),
      degree_v_(degree_v),
      knots_u_(std::move(knots_u)),
      knots_v_(std::move(knots_v)) {
  if (control_points.empty()) throw InputError(field + ".control_points: the control net is empty");
  num_u_ = static_cast<int>(control_points.size());
  num_v_ = static_cast<int>(control_points[0].size());
  if (num_v_ == 0) throw InputError(field + ".control_points[0]: the row is empty");
  for (int i = 0; i < num_u_; ++i) {
    if (static_cast<int>(control_points[i].size()) != num_v_) {
      std::ostringstream s;
      s << field << ".control_points[" << i << "]: has " << control_points[i].size()
        << " points, row 0 has " << num_v_ << " (the net must be rectangular)";
      throw InputError(s.str());
    }
  }
  validate_knot_vector(knots_u_, degree_u_, num_u_, field + ".knots_u");
  validate_knot_vector(knots_v_, degree_v_, num_v_, field + ".knots_v");
  const bool has_weights = !weights.empty();
  if (has_weights && static_cast<int>(weights.size()) != num_u_) {
    std::ostringstream s;
    s << field << ".weights: has " << weights.size() << " rows, the control net has " << num_u_;
    throw InputError(s.str());
  }
  homogeneous_.resize(static_cast<std::size_t>(num_u_) * num_v_);
  double w_min = std::numeric_limits<double>::infinity(), w_max = 0;
  points_.resize(homogeneous_.size());
  for (int i = 0; i < num_u_; ++i) {
    if (has_weights && static_cast<int>(weights[i].size()) != num_v_) {
      std::ostringstream s;
      s << field << ".weights[" << i << "]: has " << weights[i].size() << " entries, expected "
        << num_v_;
      throw InputError(s.str());
    }
    for (int j = 0; j < num_v_; ++j) {
      const Eigen::Vector3d& p = control_points[i][j];
      const std::string p_where =
          field + ".control_points[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      static const char* kAxis[] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) limits::check_coordinate(p[k], p_where + " " + kAxis[k]);
      const double w = has_weights ? weights[i][j] : 1.0;
      const std::string w_where =
          field + ".weights[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (!std::isfinite(w) || !(w > 0.0)) {
        std::ostringstream s;
        s << w_where << ": " << w << " is not a positive finite weight";
        throw InputError(s.str());
      }
      if (w < limits::kMinWeight || w > limits::kMaxWeight) {
        std::ostringstream s;
        s << w_where << ": " << w << " is outside the weight range [" << limits::kMinWeight
          << ", " << limits::kMaxWeight << "] (docs/formats.md \"Limits\")";
        throw InputError(s.str());
      }
      w_min = std::min(w_min, w);
      w_max = std::max(w_max, w);
      if (w_max > limits::kMaxWeightRatio * w_min) {
        std::ostringstream s;
        s << w_where << ": weights from " << w_min << " to " << w_max << " differ by more than a factor "
          << limits::kMaxWeightRatio << " (docs/formats.md \"Limits\")";
        throw InputError(s.str());
      }
      if (w != 1.0) rational_ = true;
      // The product evaluation sums: finite by the ranges above, checked anyway.
      if (!(w * p).allFinite())
        throw InputError(w_where + ": weight times control point is not a finite number");
      homogeneous_[index(i, j)] << w * p, w;
      points_[index(i, j)] = p;
    }
  }
  domain_ = {knots_u_[degree_u_], knots_u_[num_u_], knots_v_[degree_v_], knots_v_[num_v_]};
  // A vanishing parameter width makes the derivatives overflow.
  if (!(domain_.width_u() >= kMinDomainWidth) || !(domain_.width_v() >= kMinDomainWidth)) {
    std::ostringstream s;
    s << field << ": the parameter domain is " << domain_.width_u() << " x " << domain_.width_v()
      << " wide, below " << kMinDomainWidth << " (docs/formats.md \"Limits\")";
    throw InputError(s.str());
  }
}

Eigen::AlignedBox3d NurbsSurface::control_box() const {
  Eigen::AlignedBox3d box;
  for (const auto& p : points_) box.extend(p);
  return box;
}

Eigen::Vector3d NurbsSurface::point(double u, double v) const { return evaluate(u, v, 0).S; }

namespace {

// Homogeneous sums A_ab = d^(a+b) A / du^a dv^b for a + b <= Order, with the
// order fixed at compile time so the inner loops carry no branches.
template <int Order>
void homogeneous_sums(const Eigen::Vector4d* net, int stride, int p, int q,
                      const double Nu[3][kMaxDegree + 1], const double Nv[3][kMaxDegree + 1],
                      Eigen::Vector4d A[6]) {
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

}  // namespace

SurfaceDerivatives NurbsSurface::evaluate(double u, double v, int order) const {
  order = std::clamp(order, 0, 2);
  const int p = degree_u_, q = degree_v_;
  const int su = find_span(knots_u_, p, num_u_, u);
  const int sv = find_span(knots_v_, q, num_v_, v);
  double Nu[3][kMaxDegree + 1];
  double Nv[3][kMaxDegree + 1];
  basis_functions_with_derivatives(knots_u_, p, su, u, order, Nu);
  basis_functions_with_derivatives(knots_v_, q, sv, v, order, Nv);

  Eigen::Vector4d A[6];
  const Eigen::Vector4d* net = &homogeneous_[index(su - p, sv - q)];
  if (order == 0) homogeneous_sums<0>(net, num_v_, p, q, Nu, Nv, A);
  if (order == 1) homogeneous_sums<1>(net, num_v_, p, q, Nu, Nv, A);
  if (order == 2) homogeneous_sums<2>(net, num_v_, p, q, Nu, Nv, A);

  SurfaceDerivatives d;
  const double inv_w = 1.0 / A[0].w();
  d.S = A[0].head<3>() * inv_w;
  if (order < 1) return d;
  // Quotient rule on A = w S, differentiated term by term (P&T eq. 4.20).
  d.Su = (A[1].head<3>() - A[1].w() * d.S) * inv_w;
  d.Sv = (A[2].head<3>() - A[2].w() * d.S) * inv_w;
  if (order < 2) return d;
  d.Suu = (A[3].head<3>() - 2.0 * A[1].w() * d.Su - A[3].w() * d.S) * inv_w;
  d.Suv = (A[4].head<3>() - A[1].w() * d.Sv - A[2].w() * d.Su - A[4].w() * d.S) * inv_w;
  d.Svv = (A[5].head<3>() - 2.0 * A[2].w() * d.Sv - A[5].w() * d.S) * inv_w;
  return d;
}

}  // namespace furrow
