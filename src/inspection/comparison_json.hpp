#pragma once
// The sections of comparison.json that the QA report repeats in report.json
// (options, registration, deviation statistics), written in one place from
// the plain document structs of comparison_document.hpp: `furrow compare`
// converts its results into them before writing, `furrow report` has them
// from read_comparison(). So both files name, order and round every member
// the same way and cannot drift apart. Members: docs/formats.md "Comparison".
//
// Every number goes through json_fields::finite, which throws on NaN or
// infinity naming the member: a non-finite value is a bug upstream and must
// not reach a file.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <Eigen/Core>

#include "inspection/comparison_document.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"

namespace furrow::comparison_json {

using json_fields::json;

// Rows of numbers; `what` names the matrix in a non-finite error.
json matrix_json(const Eigen::MatrixXd& m, const char* what);

// count, mean, sigma, min, max [mm].
json statistics_json(const DeviationStatistics& s);
// Its reader: the same members, checked by `n` (a negative sigma or count
// is an InputError naming the member).
DeviationStatistics read_statistics(const JsonCursor& n);

// Every run setting of "options" except the tolerance, which comparison.json
// states as width + outside and report.json as the whole zone.
json run_options_json(const ComparisonDocument::Options& o);

// transform, placement, coarse start, RMS before/after, sigma, iteration
// counts, status, covariance and its standard deviations (null when the
// covariance is missing). Each file adds its own context around it.
json registration_json(const ComparisonDocument::Registration& r);

}  // namespace furrow::comparison_json
