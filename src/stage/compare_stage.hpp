#pragma once
// The comparison stage (`furrow compare`, and `furrow run`): measured points
// registered to the part, deviations in the tolerance zone, regions assigned
// from a partition, and — with a prediction — predicted versus measured and
// gouge confirmation. One function for both callers.
#include "inspection/comparison.hpp"
#include "inspection/measurement_merge.hpp"
#include "io/cmm/measurement_file.hpp"

namespace furrow {

// The registration's robust loss scale and outlier floor follow the profile
// tolerance: half the zone's width (docs/registration.md says why). Call
// after setting options.tolerance.
void scale_registration_to_tolerance(CompareOptions& options);

// The points to compare under options.align (docs/registration.md
// "Alignments"): with rps, fits the frame of options.rps
// (rps_alignment.hpp: InputError without one or with a point missing,
// DatumFrameError when the points do not fix the part) and returns the
// other points; with datums, fits the datum frame to the plan's datum
// points (datum_frame.hpp: InputError without a datums alignment in `plan`
// or with a datum point missing, DatumFrameError for degenerate data) into
// options.datum_frame and returns the other points; else `set` as it is.
// `plan_name` names the plan in messages.
MeasurementSet prepare_alignment(CompareOptions& options, const MeasurementSet& set, const InspectionPlan* plan,
                                 const std::string& plan_name);

// Keeps only the points of `compared` (by id) in `merged` - its set and the
// file each point came from - so that it describes the compared points
// after prepare_alignment took the datum points away.
void restrict_to(MergedMeasurements& merged, const MeasurementSet& compared);

// `plan`, `regions` and `prediction` may each be null. The measurement set,
// plan, regions and prediction must belong to `part` (their readers' checks).
Comparison compare_stage(const Part& part, const MeasurementSet& set, const InspectionPlan* plan,
                         const RegionMap* regions, const Prediction* prediction, const CompareOptions& options);

}  // namespace furrow
