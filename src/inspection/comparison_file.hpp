#pragma once
// comparison.json: what `furrow compare` found (docs/formats.md
// "Comparison"). Deterministic: the same comparison gives the same bytes.
//
// The document header (sources, tolerance, registration, summary, regions)
// is formatted like every Furrow JSON (json_fields::to_text); the points
// follow as one compact object per line, so that a million-point scan is
// written without building a million-object JSON tree in memory.
//
// read_comparison() reads it back into plain structs
// (comparison_document.hpp): every number as written, so that the QA
// report works from the file alone. Errors name the file and the field
// ("comparison.json: points[3].deviation: expected a number, found null").
#include <string>

#include "inspection/comparison.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/measurement_merge.hpp"

namespace furrow {

constexpr int kComparisonFormatVersion = 1;

struct ComparisonSources {
  // File names as given; empty when not given (plan, regions, prediction).
  std::string part, measurements, plan, regions, prediction;
  std::string measurement_units = "mm";  // how the measurement file was read (--units)
  // Several measurement files merged by id (measurement_merge.hpp), or null
  // for one file: then `measurements` names it. With several, comparison.json
  // lists every file, the file each point came from and what was replaced.
  const MergedMeasurements* merged = nullptr;
};

std::string comparison_to_json_text(const Comparison& comparison, const MeasurementSet& set,
                                    const Part& part, const CompareOptions& options,
                                    const ComparisonSources& sources);

// Throws InputError naming the file and the field for anything missing,
// mistyped or inconsistent (a point id named by a site that is no point).
ComparisonDocument read_comparison(const std::string& path);
// `name` stands for the source in messages.
ComparisonDocument parse_comparison(const std::string& text, const std::string& name);

}  // namespace furrow
