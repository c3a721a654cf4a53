#pragma once
// Deviations at a given transform, with no fit: what `furrow compare
// --align cmm` (the identity: the CMM program already aligned the part) and
// `--align datums` (the datum frame, datum_frame.hpp) evaluate
// (docs/registration.md "Alignments").
//
// Each point x = T p (CMM -> part) is projected onto the part; its deviation
// is d = n.(x - f) - r_probe as in the registration (registration.hpp), with
// the same beyond_edge / no_foot_point rules (edge_tolerance of `options`).
// No outlier rule by deviation: a deviation of location is what these
// alignments are there to show, so every point on the part is evaluated.
//
// The result is a RegistrationResult that says so: converged, no fitted
// motion, no covariance ("no fit"), identity coarse start, no weak
// direction - with no fit, observability is not a question. `status` is
// the `note` given.
#include <Eigen/Geometry>
#include <string>

#include "inspection/registration.hpp"

namespace furrow {

RegistrationResult evaluate_at_transform(const ClosestPointFinder& finder, const MeasurementSet& set,
                                         const Eigen::Isometry3d& transform, const RegistrationOptions& options,
                                         const std::string& note);

}  // namespace furrow
