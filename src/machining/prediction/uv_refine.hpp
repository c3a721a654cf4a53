#pragma once
// Refining an extremum found on a (u,v) sample grid: alternate unimodal
// searches along u and along v, each within a half-step box around the
// current point and clipped to the face's parameter domain.
//
// Why coordinate searches and not Newton: the costs refined this way (the
// z-map's error along the normal, a rapid's overcut) are piecewise smooth
// and only sampled, with no derivatives; within one sample step of the best
// sample they are unimodal along each parameter, which is all a bracketing
// search needs (docs/architecture.md "Machining error between contact points").
#include <Eigen/Core>
#include <functional>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

struct UvRefineOptions {
  int rounds = 3;                  // u-then-v rounds at most
  double relative_tolerance = 1e-5;  // of the half step: each search's bracket
  int max_iterations = 60;         // per search
  // Stop when a round lowers the cost by no more than this (negative: never
  // stop early, run every round).
  double stall = -1;
};

// Lowers `cost` from `uv` (whose cost is `value`); `half` is the search
// half-width along u and v [parameter units]. Returns the lowest cost found
// and moves `uv` there. A search that finds nothing lower leaves uv alone.
double refine_uv_by_axes(const std::function<double(const Eigen::Vector2d&)>& cost,
                         const ParameterDomain& domain, const Eigen::Vector2d& half, double value,
                         Eigen::Vector2d& uv, const UvRefineOptions& options);

}  // namespace furrow
