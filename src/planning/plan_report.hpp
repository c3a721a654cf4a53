#pragma once
// report.json of a plan folder: what was asked, what was decided and what
// went wrong, for people and for tools (docs/formats.md "Plan report").
//
// Holds the resolved options, the allocation per region (area, curvature
// spread, risk, weight, allocated / sampled / moved / dropped / planned),
// the coverage per region and face (what each needs, holds and why it is
// short), every issue with its reason (points moved or dropped and why, regions too
// small, gouge sites without points, a budget raised to the floors), the
// tour (nearest-neighbour and final length, passes, convergence) and the
// cycle estimate, and the part alignment (method, reason, the points of each
// datum feature or of the manual best fit) when the plan has one. Deterministic: no timings, no dates.
#include <string>

#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

// `prediction_path` empty when the plan was made without a prediction.
std::string plan_report_json(const PlanResult& result, const PlanCoverage& coverage, const PlannerOptions& options, const std::string& part_path,
                             const std::string& regions_path, const std::string& prediction_path = "");

}  // namespace furrow
