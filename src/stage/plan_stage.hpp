#pragma once
// The planning stage (`furrow plan`, and `furrow run`): probe points per
// region, and the plan folder's files — plan.json, plan.csv, the DMIS and
// I++ DME programs, the plan report and plan.png. One function for both
// callers, so a job's plan/ folder is the command's.
#include <string>
#include <vector>

#include "planning/part_setup.hpp"
#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "report/qa_report.hpp"

namespace furrow {

// One setup of a plan with several (docs/cmm.md "Setups").
struct SetupPlan {
  PartSetup setup;
  std::string folder;             // "setup1", "setup2", ...
  PlanResult result;              // in the setup frame
  PlanCoverage coverage;          // of the regions this setup planned
  std::string plan_json;
  double estimated_area = 0;      // further setups: reachable short area by the choice's estimate [mm^2]
  double choice_seconds = 0;      // wall clock of choosing the face (not in any file)
};

struct PlanStage {
  PlanResult result;              // plan.uncovered_regions filled from `coverage`; setup 1's with setups
  PlanCoverage coverage;          // with setups: combined over them (combine_coverage)
  std::string program;            // the CMM program name (NAME.dmi, NAME.prg)
  std::string plan_json;          // plan.json's text (also among `files`); setup 1's with setups
  std::vector<FolderFile> files;  // names relative to the plan folder
  // With more than one setup (options.setups > 1 or setup faces named):
  // each setup, its files under its folder in `files`, and report.json at
  // the top holding the coverage per setup and combined. Empty otherwise.
  std::vector<SetupPlan> setups;
  std::string note;               // why fewer setups were made than asked, or ""
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
// With several setups (docs/cmm.md "Setups"): setup 1 plans every region,
// each further one (greedy, planning/setup_choice.hpp, or the faces named)
// the regions still short for want of access, in its own frame, with its
// own alignment; its points are named "S<k>_..." so ids stay unique over
// the setups. Throws InputError naming a face that cannot carry the part.
PlanStage plan_stage(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
                     const std::string& program, const std::string& regions_name,
                     const std::string& prediction_name, const PlanProgress& progress = {});

}  // namespace furrow
