#pragma once
// The part placement that a reference point system (reference_points.hpp)
// fixes: `furrow compare --align rps` evaluates the free-form points in it,
// without a best fit (docs/registration.md "RPS alignment").
//
// The transform T (CMM -> part) minimises
//   sum over points i, over the axes a the point fixes:  w_i (e_a . (T c_i - q_i))^2
// where c_i is the measured contact point and q_i the nominal. For centre
// points the contact is the centre moved back by the ball radius along the
// nominal normal turned into the CMM frame: T c_i = R m_i + t - r n_i, with
// m_i the measured centre. Six independent constraints (a 3-2-1 RPS) fix T
// exactly and leave zero residuals; more are a weighted least-squares fit.
// When every point fixes all three axes with one weight, the fit is the
// point-to-point least-squares (Kabsch) transform.
//
// Solution: Kabsch on all coordinates of the matched points as the start,
// then Gauss-Newton on the declared axes, rotations taken about the
// nominal points' centroid. Iterations are capped (options.max_iterations);
// the step is converged when it moves no point by more than
// options.step_tolerance.
//
// Failure: an RPS point missing from the measurements, or measurements
// without ids, throw InputError naming the point (exit 2). Points that do not
// fix all six motions (all fixing z only, say: the part could slide), fewer
// than three points or collinear ones (no start), and a fit that does not
// converge throw DatumFrameError with the reason (exit 3: the computation
// did not succeed). Never NaN.
#include "inspection/datum_frame.hpp"
#include "inspection/reference_points.hpp"

namespace furrow {

struct RpsFitOptions {
  int max_iterations = 50;
  // [mm] largest point motion of a converged step: a nanometre, far below any
  // probe, and above the rounding of coordinates up to the part limit.
  double step_tolerance = 1e-9;
  // A motion whose constraint stiffness is below this share of the
  // stiffest one counts as not fixed (scaled so that a turn moves the points
  // as much as a slide of the same size).
  double rank_ratio = 1e-9;
};

// The frame: transform CMM -> part, measured = its inverse, nominal the
// identity (the RPS is stated in the part frame), reference_points filled,
// datums empty.
DatumFrame fit_rps_alignment(const ReferencePointSystem& rps, const MeasurementSet& set,
                             const RpsFitOptions& options = {});

// The set without the RPS points (the free-form points the frame evaluates).
MeasurementSet without_reference_points(const MeasurementSet& set, const ReferencePointSystem& rps);

}  // namespace furrow
