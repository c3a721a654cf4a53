#pragma once
// The verdict a QA report opens with, derived from a comparison document:
// PASS, FAIL or INCONCLUSIVE (the comparison's own decision, rules in
// inspection/comparison.hpp), the reasons in plain words (what failed, or
// what must be measured again before the part can pass), the profile value
// against the zone, and the gouge-site counts by status. Nothing here
// re-decides the comparison; it only gathers what the reader needs first.
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"

namespace furrow {

struct ReportVerdict {
  Verdict verdict = Verdict::fail;
  bool pass = false;                 // verdict == PASS
  std::vector<std::string> reasons;  // empty for PASS
  std::vector<InconclusiveReason> inconclusive;  // the INCONCLUSIVE reasons as data
  double profile = 0;                // 2 max |d| over evaluated points [mm]
  ToleranceZone zone;
  std::size_t evaluated = 0, out_of_tolerance = 0;
  bool registration_converged = false;
  std::string alignment = "ok";  // the comparison's alignment state (comparison.hpp)
  // Gouge confirmation (all zero without a prediction).
  bool has_prediction = false;
  std::size_t sites = 0, confirmed = 0, not_confirmed = 0, not_measured = 0, unexplained = 0;
  std::optional<std::string> prediction_verdict;  // "explained", ... with a prediction

  const char* result() const { return to_string(verdict); }
};

ReportVerdict report_verdict(const ComparisonDocument& doc);

}  // namespace furrow
