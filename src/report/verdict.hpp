#pragma once
// The verdict a QA report opens with, derived from a comparison document:
// PASS or FAIL (the comparison's own decision: registration converged,
// every evaluated point inside the profile zone, no predicted gouge
// confirmed), the reasons for a FAIL in plain words, the profile value
// against the zone, and the gouge-site counts by status. Nothing here
// re-decides the comparison; it only gathers what the reader needs first.
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"

namespace furrow {

struct ReportVerdict {
  bool pass = false;
  std::vector<std::string> reasons;  // empty for PASS
  double profile = 0;                // 2 max |d| over evaluated points [mm]
  ToleranceZone zone;
  std::size_t evaluated = 0, out_of_tolerance = 0;
  bool registration_converged = false;
  // Gouge confirmation (all zero without a prediction).
  bool has_prediction = false;
  std::size_t sites = 0, confirmed = 0, not_confirmed = 0, not_measured = 0, unexplained = 0;
  std::optional<std::string> prediction_verdict;  // "explained", ... with a prediction

  const char* result() const { return pass ? "PASS" : "FAIL"; }
};

ReportVerdict report_verdict(const ComparisonDocument& doc);

}  // namespace furrow
