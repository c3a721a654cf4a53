#pragma once
// A map from the unit square onto a rectangle of a face's (u, v) domain that
// carries uniform density in the square to a prescribed density on the
// surface: by default the area element, so evenly spread points in [0, 1)^2
// land evenly spread *on the surface*, whatever the parametrisation.
//
// Why: faces from CAD are rarely parametrised proportionally to arc length
// (a fillet squeezed at one end, a revolved face near its pole). Sampling u
// and v uniformly would crowd probe points where the parametrisation is
// slow. The warp is the Rosenblatt transform of a piecewise-constant density
// on a G x G cell grid over the rectangle: u from the marginal distribution
// of the density along u, then v from the conditional distribution in the
// column u fell into, each piecewise linear (exact inverse CDFs). Points that
// are evenly spread in the square stay evenly spread in the warped measure
// (the transform is monotone in each coordinate), so low-discrepancy sets
// keep most of their advantage.
//
// The density is `weight(u, v) * area_element(u, v)` sampled at cell centres;
// weights let curvature-adaptive and risk-driven sampling ask for more points
// where |k| or the predicted error is high. Weights must be >= 0 and not all
// zero; a column of zero weight is skipped, so no point lands there.
//
// Units: none (u, v are face parameters). Thread safety: immutable after
// construction.
#include <Eigen/Geometry>
#include <functional>
#include <vector>

namespace furrow {

class AreaWarp {
 public:
  // `density(u, v)` at the centres of a `cells` x `cells` grid over `box`
  // (cells >= 1). Throws std::invalid_argument when the total is not a
  // positive finite number or a value is negative or not finite.
  AreaWarp(const Eigen::AlignedBox2d& box, int cells,
           const std::function<double(double u, double v)>& density);

  // (s, t) in [0, 1]^2 -> (u, v) in the box.
  Eigen::Vector2d map(const Eigen::Vector2d& st) const;

  const Eigen::AlignedBox2d& box() const { return box_; }
  int cells() const { return cells_; }

 private:
  // Inverse of a piecewise-linear CDF given by cumulative values at nodes
  // 0..n (cdf[0] = 0, increasing weakly to cdf[n] = 1): position in [0, n].
  static double invert(const double* cdf, int n, double p);

  Eigen::AlignedBox2d box_;
  int cells_ = 1;
  std::vector<double> u_cdf_;  // cells + 1
  std::vector<double> v_cdf_;  // per column, cells + 1 each
};

}  // namespace furrow
