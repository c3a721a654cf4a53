#pragma once
// points.csv of a QA report: one row per measured point (in measurement
// order) after a header row, every number of comparison.json's point plus
// the prediction's, so a spreadsheet or a script needs nothing else.
//
// Columns (docs/formats.md "Report folder"): id, face, u, v, foot x y z,
// normal i j k, measured x y z (CMM frame), deviation, uncertainty,
// evaluated, in_tolerance, in_fit, outlier, region, predicted,
// measured_aligned, residual, sigma_total, then the metrologist's columns
// of the point table (point_table.hpp; its nominal X Y Z and I J K are
// foot_* and normal_*): actual_x y z (part frame), lower_tolerance,
// upper_tolerance, out_of_tolerance, status (IN, OUT, NOT EVALUATED) -
// appended, so scripts that read the first columns by position keep
// working. Lengths in mm, numbers in their
// shortest exact text; an empty cell where the value does not exist (no
// covariance, not evaluated, no region, no prediction there). Text cells
// with a comma, quote or line break are quoted (RFC 4180).
#include <string>

#include "inspection/comparison_document.hpp"

namespace furrow {

std::string points_csv_text(const ComparisonDocument& doc);

}  // namespace furrow
