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
// surface (a steep flank next to the path), or does not meet it within
// `max_distance`: above Q there is then stock the tool never came near, not
// a machined surface, and no number describes it (docs/formats.md
// "prediction.json": such samples are counted as not reached, never given a
// value).
//
// Why `max_step`: H may be finite, then +infinity (uncut), then finite again
// along the normal (two passes with uncut stock between them). A step that
// jumped over the uncut gap would meet the far pass's envelope and report
// the distance to it as material left, although the normal went through
// stock first. A step can also jump the other way, past a short stretch
// where the normal lies above the machined surface (a true crossing) into
// uncut space beyond, and report nothing where material is left. With steps
// no longer than max_step (the z-map sets one cell of horizontal travel,
// the finest feature it resolves) the search sees both; and a crossing
// found at a jump of H from +infinity (the far side of a gap narrower than
// a step) is not reached unless a finer scan finds a true crossing first.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/scalar_search.hpp"

namespace furrow {

struct NormalErrorOptions {
  double tolerance = 1e-9;   // on the distance along the normal [mm]
  int max_iterations = 100;  // root refinement
  double max_distance = 10;  // search range along the normal [mm]
  double growth = 1.6;       // bracket growth per step
  double max_step = 0;       // [mm] longest step along the normal; 0: no limit (see above)
  // What the caller knows of H, so that an overcut of any depth is measured
  // rather than stopped at max_distance: H >= floor everywhere, and
  // H = +infinity outside `shadow` (an empty box: not known). Going down,
  // the normal line is past any crossing once it runs below the floor or
  // out of the shadow, so the search range extends to there.
  double floor = -std::numeric_limits<double>::infinity();
  Eigen::AlignedBox2d shadow;
};

// `options` with the bounds of H set (see NormalErrorOptions::floor).
inline NormalErrorOptions with_height_bounds(NormalErrorOptions options, double floor,
                                             const Eigen::AlignedBox2d& shadow) {
  options.floor = floor;
  options.shadow = shadow;
  return options;
}

// The range of the downward (overcut) search from q along n [mm]: at least
// max_distance, and far enough that the line has crossed H when the bounds
// above are known.
inline double overcut_search_range(const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                                   const NormalErrorOptions& options) {
  double range = std::numeric_limits<double>::infinity();
  if (n.z() > 0 && std::isfinite(options.floor)) range = (q.z() - options.floor) / n.z();
  const double nxy = std::hypot(n.x(), n.y());
  if (!options.shadow.isEmpty() && nxy > 0) {
    double farthest = 0;
    for (int c = 0; c < 4; ++c)
      farthest = std::max(farthest, (options.shadow.corner(static_cast<Eigen::AlignedBox2d::CornerType>(c)) -
                                     q.head<2>()).norm());
    range = std::min(range, farthest / nxy);
  }
  if (!std::isfinite(range)) return options.max_distance;
  // A margin for rounding: at the bound itself g is exactly 0 or +infinity.
  return std::max(options.max_distance, range + 1e-9 * (1 + range) + 10 * options.tolerance);
}

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
  const double range = dir > 0 ? options.max_distance : overcut_search_range(q, n, options);
  double step = std::fabs(g0) * std::max(n.z(), 0.05);
  step = std::max(step, 10 * options.tolerance);
  double ta = 0, ga = g0;
  for (;;) {
    double reach = std::min(step, range);
    if (options.max_step > 0) reach = std::min(reach, std::fabs(ta) + options.max_step);
    const double tb = dir * reach;
    const double gb = g(tb);
    const bool crossed = dir > 0 ? gb <= 0 : gb >= 0;  // +inf counts going down: out of the cut
    if (crossed) {
      const ScalarSearchResult r =
          find_bracketed_root(g, ta, ga, tb, gb, {options.tolerance, options.max_iterations});
      result.error = r.x;
      result.end = r.x;
      result.converged = r.converged;
      result.wall = !(std::fabs(r.value) <= std::max(kWallJump, 1e3 * options.tolerance));
      // Going up, a wall whose near side is uncut: the normal went through
      // stock before meeting this envelope (the header). The bracket may
      // also hold an earlier, true crossing before the stock (the root
      // finder need not find the first of several): scan [ta, root] finely
      // for the first sign change or the first uncut point, whichever comes
      // first.
      if (dir > 0 && result.wall) {
        const double before = r.x - std::max(4 * options.tolerance, 1e-12 * std::fabs(r.x));
        if (before > ta && !std::isfinite(g(before))) {
          constexpr int kScan = 256;
          const double dt = (before - ta) / kScan;
          double sa = ta, sga = ga;
          for (int k = 1; k <= kScan; ++k) {
            const double sb = k == kScan ? before : ta + k * dt;
            const double sgb = g(sb);
            if (!std::isfinite(sgb)) break;  // stock first: not reached
            if (sgb <= 0) {
              const ScalarSearchResult first =
                  find_bracketed_root(g, sa, sga, sb, sgb, {options.tolerance, options.max_iterations});
              result.error = first.x;
              result.end = first.x;
              result.converged = first.converged;
              result.wall = !(std::fabs(first.value) <= std::max(kWallJump, 1e3 * options.tolerance));
              return result;
            }
            sa = sb, sga = sgb;
          }
          result = NormalError{};
          result.end = r.x;
          return result;
        }
      }
      return result;
    }
    if (!std::isfinite(gb) || reach >= range) {
      // Going up: the normal left the cut area without meeting the machined
      // surface. Going down beyond the range (only without bounds on H): an
      // overcut deeper than it, a lower bound, not converged.
      result.reached = dir < 0;
      result.error = dir < 0 ? -range : 0.0;
      result.end = tb;
      return result;
    }
    ta = tb, ga = gb;
    if (reach >= step) step *= options.growth;
  }
}

}  // namespace furrow
