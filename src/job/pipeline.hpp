#pragma once
// One inspection job end to end (`furrow run job.json`, `furrow demo`):
//   partition -> tool path (read, or generated) -> predict -> plan
//   -> measurements (read, or simulated) -> compare (regions, prediction,
//   gouge confirmation) -> report
// with the library functions the single commands use, in the same order
// and with the same files in between: each stage's output is rendered to
// the text its command writes and the next stage reads that text back, so a
// job gives exactly what the chain of commands would (prediction.json, for
// one, rounds its numbers, and the plan works from the rounded ones).
// Without measurements the job stops after the plan.
//
// Everything is rendered in memory first; write_job_output() then replaces
// the output folder as a whole (write_folder_atomically), so a failed job
// leaves no half-written folder:
//   job.json            the job file as given (absent for a job built in code)
//   regions.json, regions.png
//   toolpath.nc, toolpath.csv     (generated paths only)
//   prediction.json, prediction.png
//   plan/               plan.json, plan.csv, NAME.dmi, NAME.prg, plan.png, coverage.png, report.json,
//                       plan.qif (docs/qif.md)
//   measurements.csv    (simulated measurements only)
//   comparison.json
//   report.html, report.json, points.csv, results.qif, figures/*.png   (qa_report.hpp)
//   COMP.nc|COMP.apt, COMP.json   ("compensate": the program moved by the
//                       measured error field, compensate_stage.hpp)
// The paths inside comparison.json are relative to the output folder (the
// part's and a measurement file's too), so `furrow report OUT/comparison.json`
// finds them from any directory.
//
// Deterministic: the same job gives the same files, except the report's
// timestamp and stage times (qa_report.hpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "job/job.hpp"
#include "report/qa_report.hpp"

namespace furrow {

// (stage, done, total); total 0 when a stage cannot count its work. Calls
// never overlap but may come from worker threads.
using PipelineProgress = std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

struct PipelineResult {
  std::vector<FolderFile> files;  // the output folder, rendered
  std::vector<StageTime> stages;  // wall time per stage
  std::vector<InputDigest> inputs;  // files given and files generated for later stages
  double total_seconds = 0;
  bool measured = false;  // the job had measurements: comparison and report exist
  bool pass = false;      // the verdict is PASS (when measured)
  Verdict verdict = Verdict::fail;  // when measured
  std::string alignment = "ok";     // when measured: the comparison's alignment state
  bool plan_complete = true;        // every region holds its minimum of plan points
  std::size_t rapid_gouges = 0;     // rapids into the part or stock: the job fails (docs/architecture.md "Rapid moves")
  std::vector<std::string> summary;  // a few lines for people
  // "compensate": the z-map check still failed after the clip-back rounds;
  // the caller writes nothing and exits 3 (docs/compensation.md "Safety").
  bool compensation_refused = false;
  std::string compensation_message;  // why, when refused
};

// The part's place in its batch for the report's Process section, from the
// comparison.json text the job made (`furrow run --db`: the results
// database with this part appended, report/process_context.hpp); none
// without a database.
using ProcessLookup = std::function<std::optional<ProcessContext>(const std::string& comparison_text)>;

// Throws InputError for bad inputs (file, field or option named).
PipelineResult run_job(const Job& job, const PipelineProgress& progress = {}, const ProcessLookup& process = {});

// Replaces job.output atomically with result.files. Throws InputError when
// an input file lies inside job.output (replacing it would delete it).
void write_job_output(const Job& job, const PipelineResult& result);

}  // namespace furrow
