#pragma once
// The comparison stage (`furrow compare`, and `furrow run`): measured points
// registered to the part, deviations in the tolerance zone, regions assigned
// from a partition, and — with a prediction — predicted versus measured and
// gouge confirmation. One function for both callers.
#include "inspection/comparison.hpp"
#include "io/cmm/measurement_file.hpp"

namespace furrow {

// The registration's robust loss scale and outlier floor follow the profile
// tolerance: half the zone's width (docs/registration.md says why). Call
// after setting options.tolerance.
void scale_registration_to_tolerance(CompareOptions& options);

// `plan`, `regions` and `prediction` may each be null. The measurement set,
// plan, regions and prediction must belong to `part` (their readers' checks).
Comparison compare_stage(const Part& part, const MeasurementSet& set, const InspectionPlan* plan,
                         const RegionMap* regions, const Prediction* prediction, const CompareOptions& options);

}  // namespace furrow
