#pragma once
// The scan comparison stage (`furrow compare PART --scan FILE`): the cloud
// pre-processed in the scan module, registered and compared point by point
// (inspection/scan_comparison.hpp, docs/scan.md).
#include "inspection/scan_comparison.hpp"

namespace furrow {

// `regions` may be null; it must belong to `part`. options.tolerance must
// be set and the registration scaled to it (scale_registration_to_tolerance).
// InputError for a cloud the pre-processing refuses (scan_preprocess.hpp).
ScanComparison compare_scan_stage(const Part& part, const ScanCloud& cloud, const RegionMap* regions,
                                  const CompareOptions& options, const ScanPreprocessOptions& preprocessing);

}  // namespace furrow
