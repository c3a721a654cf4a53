#pragma once
// The machining error at a design-surface point: the signed distance along
// the surface normal from the point to a machined surface given as a height
// function z = H(x, y) (+infinity where nothing was cut) — one move's swept
// envelope (swept_envelope.hpp) or a whole path's z-map (zmap.hpp).
//
// With Q the point and n its unit normal (out of the material), solve
//   g(t) = H(Q_xy + t n_xy) - (Q_z + t n_z) = 0.
// t > 0: the machined surface lies above Q along the normal, material is
// left (undercut); t < 0: Q was cut away, the cut reaches t below it
// (overcut). The error is t itself, exact along the normal (not the vertical
// gap times n_z, which is only its first-order estimate).
//
// The root is bracketed by stepping away from Q (first step the vertical-gap
// estimate, then growing), so the crossing nearest to Q is found, then
// refined by find_bracketed_root. Q with H = +infinity above it was not
// reached by the tool: `reached` is false and the error undefined (0). So is
// an undercut whose normal leaves the cut area before meeting the machined
// surface (a steep flank next to the path).
#include <Eigen/Core>
#include <cmath>

#include "base/scalar_search.hpp"

namespace furrow {

struct NormalErrorOptions {
  double tolerance = 1e-9;   // on the distance along the normal [mm]
  int max_iterations = 100;  // root refinement
  double max_distance = 10;  // search range along the normal [mm]
  double growth = 1.6;       // bracket growth per step
};

struct NormalError {
  double error = 0;        // [mm], positive = material left, negative = overcut
  bool reached = false;    // the normal line meets the machined surface
  bool converged = false;  // within the tolerance (false also when beyond max_distance)
  bool wall = false;       // met at a jump of H (a vertical wall), see above
  double end = 0;          // [mm] along the normal where the search ended (the crossing,
                           // or where the normal left the cut area)
};

// A sign change of g with |g| still above this at the root is a jump of H,
// not a crossing of a continuous surface [mm].
constexpr double kWallJump = 1e-6;

template <class Height>
NormalError normal_error(const Height& height, const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                         const NormalErrorOptions& options = {}) {
  NormalError result;
  auto g = [&](double t) { return height(q.x() + t * n.x(), q.y() + t * n.y()) - (q.z() + t * n.z()); };
  const double g0 = g(0.0);
  if (!std::isfinite(g0)) return result;
  result.reached = true;
  if (g0 == 0) {
    result.converged = true;
    return result;
  }
  const double dir = g0 > 0 ? 1.0 : -1.0;
  double step = std::fabs(g0) * std::max(n.z(), 0.05);
  step = std::max(step, 10 * options.tolerance);
  double ta = 0, ga = g0;
  for (;;) {
    const double tb = dir * std::min(step, options.max_distance);
    const double gb = g(tb);
    const bool crossed = dir > 0 ? gb <= 0 : gb >= 0;  // +inf counts going down: out of the cut
    if (crossed) {
      const ScalarSearchResult r =
          find_bracketed_root(g, ta, ga, tb, gb, {options.tolerance, options.max_iterations});
      result.error = r.x;
      result.end = r.x;
      result.converged = r.converged;
      result.wall = !(std::fabs(r.value) <= std::max(kWallJump, 1e3 * options.tolerance));
      return result;
    }
    if (!std::isfinite(gb) || step >= options.max_distance) {
      // Going up: the normal left the cut area without meeting the machined
      // surface. Going down beyond the range: an overcut deeper than it.
      result.reached = dir < 0;
      result.error = dir < 0 ? -options.max_distance : 0.0;
      result.end = tb;
      return result;
    }
    ta = tb, ga = gb;
    step *= options.growth;
  }
}

}  // namespace furrow
