#pragma once
// Rational B-spline (NURBS) surface patch of any degree up to kMaxDegree,
// clamped or unclamped knot vectors.
//
// Units: millimetres (the part readers convert). Control point (i, j) is index
// i along u and j along v, as in the part JSON. Derivatives are exact: the
// homogeneous surface A(u,v) = sum N_i N_j w_ij P_ij and w(u,v) are
// differentiated analytically and combined by the quotient rule (Piegl &
// Tiller eq. 4.20), never by finite differences.
//
// Construction validates everything (knot counts, monotone knots, finite
// numbers, positive weights) and throws InputError naming the offending field,
// so an existing NurbsSurface is always evaluable. Parameters outside the
// domain are clamped to it.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace furrow {

// Point and partial derivatives of a surface at (u, v). Entries above the
// requested order are left zero.
struct SurfaceDerivatives {
  Eigen::Vector3d S = Eigen::Vector3d::Zero();
  Eigen::Vector3d Su = Eigen::Vector3d::Zero();
  Eigen::Vector3d Sv = Eigen::Vector3d::Zero();
  Eigen::Vector3d Suu = Eigen::Vector3d::Zero();
  Eigen::Vector3d Suv = Eigen::Vector3d::Zero();
  Eigen::Vector3d Svv = Eigen::Vector3d::Zero();
};

// Closed parameter rectangle [u0,u1] x [v0,v1].
struct ParameterDomain {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  double width_u() const { return u1 - u0; }
  double width_v() const { return v1 - v0; }
};

class NurbsSurface {
 public:
  // control_points[i][j], weights[i][j] (empty = all 1). `field` prefixes error
  // messages (e.g. "part.json: faces[2]") so they point at the source.
  NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
               const std::vector<std::vector<Eigen::Vector3d>>& control_points,
               const std::vector<std::vector<double>>& weights = {},
               const std::string& field = "surface");

  int degree_u() const { return degree_u_; }
  int degree_v() const { return degree_v_; }
  int num_u() const { return num_u_; }  // control points along u
  int num_v() const { return num_v_; }
  const std::vector<double>& knots_u() const { return knots_u_; }
  const std::vector<double>& knots_v() const { return knots_v_; }
  const Eigen::Vector3d& control_point(int i, int j) const { return points_[index(i, j)]; }
  double weight(int i, int j) const { return homogeneous_[index(i, j)].w(); }
  bool is_rational() const { return rational_; }
  const ParameterDomain& domain() const { return domain_; }

  // Axis-aligned box of the control net; contains the surface (convex hull
  // property, positive weights). Kept from construction: tolerances scaled
  // by the part's size ask for it at every evaluation of the geometry.
  const Eigen::AlignedBox3d& control_box() const { return control_box_; }

  // Point only.
  Eigen::Vector3d point(double u, double v) const;
  // Point and derivatives up to `order` (0, 1 or 2) in each direction,
  // mixed Suv included when order == 2.
  SurfaceDerivatives evaluate(double u, double v, int order = 2) const;

 private:
  int index(int i, int j) const { return i * num_v_ + j; }

  int degree_u_, degree_v_, num_u_ = 0, num_v_ = 0;
  std::vector<double> knots_u_, knots_v_;
  std::vector<Eigen::Vector4d> homogeneous_;  // (w x, w y, w z, w), row-major i*num_v + j
  std::vector<Eigen::Vector3d> points_;       // as given, so that files round-trip exactly
  bool rational_ = false;
  ParameterDomain domain_;
  Eigen::AlignedBox3d control_box_;
};

}  // namespace furrow
