#pragma once
// A QA report folder (`furrow report`, and the last stage of `furrow run`):
//   report.html   self-contained (inline CSS, figures as data URIs): opens
//                 offline, in a mail client, from an archive
//   report.json   every number (docs/report.schema.json)
//   points.csv    one row per measured point
//   results.qif   the same as QIF 3.0 Results, timed like report.json (report_qif.hpp);
//                 not for a scan, whose points are in its deviation cloud
//   figures/*.png the figures of the HTML as files
// built from a comparison document (read_comparison) and the part it was
// made on, plus what the document cannot know: where it came from (input
// files with SHA-256), when (one timestamp), the options of the stages that
// produced it (a job) and how long they took.
//
// Determinism: the same document, part, partition and context give the same
// bytes; report.json differs between two runs on the same inputs only in
// "generated" (the timestamp) and "timing" (stage times), which is why the
// context carries them explicitly.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/compensation_record.hpp"
#include "inspection/scan_comparison_document.hpp"
#include "partition/region_map.hpp"
#include "report/inspection_record.hpp"
#include "report/process_context.hpp"
#include "report/report_figures.hpp"

namespace furrow {

struct InputDigest {
  std::string role;  // part, tool, toolpath, measurements, plan, regions, prediction, comparison, compensation, job,
                    // scan, deviation cloud
  std::string path;  // as used (a generated file: relative to the output folder)
  std::string sha256;
  std::uintmax_t bytes = 0;
  bool generated = false;  // written by the same run (furrow run), not given
};
// Digest of a file on disk (InputError naming `role` and the path if unreadable).
InputDigest digest_file(const std::string& role, const std::string& path);
// Digest of bytes about to be written as `path`.
InputDigest digest_generated(const std::string& role, const std::string& path, const std::string& bytes);

struct StageTime {
  std::string stage;
  double seconds = 0;
};

struct ReportContext {
  std::string title;                  // heading; e.g. the job's or the comparison's name
  std::string description;            // a paragraph under the heading (a job's), may be empty
  std::string generated;              // the timestamp, UTC ISO 8601 (utc_timestamp())
  std::vector<InputDigest> inputs;    // every file the verdict rests on
  std::string job_options_json;       // resolved stage options as a JSON object, "" without a job
  std::vector<StageTime> stages;      // empty unless the report ends a job run
  double total_seconds = 0;           // wall time of the run up to the report
  // Part number, serial, operator, sign-off... (inspection_record.hpp);
  // none: the report says that no record was given. Its file, when it came
  // from one, belongs in `inputs` (role "record").
  std::optional<InspectionRecord> record;
  // Where the part sits in its batch (process_context.hpp), when a results
  // database was given; none: the report has no Process section.
  std::optional<ProcessContext> process;
  // What a compensated program is expected to leave (a COMP.json of furrow
  // compensate, checked against the comparison: check_record_against), and
  // its file as named; none: the report has no Compensation section. The
  // file belongs in `inputs` too (role "compensation").
  std::optional<CompensationRecord> compensation;
  std::string compensation_file;
  // What each face of the part exactly is, indexed like Part::faces (from
  // face_surfaces below); unset for a free-form face. Empty: not known.
  std::vector<std::optional<AnalyticSurface>> face_surfaces;
  // The report of a scan (scan_report.hpp): what it read, kept and removed,
  // its registration, display sample and histogram; null for probe points.
  std::shared_ptr<const ScanComparisonDocument> scan;
};

// The elementary surface (plane, cylinder, cone, sphere, torus) of every
// face that carries measured points: the import's metadata where the part
// has it, else recognised from the NURBS (geometry/analytic_surface.hpp);
// unset for the other faces and for free-form ones. The metrologist reads a
// bore's radius and axis next to its deviations.
std::vector<std::optional<AnalyticSurface>> face_surfaces(const Part& part, const ComparisonDocument& doc);

// "2024-05-01T12:34:56Z", now.
std::string utc_timestamp();

// A file of the report folder: path relative to it, content.
struct FolderFile {
  std::string path;
  std::string bytes;
};

// Throws InputError when the document names a face the part does not have
// (a comparison of another part).
void check_comparison_faces(const ComparisonDocument& doc, const Part& part);

// Renders the whole folder in memory. `regions` may be null. Checks the
// faces first (check_comparison_faces).
// `prediction` (may be null) colours the 3D view's surface with the
// predicted error field.
std::vector<FolderFile> make_report(const ComparisonDocument& doc, const Part& part, const RegionMap* regions,
                                    const ReportContext& context, const Prediction* prediction = nullptr);
// The same in two steps, for a caller that times the figures (the costly
// part) and puts the time into the context: the figures come from
// make_report_figures (report_figures.hpp) after check_comparison_faces.
std::vector<FolderFile> render_report(const ComparisonDocument& doc, const RegionMap* regions,
                                      const std::vector<ReportFigure>& figures, const ReportContext& context);

// Throws InputError when a file of `inputs` (not generated) lies inside
// `folder`: replacing the folder as a whole would delete an input.
void check_inputs_outside(const std::string& folder, const std::vector<InputDigest>& inputs);

// Writes files into `folder` (write_file_atomically each; creates
// sub-folders). Call inside write_folder_atomically for a whole-or-nothing
// folder.
void write_folder_files(const std::string& folder, const std::vector<FolderFile>& files);

}  // namespace furrow
