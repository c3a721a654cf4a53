#include "geometry/nurbs_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry/bspline_basis.hpp"
#include "geometry/rational_derivatives.hpp"
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
      control_box_.extend(p);
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


Eigen::Vector3d NurbsSurface::point(double u, double v) const { return evaluate(u, v, 0).S; }

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
  homogeneous_sums(order, net, num_v_, p, q, Nu, Nv, A);
  return quotient_rule(A, order);
}

}  // namespace furrow
