#pragma once
// Per-step machining error beside the design curve (docs/architecture.md
// "Machining error between contact points", "Beside the curve").
//
// furrow_step.hpp measures one move's error on the design curve between its
// contact points. The move's swept cutter also cuts the surface beside that
// curve, and on an oblique step (contacts apart both along and across the
// surface's curvature) its deepest overcut lies there, not on the curve:
// about 0.15 mm beside it on a cylinder, 0.5 % deeper. This refines both of
// a step's overcut over the strip the move sweeps, points S(lambda, c): the
// curve point at lambda moved c millimetres across the move (along n x d,
// d the move's direction in the tangent plane, as a straight line in the
// face's (u, v)), the error the same normal distance to the move's envelope.
// From the curve's smallest error, Brent searches across (sampled first
// over +-half_width) and along (+-along_bracket of lambda) alternate until
// the point settles. The result is never shallower than the curve's (the
// start is kept when nothing beats it).
// Only the overcut: material left grows away from the curve toward the
// neighbouring passes, where it is the scallop's (pass_scallops.hpp); the
// step's undercut stays the curve's, the line the furrow runs along.
// Samples off the face, facing down or not reached by the move are left
// out. The search is local: the strip's deepest point is taken to lie in
// the valley the curve's deepest point lies in, as it does on a smooth
// surface for a step short against its curvature radii.
// Cost: about a hundred error evaluations per step, so callers refine only
// the steps that matter (path_steps.hpp).
#include "geometry/part.hpp"
#include "machining/prediction/furrow_step.hpp"

namespace furrow {

struct StripStepOptions {
  double half_width = 0;       // [mm] across the curve each way; 0: the cutter's radius
  int across_samples = 8;      // first search across: this many intervals over the width
  double along_bracket = 0.1;  // lambda either side of the current extreme
  // [mm] position across, and along (times the chord). At an extreme the
  // error is flat: a position off by d changes it by about d^2 times the
  // curvature difference (< 1/mm), so 1e-4 mm keeps it within 1e-8 mm.
  double tolerance = 1e-4;
  int max_rounds = 8;          // alternations of the two searches
  int max_iterations = 100;    // per Brent search
};

struct StripExtreme {
  double error = 0;   // [mm]
  double lambda = 0;  // curve parameter of its section
  double offset = 0;  // [mm] across the move (c)
  SurfacePoint at;
};

struct StripStepResult {
  bool valid = false;     // false: the step itself was not valid, or it cuts nothing
  StripExtreme overcut;   // <= 0
  bool converged = true;  // the alternation settled within max_rounds
  int evaluations = 0;
};

// `on_curve` is furrow_step_error's result for the same move and curve
// (whose points must lie on `part`'s faces).
StripStepResult strip_step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve,
                                 const FurrowStepResult& on_curve, const FurrowStepOptions& step_options,
                                 const StripStepOptions& options = {});

}  // namespace furrow
