#pragma once
// comparison.json of a scan (docs/formats.md "comparison.json of a scan"):
// what was read, kept and removed per reason, the registration, the
// statistics overall and per region, the verdict. It holds no per-point
// record: a million points would make it hundreds of MB; they go to the
// deviation cloud (scan_deviation_cloud.hpp).
#include <string>

#include "inspection/scan_comparison.hpp"

namespace furrow {

struct ScanComparisonSources {
  std::string part, scan, regions, deviations, prediction;  // file names; empty when not given
  std::string units = "mm";                     // of the scan file
};

// Furrow's JSON layout (json_fields::to_text), ending with a newline.
std::string scan_comparison_json(const ScanComparison& c, const ScanComparisonSources& sources);

}  // namespace furrow
