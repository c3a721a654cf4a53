#pragma once
// Local foot-point solves on one surface: minimise phi(u,v) = |S(u,v) - q|^2 / 2
// over a parameter box, or along a straight (u,v) segment.
//
// These are the building blocks of ClosestPointFinder (closest_point.hpp),
// which decides where to run them so that the global minimum is found. On
// their own they find *a* local minimum near the seed.
//
// Box solve: projected Newton with an active set (Bertsekas): a parameter at
// a bound whose gradient points out of the box is held there, the others take
// a Newton step, so a minimum on an edge is approached along the edge and a
// corner is recognised as such. Where the Hessian
//   H = J^T J + [r.Suu r.Suv; r.Suv r.Svv],   r = S - q,
// is not positive definite (q beyond the centre of curvature, near the
// evolute) the Gauss-Newton matrix J^T J is used instead, which still gives a
// descent direction; a tiny Levenberg term keeps it invertible at a collapsed
// edge (Su = 0). Armijo backtracking guarantees descent.
//
// Units: millimetres; parameters in the surface's own (u,v).
#include <Eigen/Core>

#include "geometry/bezier_patch.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/nurbs_surface.hpp"

namespace furrow {

struct LocalFoot {
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double squared_distance = 0;  // |S(uv) - q|^2 [mm^2]
  // Su and Sv at the foot (box solve; zero from the segment solve), so that
  // the caller gets the normal without another evaluation.
  Eigen::Vector3d su = Eigen::Vector3d::Zero(), sv = Eigen::Vector3d::Zero();
  int iterations = 0;
  bool converged = false;
};

// Minimum of |S - q| over the box [lo, hi] (lo <= hi componentwise) from
// `seed` (clamped into the box). Uses max_newton_iterations,
// max_line_search_halvings, step_tolerance and stall_tolerance of `options`.
LocalFoot foot_point_in_box(const NurbsSurface& surface, const Eigen::Vector3d& q,
                            const Eigen::Vector2d& seed, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi, const ClosestPointOptions& options);

// The same over a Bezier piece (the box must lie within the patch's box):
// the numbers of the B-spline surface it was cut from, evaluated faster.
LocalFoot foot_point_in_box(const BezierPatch& patch, const Eigen::Vector3d& q,
                            const Eigen::Vector2d& seed, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi, const ClosestPointOptions& options);

// Minimum of |S(a + t (b - a)) - q| over t in [0, 1]: the best of
// trim_samples_per_segment + 1 evenly spaced samples seeds a bounded 1-D
// Newton solve.
LocalFoot foot_point_on_segment(const NurbsSurface& surface, const Eigen::Vector3d& q,
                                const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                const ClosestPointOptions& options);

}  // namespace furrow
