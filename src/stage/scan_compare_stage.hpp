#pragma once
// The scan comparison stage (`furrow compare PART --scan FILE`): the cloud
// pre-processed in the scan module, registered and compared point by point
// (inspection/scan_comparison.hpp, docs/scan.md).
#include "inspection/scan_comparison.hpp"

namespace furrow {

// `regions` and `prediction` may be null; they must belong to `part`
// (with a prediction: predicted versus measured and gouge confirmation,
// inspection/scan_verification.hpp). options.tolerance must be set and the
// registration scaled to it (scale_registration_to_tolerance). InputError
// for a cloud the pre-processing refuses (scan_preprocess.hpp).
ScanComparison compare_scan_stage(const Part& part, const ScanCloud& cloud, const RegionMap* regions,
                                  const Prediction* prediction, const CompareOptions& options,
                                  const ScanPreprocessOptions& preprocessing);

}  // namespace furrow
