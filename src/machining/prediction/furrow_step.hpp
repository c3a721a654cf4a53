#pragma once
// Per-step machining error, exact (docs/architecture.md "Machining error between
// contact points", predictor 1).
//
// Between two consecutive contact points the tool moves on the straight
// segment between their cutter locations (tips), while the design surface
// follows a curve (surface_curve.hpp). The machined surface near the step is
// the swept cutter's lower envelope (swept_envelope.hpp); the error at a
// curve point is its signed distance along the normal to that envelope
// (normal_error.hpp): positive = material left (undercut, the furrow of a
// concave stretch), negative = overcut (the straight move dips into a convex
// stretch). Both happen in one step on an inflecting curve, so both extremes
// are reported with where they occur.
//
// Method: the curve is sampled (ends included, spacing from the options),
// the largest and the smallest sampled errors are each refined by Brent's
// method on the bracket of their neighbouring samples. Exact up to the
// tolerances below; sampling can only miss a local extremum narrower than
// the sample spacing (the default 0.1 mm is far below any cutter radius, and
// the error varies on the scale of the step and the cutter).
// Only this move's envelope counts, and only on the curve: neighbouring
// moves and passes (scallops) are the z-map's business (zmap.hpp). Beside
// the curve the same move can cut deeper (an oblique step, a saddle):
// strip_step.hpp refines the overcut there from this result.
// On a convex stretch the contact points themselves are overcut a little:
// the cutter moving off along the chord dips below the point it touched.
#include <Eigen/Core>

#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/normal_error.hpp"
#include "machining/prediction/surface_curve.hpp"
#include "machining/prediction/swept_envelope.hpp"

namespace furrow {

struct FurrowStepOptions {
  int min_intervals = 16;            // samples along the curve: at least this + 1
  double max_sample_spacing = 0.1;   // mm of chord between samples
  int max_intervals = 8192;
  double refine_tolerance = 1e-7;    // position of an extremum along the chord [mm]
  int refine_iterations = 100;
  EnvelopeOptions envelope;
  NormalErrorOptions normal;
  CutterLocationOptions location;
};

struct ErrorExtreme {
  double error = 0;   // [mm]
  double lambda = 0;  // curve parameter where it occurs
  SurfacePoint at;    // the surface point there
};

struct FurrowStepResult {
  // False when a contact point is invalid or cannot be reached from above
  // (n_z < 0): nothing else is set.
  bool valid = false;
  ErrorExtreme undercut;  // largest error, >= 0 (0 at a contact point when nothing is left)
  ErrorExtreme overcut;   // smallest error, <= 0 (0 at a contact point when nothing is cut)
  Eigen::Vector3d tip0 = Eigen::Vector3d::Zero(), tip1 = Eigen::Vector3d::Zero();
  int samples = 0;
  int unreached = 0;      // samples whose normal misses the envelope (left out)
  bool converged = true;  // every root and refinement within its tolerance
  double magnitude() const { return std::max(undercut.error, -overcut.error); }
};

// Error on `curve` left by the straight move tip0 -> tip1.
FurrowStepResult furrow_step_error(const Cutter& cutter, const Eigen::Vector3d& tip0,
                                   const Eigen::Vector3d& tip1, const SurfaceCurve& curve,
                                   const FurrowStepOptions& options = {});
// The tips located at the curve's end points (cutter_location.hpp).
FurrowStepResult furrow_step_error(const Cutter& cutter, const SurfaceCurve& curve,
                                   const FurrowStepOptions& options = {});

// `curve` that remembers every point it has evaluated and returns the same
// point again for the same lambda (bit for bit: the curve must be a function
// of lambda alone, as iso_parametric_curve and vertical_section_curve are).
// Why: each of the two predictors above and below samples the curve on the
// same grid (lambda = i / n, n from the chord) and evaluates its extremes
// again at the end, and a curve point is a surface projection, the bulk of
// their cost; one step's error and chord deviation share the points through
// one remembering curve. Not thread-safe: one per step and thread.
SurfaceCurve remembering_curve(SurfaceCurve curve);

// The chord-deviation estimate for comparison: the largest distance from the
// curve to the straight segment between its end points (what a CAM system
// bounds when it ignores the cutter), refined like the errors.
struct ChordDeviation {
  bool valid = false;
  double deviation = 0;  // [mm], >= 0
  double lambda = 0;
  SurfacePoint at;
};
ChordDeviation chord_deviation(const SurfaceCurve& curve, const FurrowStepOptions& options = {});

}  // namespace furrow
