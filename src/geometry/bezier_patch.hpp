#pragma once
// The piece of a NURBS surface over a parameter box that lies inside one
// knot span in each direction, in Bernstein (Bezier) form.
//
// Why: inside one span a NURBS surface is a single rational polynomial, so
// its Bezier control net over the box describes it exactly, and evaluating
// it needs neither a knot search nor the Cox-de Boor recurrence (with its
// divisions) - only the Bernstein triangle on [0, 1]. The closest-point
// search evaluates the surface millions of times inside small cells; there
// this is about twice as fast as NurbsSurface::evaluate for the same numbers.
//
// Construction is exact up to rounding: each control point is a blossom of
// the span's polynomial, computed by de Boor's algorithm with the box's end
// parameters as arguments (Ramshaw's blossoming; every step is a convex
// combination, so it is as stable as evaluation itself). Derivatives are
// taken with respect to the surface's own (u, v), not the box's local
// coordinates, and combined by the same quotient rule as
// NurbsSurface::evaluate (rational_derivatives.hpp).
//
// Units: millimetres; parameters in the surface's (u, v). Parameters outside
// the box are clamped to it.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

class BezierPatch {
 public:
  // The piece of `surface` over [lo, hi], or nothing when the box crosses
  // an interior knot (the surface is then not one polynomial over it) or
  // is empty. The box must lie in the surface's domain.
  static std::optional<BezierPatch> within_span(const NurbsSurface& surface,
                                                const Eigen::Vector2d& lo,
                                                const Eigen::Vector2d& hi);

  int degree_u() const { return p_; }
  int degree_v() const { return q_; }
  const Eigen::Vector2d& lo() const { return lo_; }
  const Eigen::Vector2d& hi() const { return hi_; }
  // Homogeneous control point (w x, w y, w z, w), i along u, j along v.
  const Eigen::Vector4d& control_point(int i, int j) const { return net_[i * (q_ + 1) + j]; }

  // Point and derivatives up to `order` (0, 1 or 2), as NurbsSurface::evaluate.
  SurfaceDerivatives evaluate(double u, double v, int order = 2) const {
    return evaluator_(*this, u, v, order);
  }
  Eigen::Vector3d point(double u, double v) const { return evaluate(u, v, 0).S; }

 private:
  using Evaluator = SurfaceDerivatives (*)(const BezierPatch&, double, double, int);
  template <int P, int Q>
  static SurfaceDerivatives evaluate_fixed(const BezierPatch& patch, double u, double v, int order);
  static Evaluator evaluator_for(int p, int q);

  BezierPatch() = default;
  Evaluator evaluator_ = nullptr;
  int p_ = 0, q_ = 0;
  Eigen::Vector2d lo_, hi_, inv_size_;
  std::vector<Eigen::Vector4d> net_;  // (p+1) x (q+1), row i along u
};

// Bernstein polynomials of degree p (1 <= p <= kMaxDegree) at t in [0, 1]
// and their derivatives up to max_order (<= 2): ders[k][i] is the k-th
// derivative of B_i^p. Exposed for tests.
void bernstein_with_derivatives(int p, double t, int max_order, double ders[3][16]);

}  // namespace furrow
