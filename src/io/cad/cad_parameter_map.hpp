#pragma once
// Carrying (u,v) parameters of a CAD surface over to its NURBS conversion.
//
// Converting an elementary or swept surface to a rational B-spline keeps its
// shape but not its parametrisation: a circle of angle u becomes a rational
// quadratic whose parameter runs at another speed (the knots equal the angles
// only at span ends; inside a 90-degree span the two differ by up to ~0.1 rad).
// Trim curves arrive in the original (u,v), so every trim vertex must be moved
// to the (s,t) with N(s,t) = S(u,v), or the trims land beside the face.
//
// The conversions of cylinders, cones, spheres, tori, linear extrusions and
// revolutions reparametrise each direction on its own: (s,t) = (f(u), g(v))
// with f and g monotone. A product ParameterMap finds f by inverting N along
// one reference iso-line t = t_ref against S along v = v_ref (Gauss-Newton from
// a start interpolated between the pairs already known, so a dense trim loop
// costs one or two iterations per vertex), and g likewise along s = s_ref.
// Poles and apexes, where one direction collapses, need no special case: the
// reference lines avoid them and the product map extends to them continuously.
// B-spline, Bezier and approximated surfaces keep (u,v): the identity map.
//
// Whether a conversion really is a product map is not assumed: the caller
// measures max_deviation() on a grid and rejects the face when it is not.
// Inversions that miss the tolerance are counted (failures(), worst_residual()),
// never silently accepted.
#include <Eigen/Core>
#include <functional>
#include <map>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

struct ParameterMapOptions {
  int max_iterations = 50;   // Gauss-Newton steps per inversion
  double tolerance = 1e-7;   // [mm] accepted |N(s,t) - S(u,v)| of one inversion
  int scan_samples = 64;     // restart points along a reference line when Newton fails
};

class ParameterMap {
 public:
  // The original surface's point at (u,v) [mm].
  using Evaluator = std::function<Eigen::Vector3d(double u, double v)>;

  // Identity: (s,t) = (u,v).
  ParameterMap() = default;

  // Product map from `bounds` (the original's parameter rectangle that was
  // converted) to `nurbs`' domain. `nurbs` must outlive the map.
  ParameterMap(const NurbsSurface& nurbs, Evaluator original, const ParameterDomain& bounds,
               const ParameterMapOptions& options = {});

  bool is_identity() const { return nurbs_ == nullptr; }

  // (s,t) of the original's (u,v); results are cached per coordinate value.
  Eigen::Vector2d operator()(double u, double v);

  // Inversions that did not reach options.tolerance, and the largest residual
  // of any inversion [mm].
  int failures() const { return failures_; }
  double worst_residual() const { return worst_residual_; }

 private:
  struct Line {
    std::map<double, double> known;  // original parameter -> NURBS parameter
  };
  void choose_reference();
  void seed(bool along_u);
  double solve(bool along_u, double x);
  double newton(bool along_u, const Eigen::Vector3d& target, double start, double* residual) const;
  Eigen::Vector3d line_point(bool along_u, double p, Eigen::Vector3d* tangent) const;

  const NurbsSurface* nurbs_ = nullptr;
  Evaluator original_;
  ParameterDomain bounds_;
  ParameterMapOptions options_;
  double u_ref_ = 0, v_ref_ = 0, s_ref_ = 0, t_ref_ = 0;
  Line u_line_, v_line_;
  int failures_ = 0;
  double worst_residual_ = 0;
};

// Largest |N(map(u,v)) - S(u,v)| [mm] over an n x n grid spanning `bounds`
// (edges included), n >= 2.
double max_deviation(const NurbsSurface& nurbs, ParameterMap& map,
                     const ParameterMap::Evaluator& original, const ParameterDomain& bounds, int n);

}  // namespace furrow
