#pragma once
// comparison.json: what `furrow compare` found (docs/formats.md
// "Comparison"). Deterministic: the same comparison gives the same bytes.
//
// The document header (sources, tolerance, registration, summary, regions)
// is formatted like every Furrow JSON (json_fields::to_text); the points
// follow as one compact object per line, so that a million-point scan is
// written without building a million-object JSON tree in memory.
#include <string>

#include "inspection/comparison.hpp"

namespace furrow {

struct ComparisonSources {
  std::string part, measurements, plan;  // file names as given; plan may be empty
};

std::string comparison_to_json_text(const Comparison& comparison, const MeasurementSet& set,
                                    const Part& part, const CompareOptions& options,
                                    const ComparisonSources& sources);

}  // namespace furrow
