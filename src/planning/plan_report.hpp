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
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

// `prediction_path` empty when the plan was made without a prediction.
std::string plan_report_json(const PlanResult& result, const PlanCoverage& coverage, const PlannerOptions& options, const std::string& part_path,
                             const std::string& regions_path, const std::string& prediction_path = "");

// The coverage object of report.json ("coverage"): counts, areas by state
// and by access problem, faces, the short regions with their reasons.
nlohmann::json coverage_json(const PlanCoverage& coverage);

// A setup of a plan with several, for the top-level report.json.
struct SetupSummary {
  int index = 1;
  std::string folder;
  std::optional<int> resting_face;  // none in setup 1
  std::string resting_face_name;
  bool named = false;               // from --setup-faces
  double estimated_area = 0;        // the choice's estimate [mm^2]
  Eigen::Isometry3d to_setup = Eigen::Isometry3d::Identity();
  std::size_t points = 0;
  std::vector<PlanTip> tips;
  const PlanCoverage* coverage = nullptr;  // of that setup; not null
};

// The top-level report.json of `furrow plan --setups` (docs/formats.md
// "Plan report"): each setup (frame, points, tips, coverage) and the
// combined coverage with the setup each region's state comes from.
std::string setups_report_json(const std::vector<SetupSummary>& setups, const PlanCoverage& combined,
                               const std::string& part_path, const std::string& regions_path, const std::string& note);

}  // namespace furrow
