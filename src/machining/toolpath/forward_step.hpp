#pragma once
// Contact points along one pass (pass_curve.hpp): each step as long as its
// error allows (docs/architecture.md "Machining error between contact points").
//
// Three rules, so they can be compared on the same pass:
//   exact         the step's largest error from the swept cutter
//                 (furrow_step.hpp: max(undercut, |overcut|)) equals the
//                 tolerance: a line search on the exact predictor;
//   chord         the largest distance between the design curve and the
//                 chord between the contact points equals the tolerance
//                 (what CAM systems bound; it ignores the cutter, so on a
//                 convex stretch the real error is larger by (rho + r)/rho);
//   circular_arc  the curve is replaced by its osculating circle at the
//                 step's start (normal curvature along the pass) and the
//                 step follows from docs/architecture.md's ball formula with the
//                 cutter's corner radius r: (rho + r)(1 - cos(ds / 2 rho)) = e
//                 convex, (rho - r)(...) concave; unbounded on flat
//                 stretches and in concave ones tighter than r. An estimate:
//                 no search, no check.
// Line search (exact, chord): from the circular-arc estimate the step is
// doubled or halved until it brackets the tolerance, then refined by false
// position on (error - tolerance) (Illinois variant, bisection while an end's
// error is unknown) until the accepted step's error is within
// max(relative_precision * tolerance, absolute_precision) below the
// tolerance: the step is as long as the tolerance allows, not merely close
// to it in length (the error grows with the square of the step, so a
// parameter bracket of 1e-3 leaves 0.2 % of the tolerance unused). The
// accepted step always has error <= tolerance as computed (a zero-length
// step has none), and a longer one tried exceeded it. Where the error jumps
// over the tolerance (a step reaching another face, a change of contact) the
// bracket collapses first; the step is kept and counted in `jumps`.
// The exact rule's overcut is the deepest beside the curve too (strip_step.hpp:
// an oblique step cuts deepest off it) where the cutter fits the part at
// the step's start (no local gouge, local_gouge.hpp); where it does not, that
// gouge is beside the curve at any step length, and the curve's error
// decides. So it does when even a minimal step keeps an overcut beside the
// curve over the tolerance, or the error beside it jumps over the tolerance
// (a feature within the cutter's reach, a part edge). The last
// step of a pass ends at the pass end and may be shorter. `max_step` [mm,
// chord] caps every rule (0: no cap).
#include <vector>

#include "machining/cutter/cutter.hpp"
#include "machining/prediction/furrow_step.hpp"
#include <string>

#include "machining/toolpath/pass_curve.hpp"

namespace furrow {

enum class StepRule { exact, chord, circular_arc };
const char* to_string(StepRule rule);  // "exact", "chord", "circular_arc"
// The names of to_string, and "circular-arc" (the command line's older
// spelling); InputError naming `where` for any other text.
StepRule parse_step_rule(const std::string& text, const std::string& where);

struct ForwardStepOptions {
  double tolerance = 0.01;  // [mm]
  StepRule rule = StepRule::exact;
  double relative_precision = 1e-4;  // the accepted error is >= tolerance (1 - this) ...
  double absolute_precision = 1e-7;  // [mm] ... or >= tolerance - this, whichever is lower
  int max_iterations = 60;  // per step (bracketing + refinement)
  double max_step = 0;      // [mm] chord; 0: none
  long max_points = 1'000'000;  // per pass: beyond, the search stops (ForwardSteps::truncated)
  FurrowStepOptions predictor;
};

struct ForwardSteps {
  std::vector<double> params;  // t of every contact point, t0 first, t1 last
  int capped = 0;              // steps whose search hit max_iterations
  int jumps = 0;               // steps ended where the error jumps over the tolerance
  int evaluations = 0;         // error evaluations (exact or chord)
  int invalid = 0;             // evaluations on curves that could not be evaluated (treated as too long)
  bool truncated = false;      // stopped at max_points (docs/formats.md "Limits")
};

// The rule's error of one step (exact: max(undercut, |overcut|); chord: the
// chord deviation); +infinity when the step cannot be evaluated. With
// `beside` the exact rule's overcut is the deepest over the strip beside the
// curve (strip_step.hpp), whose points lie on `part`.
double step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve, StepRule rule,
                  const FurrowStepOptions& predictor = {}, bool beside = true);

// Arc length of the circular-arc estimate at a point for a pass direction
// (unit, tangent); +infinity when the formula gives no bound.
double circular_arc_step(const Part& part, const Cutter& cutter, const SurfacePoint& at,
                         const Eigen::Vector3d& direction, double tolerance);

ForwardSteps place_contact_points(const Part& part, const PassCurve& pass, const Cutter& cutter,
                                  const ForwardStepOptions& options = {});

}  // namespace furrow
