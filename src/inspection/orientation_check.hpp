#pragma once
// Whether another orientation of the part explains the measured points as
// well as the fitted one - decided on fine fits, not on the coarse search's
// scores (docs/registration.md "Ambiguous orientation").
//
// The coarse search (coarse_alignment.hpp) scores placements by a trimmed
// point-to-point ICP against a sampling of the surface. Its scores are
// coarse: 120 probe centres on the mould ended 0.5 mm from the part, and a
// placement turned 180 degrees scored within the ambiguity ratio of that,
// so a part with no symmetry was reported "ambiguous: another orientation
// fits as well" - a false statement in a QA report. So the question is put
// to the fine fit instead:
//   * fit_cost: a fit's robust cost, the sum over all points of
//     min(d^2, T^2), T the outlier floor (MSAC: a blunder costs T^2 however
//     far off, a point without a foot counts T^2);
//   * another_orientation: true when `other`, a converged fit, is turned
//     more than CoarseOptions::ambiguity_angle_deg from `kept` and costs at
//     most CoarseOptions::ambiguity_ratio times as much;
//   * settle_orientation: when the coarse search called its placement
//     ambiguous, the fit is run again from its runner-up (the best other
//     placement turned more than the ambiguity angle); the fit that
//     explains the points better is kept, and the result is ambiguous only
//     if the other one passes another_orientation. Few points
//     (few_point_search.hpp) apply the same rule to all their fits.
// An ambiguous result carries the other fit's deviations
// (RegistrationResult::other_orientation, from orientation_of): whether
// the two disagree about the tolerance is the comparison's question
// (comparison.hpp).
#include "inspection/registration.hpp"

namespace furrow {

double fit_cost(const RegistrationResult& r, const RegistrationOptions& options);

OtherOrientation orientation_of(const RegistrationResult& fit);

bool another_orientation(const Eigen::Isometry3d& kept, double kept_cost, const Eigen::Isometry3d& other,
                         double other_cost, const CoarseOptions& options);

// `first`: register_measurements' first run. Returns it unchanged unless
// its coarse start was a global search that it called ambiguous.
RegistrationResult settle_orientation(RegistrationResult first, const ClosestPointFinder& finder,
                                      const MeasurementSet& set, const InspectionPlan* plan,
                                      const RegistrationOptions& options);

}  // namespace furrow
