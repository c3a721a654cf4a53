#pragma once
// The search that follows a registration of few points (fewer than
// CoarseOptions::few_points, RegistrationOptions::multi_start_few): with a
// handful of points a single blunder can lead the fit into a wrong local
// minimum that keeps the blunder and drops good points, and on a
// symmetric part another choice of outliers can explain the points as
// well as the right one (docs/registration.md "Few points").
//
// Fits tried besides the first:
//   * without ids (the first started by the global search): one from every
//     other placement the search refined (CoarseResult::alternatives);
//   * without ids and at most 16 points: the global search run again
//     without each point in turn (one blunder among so few can move every
//     placement it refines), and a fit from its placement with that point
//     left out of the first pass;
//   * when the best fit so far flags points: one from its transform with
//     each point it kept left out of the first pass in turn, so that a
//     blunder the fit absorbed gets judged from a fit without it.
// The fit that explains the points best is kept: the least robust cost
// (orientation_check.hpp fit_cost). Its coarse result is the first fit's,
// with the start that won.
//
// Ambiguous orientation: after a global search the result's
// coarse.ambiguous says whether another of these fits passes
// orientation_check.hpp's another_orientation - whatever the search said
// (a search without one point can find the other side of a flat part, and
// the search's coarse scores can call a part with no symmetry ambiguous).
//
// Ambiguous outliers: another converged fit that flags as many points,
// but other ones, and whose points in the fit scatter within what the
// best fit's residual sigma allows (sum of squares below sigma^2 times the
// chi-square 99.9 % quantile of its degrees of freedom) explains the points
// as well: the data cannot tell which of those points are the blunders.
// Their indices go to RegistrationResult::ambiguous_outliers, which makes
// the alignment a computation that did not succeed (exit 3), never a
// verdict on the wrong points.
#include "inspection/registration.hpp"

namespace furrow {

RegistrationResult search_few_points(RegistrationResult first, const ClosestPointFinder& finder,
                                     const MeasurementSet& set, const InspectionPlan* plan,
                                     const RegistrationOptions& options);

// Upper quantile of the chi-square distribution with `nu` > 0 degrees of
// freedom at the standard normal score `z` (Wilson-Hilferty: within 6 % of
// the exact quantile at nu = 1 and 1 % from nu = 2 on, z = 3.09).
double chi_square_quantile(double nu, double z);

}  // namespace furrow
