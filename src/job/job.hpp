#pragma once
// A job file (job.json): one inspection job end to end, for `furrow run`
// and `furrow demo` (docs/formats.md "Job file"). It names the part, the
// tool, the tool path (a file, or options to generate one), the profile
// tolerance, the options of every stage and the measurements (a file, or a
// simulation of them - a test and demo aid), and the output folder.
//
// Paths in the file are relative to the job file's folder (so a job and its
// inputs can move together); read_job() resolves them. Every member is
// checked: unknown keys are errors (a typo must never run silently with a
// default), as are wrong types, out-of-range numbers and missing required
// members - InputError naming the file and the field ("job.json:
// plan.density: expected a positive number").
//
// The option structs are the library's own, so a job runs exactly what the
// matching command-line options would (the defaults are the commands').
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/prediction/path_prediction.hpp"
#include "partition/partition.hpp"
#include "planning/probe_planner.hpp"
#include "report/inspection_record.hpp"
#include "stage/compensate_options.hpp"
#include "stage/toolpath_stage.hpp"
#include "io/scan/scan_preprocess.hpp"
#include "stage/scan_simulation_options.hpp"

namespace furrow {

constexpr int kJobFormatVersion = 1;

// `furrow simulate-measurement` options: CMM points of the plan on the part
// as machined (nominal + predicted error when `from_prediction`), plus any
// planted bumps, misaligned, with noise and blunders.
struct MeasurementSimulationJob {
  bool from_prediction = true;
  SimulationOptions options;  // surface_offset is set by the pipeline
};

// A dense scan compared instead of probe points ("measurements": {"scan":
// {...}}; docs/scan.md "In a job"): the cloud file, its units and the
// pre-processing options of furrow compare --scan. Or, with "simulate"
// instead of "file", a simulated scan: the scanner model of furrow
// simulate-measurement --scan (its option table, with "misalign", "seed"
// and "bumps" as a probe-point simulation takes them), which the job writes
// as scan.ply in its folder and compares as that file.
struct ScanJob {
  std::string file;  // resolved path; empty for a simulated scan
  std::string units = "mm";
  ScanPreprocessOptions preprocessing;
  std::optional<ScanSimulationOptions> simulate;  // placement, seed and bumps in its scanner
};

struct Job {
  std::string file;    // the job file as given ("" for a job built in code)
  std::string folder;  // its folder: relative paths were resolved against it
  std::string name;    // "name", default the job file's stem
  std::string description;  // free text for people, optional
  std::string part, tool;  // resolved paths

  // Tool path: a file, or generated (exactly one of the two).
  std::optional<std::string> toolpath_file;
  ToolpathReadOptions toolpath_read;
  // Tool table of a program that changes tools (toolpath.tools; io/machining/tool_file.hpp);
  // empty: none, every pass is cut with `tool`.
  std::string tool_table;
  std::optional<ToolpathGeneration> generate;

  PartitionOptions partition;
  PathPredictionOptions prediction;
  double prediction_map_scale = 0;  // [mm] colour saturation of prediction.png; 0: 2 x tolerance

  PlannerOptions plan;
  std::string head_file;  // plan.head: the indexable head (plan.head set from it); empty: none
  bool plan_with_prediction = true;  // risk-weighted plan, points on every gouge site
  bool plan_allow_uncovered = false;  // a plan with regions below their minimum is not an error (docs/cmm.md "Coverage")

  // Measurements: files (several: a re-measure, merged by id in this order,
  // measurement_merge.hpp), a simulation, or neither (the job stops after the plan).
  std::vector<std::string> measurement_files;
  std::string rps_file;  // comparison.rps: the reference point system of "align": "rps" (in compare.rps); empty: none
  std::string measurement_dialect_file;  // a saved CSV dialect (measurement_read.dialect comes from it); empty: none
  MeasurementReadOptions measurement_read;  // probe diameter 0: the plan's probe
  std::optional<MeasurementSimulationJob> simulate;
  std::optional<ScanJob> scan;  // a scan instead (then no probe-point measurements)

  CompareOptions compare;              // tolerance zone, registration, verification rules
  bool compare_with_prediction = true;  // predicted vs measured, gouge confirmation

  // "compensate": the program moved by the measured error field, written
  // into the output folder as `compensate_out` (a bare file name in the
  // program's own format) with its record beside it (docs/compensation.md
  // "In a job"). Needs measurements and a G-code or APT CL toolpath file.
  std::optional<CompensateOptions> compensate;
  std::string compensate_out;

  std::string output;  // resolved output folder
  bool pdf = false;            // "pdf": also report.pdf, printed by headless Chromium (report/pdf_print.hpp)
  std::string paper = "a4";    // "paper": a4 or letter

  // The inspection record for the report header, QIF and sign-off
  // (report/inspection_record.hpp): "record" is a file name (record_file,
  // resolved; digested as an input) or the record inline; none: the report
  // says no record was given.
  std::optional<InspectionRecord> record;
  std::string record_file;

  bool has_measurements() const { return !measurement_files.empty() || simulate.has_value() || scan.has_value(); }
};

// Reads and checks a job file; relative paths become relative to its folder
// (joined with it, so they stay relative when the job path is relative).
Job read_job(const std::string& path);
// `name` stands for the source in messages; `folder` is where relative paths
// in the text start.
Job parse_job(const std::string& text, const std::string& name, const std::string& folder);

}  // namespace furrow
