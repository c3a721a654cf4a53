#pragma once
// The planning stage (`furrow plan`, and `furrow run`): probe points per
// region, and the plan folder's files — plan.json, plan.csv, the DMIS and
// I++ DME programs, the plan report and plan.png. One function for both
// callers, so a job's plan/ folder is the command's.
#include <string>
#include <vector>

#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "report/qa_report.hpp"

namespace furrow {

struct PlanStage {
  PlanResult result;              // plan.uncovered_regions filled from `coverage`
  PlanCoverage coverage;
  std::string program;            // the CMM program name (NAME.dmi, NAME.prg)
  std::string plan_json;          // plan.json's text (also among `files`)
  std::vector<FolderFile> files;  // names relative to the plan folder
};

// A CMM program name from any text (a folder or job name): letters, digits,
// '_' and '-', other characters replaced by '_', at most 64 characters;
// `fallback` when nothing is left.
std::string cmm_program_name(const std::string& text, const std::string& fallback);

// `options.part_name` names the part in the files; `regions_name` and
// `prediction_name` ("" without a prediction) are recorded in the plan
// report. `risk` may be null. Throws InputError for options the planner refuses.
// A plan that leaves regions below their minimum is still made and written:
// `coverage` says which and why; the caller decides what that means for its
// exit status (docs/cmm.md "Coverage").
PlanStage plan_stage(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
                     const std::string& program, const std::string& regions_name,
                     const std::string& prediction_name, const PlanProgress& progress = {});

}  // namespace furrow
