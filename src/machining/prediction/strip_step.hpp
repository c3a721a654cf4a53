#pragma once
// Per-step machining error beside the design curve (docs/architecture.md
// "Machining error between contact points", "Beside the curve").
//
// furrow_step.hpp measures one move's error on the design curve between its
// contact points. The move's swept cutter also cuts the surface beside that
// curve, and on an oblique step (contacts apart both along and across the
// surface's curvature) its extremes lie there, not on the curve: about
// 0.15 mm beside it on a cylinder, 0.5 % deeper. This refines both of a
// step's extremes over the strip the move sweeps, points S(lambda, c): the
// curve point at lambda moved c millimetres across the move (along n x d,
// d the move's direction in the tangent plane, as a straight line in the
// face's (u, v)), the error the same normal distance to the move's envelope.
//   Overcut (the smallest error): from the curve's smallest error, Brent
//   searches across (sampled first over +-half_width) and along
//   (+-along_bracket of lambda) alternate until the point settles. Never
//   shallower than the curve's (the start is kept when nothing beats it).
//   Undercut (the material the move leaves along its track): across the
//   track the error grows toward the neighbouring passes (the scallop's
//   business, pass_scallops.hpp), so the largest error over a strip is not
//   the step's. The step's is the crest of its track bottom: on each section
//   the valley (the smallest error within one across-sample cell, 2
//   half_width / across_samples, of the curve), and the largest of these
//   over the sections, searched by Brent along (+-along_bracket) with the
//   valley by Brent across, each section's bracket starting at the last
//   valley. Where the valley is a proper minimum this is the saddle value of
//   the error on the surface, whatever the sections are. Never above the
//   curve's largest error. The alternation can circle a saddle whose
//   valley turns sharply along the step; it is then searched nested (each
//   section's valley afresh, Brent along), slower. Refined only where the
//   move does not cut in beside the curve (overcut above -clear) and the
//   valley lies inside the width: otherwise the track has no bottom that
//   leaves material within the cutter's reach and the curve's undercut is
//   kept. A flat end mill's envelope has a crease along its rim: its valley
//   has a kink and its crest depends slightly on how the sections are drawn
//   (0.6 um of 54 um on a saddle), so for it the figure is the crest on
//   these sections, between the true saddle and the curve's.
// Samples off the face, facing down or not reached by the move are left
// out. The searches are local: the extremes are taken to lie in the valley
// the curve's extremes lie in, as they do on a smooth surface for a step
// short against its curvature radii.
// Cost: about a hundred error evaluations per extreme, so callers refine
// only what they report (path_steps.hpp); the planner refines only the
// overcut (forward_step.hpp).
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
  bool undercut = true;        // also refine the undercut (the crest of the track bottom)
  // [mm] an overcut beside the curve deeper than this means the move cuts
  // in there: the undercut is then not refined.
  double clear = 1e-6;
};

struct StripExtreme {
  double error = 0;   // [mm]
  double lambda = 0;  // curve parameter of its section
  double offset = 0;  // [mm] across the move (c)
  SurfacePoint at;
};

struct StripStepResult {
  bool valid = false;     // false: the step itself was not valid
  StripExtreme overcut;   // <= 0 (the curve's when it has no overcut)
  StripExtreme undercut;  // >= 0 (the curve's when not refined, above)
  bool converged = true;  // the alternation settled within max_rounds
  int evaluations = 0;
};

// `on_curve` is furrow_step_error's result for the same move and curve
// (whose points must lie on `part`'s faces).
StripStepResult strip_step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve,
                                 const FurrowStepResult& on_curve, const FurrowStepOptions& step_options,
                                 const StripStepOptions& options = {});

}  // namespace furrow
