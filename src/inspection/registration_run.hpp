#pragma once
// One registration from one start, in the steps docs/registration.md
// describes (coarse start, fit with the weak directions held, outlier
// passes, release, classification, uncertainty): register_measurements
// (registration.hpp) is this, followed for few points by the search of
// few_point_search.hpp, which runs it again from other starts.
#include <cstddef>
#include <limits>

#include "inspection/registration.hpp"

namespace furrow {

constexpr std::size_t kNoPointLeftOut = std::numeric_limits<std::size_t>::max();

// `left_out`: a point kept out of the fit's first pass (the outlier rule
// judges it with the others after that pass), or kNoPointLeftOut.
// Preconditions: options validated by register_measurements.
RegistrationResult run_registration(const ClosestPointFinder& finder, const MeasurementSet& set,
                                    const InspectionPlan* plan, const RegistrationOptions& options,
                                    std::size_t left_out = kNoPointLeftOut);

}  // namespace furrow
