#include "job/pipeline.hpp"

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <fstream>
#include <optional>

#include "base/atomic_file.hpp"
#include "base/json_fields.hpp"
#include "base/text_fields.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/scan_comparison_file.hpp"
#include "inspection/scan_deviation_cloud.hpp"
#include "io/scan/scan_read.hpp"
#include "inspection/measurement_merge.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/cutter/path_tools.hpp"
#include "job/job_options.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "partition/region_image.hpp"
#include "partition/regions_file.hpp"
#include "planning/prediction_risk.hpp"
#include "stage/compare_stage.hpp"
#include "stage/compensate_stage.hpp"
#include "io/qif/plan_qif.hpp"
#include "stage/plan_stage.hpp"
#include "report/pdf_print.hpp"
#include "report/scan_report.hpp"
#include "stage/scan_compare_stage.hpp"
#include "stage/scan_simulate_stage.hpp"
#include "stage/predict_stage.hpp"
#include "stage/toolpath_stage.hpp"

namespace furrow {

namespace {

using Clock = std::chrono::steady_clock;

// Wall time of each stage, in order.
class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>& out) : out_(out), start_(Clock::now()), stage_start_(start_) {}
  void done(const std::string& stage) {
    const Clock::time_point now = Clock::now();
    out_.push_back({stage, std::chrono::duration<double>(now - stage_start_).count()});
    stage_start_ = now;
  }
  double total() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  std::vector<StageTime>& out_;
  Clock::time_point start_, stage_start_;
};

std::string as_text(const std::vector<unsigned char>& png) { return std::string(png.begin(), png.end()); }

std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

// `path` as seen from `folder` (both taken from the current directory), so
// that comparison.json names its sources relative to itself and `furrow
// report` finds them from anywhere (report_sources.hpp).
std::string relative_to_folder(const std::string& folder, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target = fs::absolute(path).lexically_normal();
  const fs::path relative = target.lexically_relative(fs::absolute(folder).lexically_normal());
  return relative.empty() ? target.string() : relative.string();
}

struct Staged {
  const Job& job;
  const PipelineProgress& progress;
  PipelineResult& result;
  std::vector<InputDigest> inputs;
  // How the generated files name the part: relative to the output folder,
  // as the commands run inside that folder would.
  std::string part_name;
  // Several measurement files merged by id (names relative to the output folder).
  std::optional<MergedMeasurements> merged;

  void add(const std::string& path, std::string bytes) { result.files.push_back({path, std::move(bytes)}); }
  // A generated file that a later stage reads: recorded with its digest.
  void add_input(const std::string& role, const std::string& path, std::string bytes) {
    inputs.push_back(digest_generated(role, path, bytes));
    add(path, std::move(bytes));
  }
  void note(const std::string& stage, std::size_t done = 0, std::size_t total = 0) const {
    if (progress) progress(stage, done, total);
  }
};

Toolpath toolpath_stage(Staged& s, const Part& part, const Cutter& cutter) {
  const Job& job = s.job;
  if (job.toolpath_file) return read_toolpath(*job.toolpath_file, job.toolpath_read);
  GeneratedToolpath generated = generate_toolpath(part, job.part, cutter, *job.generate,
                                                  [&](std::size_t d, std::size_t t) { s.note("toolpath", d, t); });
  s.add("toolpath.csv", std::move(generated.contacts_csv));
  s.result.summary.push_back(line("tool path: %zu passes, %zu contact points (generated)",
                                  generated.plan.passes.size(), generated.plan.points));
  Toolpath path = parse_gcode(generated.gcode, "toolpath.nc");
  s.add_input("toolpath", "toolpath.nc", std::move(generated.gcode));
  return path;
}

Prediction predict_stage(Staged& s, const Part& part, const PathTools& tools, const Toolpath& path,
                         const RegionMap& map) {
  const Job& job = s.job;
  const PredictionSources names{
      s.part_name, job.toolpath_file ? relative_to_folder(job.output, *job.toolpath_file) : "toolpath.nc",
      "regions.json"};
  PredictedPath predicted = predict_stage(part, tools, path, job.prediction, names, &map,
                                          [&](const std::string& stage, std::size_t d, std::size_t t) {
                                            s.note("predict: " + stage, d, t);
                                          });
  s.add("prediction.png", prediction_map_png(part, predicted, job.prediction, job.prediction_map_scale));
  std::string text = std::move(predicted.json);
  // Later stages see what prediction.json holds (its numbers are rounded).
  Prediction read_back = parse_prediction_json(text, "prediction.json");
  s.add_input("prediction", "prediction.json", std::move(text));
  const PredictionSummary& p = read_back.summary;
  s.result.summary.push_back(line("prediction: max undercut %.1f um, max overcut %.1f um, %zu gouge sites",
                                  p.max_undercut.error * 1000, p.max_overcut.error * 1000, p.gouge_sites));
  // Only when there is one, so a clean job's summary is what it was.
  s.result.rapid_gouges = read_back.rapids.gouges.size();
  for (const RapidGougeRecord& g : read_back.rapids.gouges)
    s.result.summary.push_back(line("RAPID GOUGE line %d (%s): %.4f mm deep at (%.3f, %.3f, %.3f)", g.line,
                                    g.kind.c_str(), g.depth, g.at.xyz.x(), g.at.xyz.y(), g.at.xyz.z()));
  return read_back;
}

InspectionPlan plan_stage(Staged& s, const Part& part, const RegionMap& map, const Prediction& prediction) {
  const Job& job = s.job;
  PlannerOptions o = job.plan;
  o.part_name = s.part_name;
  // The programs state the job's profile zone per point (TOL/PROFP).
  o.program.tolerance = PointProfileTolerance{job.compare.tolerance.lower(), job.compare.tolerance.upper()};
  std::optional<PredictionRiskMap> risk;
  if (job.plan_with_prediction) risk.emplace(prediction, part, "prediction.json", s.part_name);
  PlanStage stage = plan_stage(part, map, o, risk ? &*risk : nullptr, cmm_program_name(job.name, "furrow_job"),
                               "regions.json", job.plan_with_prediction ? "prediction.json" : "",
                               [&](const char* step, std::size_t d, std::size_t t) {
                                 s.note(std::string("plan: ") + step, d, t);
                               });
  InspectionPlan read_back = parse_plan(stage.plan_json, "plan/plan.json");
  stage.files.push_back({"plan.qif", plan_to_qif(read_back, s.part_name, job.compare.tolerance.width,
                                                 job.compare.tolerance.outside)});  // docs/qif.md
  for (FolderFile& f : stage.files) {
    if (f.path == "plan.json")
      s.add_input("plan", "plan/plan.json", std::move(f.bytes));
    else
      s.add("plan/" + f.path, std::move(f.bytes));
  }
  const PlanResult& r = stage.result;
  s.result.summary.push_back(line("plan: %zu points in %zu regions%s, cycle about %.1f min", r.plan.points.size(),
                                  r.regions.size(), job.plan_with_prediction ? " (risk-weighted)" : "",
                                  r.cycle.seconds / 60));
  const PlanCoverage& c = stage.coverage;
  s.result.plan_complete = c.complete();
  if (!c.complete()) {
    std::string detail = c.describe_uncovered();
    if (!detail.empty() && detail.back() == '\n') detail.pop_back();
    s.result.summary.push_back(line("plan coverage: %zu of %zu regions hold fewer than %d points%s:",
                                    c.regions.size() - static_cast<std::size_t>(c.regions_covered), c.regions.size(),
                                    o.min_per_region,
                                    job.plan_allow_uncovered ? " (accepted: allow_uncovered)" : "") +
                               "\n" + detail);
  }
  return read_back;
}

MeasurementSet measurement_stage(Staged& s, const InspectionPlan& plan, const Prediction& prediction) {
  const Job& job = s.job;
  MeasurementReadOptions read = job.measurement_read;
  if (read.probe_diameter == 0) read.probe_diameter = plan.probe.diameter;
  if (!job.simulate) {
    std::vector<MeasurementSet> sets;
    for (const std::string& f : job.measurement_files) sets.push_back(read_measurements(f, read));
    s.merged = merge_measurements(sets);
    for (std::size_t k = 0; k < job.measurement_files.size(); ++k) {
      s.merged->files[k] = relative_to_folder(job.output, job.measurement_files[k]);
      s.merged->sha256.push_back(digest_file("measurements", job.measurement_files[k]).sha256);
    }
    for (const MeasurementReplacement& m : s.merged->replaced)
      s.result.summary.push_back(line("re-measured: %s from %s replaces %s", m.id.c_str(),
                                      s.merged->files[m.by_file].c_str(), s.merged->files[m.file].c_str()));
    return s.merged->set;
  }
  SimulationOptions o = job.simulate->options;
  PredictedSurfaceOffsets machined;
  if (job.simulate->from_prediction) {
    machined = predicted_surface_offsets(plan, prediction);
    o.surface_offset = machined.lookup(plan);
  }
  const SimulatedMeasurement sim = simulate_measurement(plan, o, "plan/plan.json");
  std::string csv = measurements_to_csv(sim.set);
  read.kind = o.kind;
  MeasurementSet set = parse_measurements(csv, "measurements.csv", MeasurementFormat::csv, read);
  s.add_input("measurements", "measurements.csv", std::move(csv));
  s.result.summary.push_back(line("measurements: %zu simulated points (%s surface, noise %g mm, %d blunders, %zu "
                                  "bumps, seed %u)",
                                  set.points.size(), job.simulate->from_prediction ? "predicted" : "nominal",
                                  o.noise_sigma, o.blunders, o.bumps.size(), o.seed));
  return set;
}

ComparisonDocument compare_stage(Staged& s, const Part& part, const InspectionPlan& plan, const RegionMap& map,
                                 const Prediction& prediction, const MeasurementSet& all) {
  const Job& job = s.job;
  CompareOptions options = job.compare;
  options.registration.progress = [&](const std::string& what) { s.note("compare: " + what); };
  // With datums, the datum points set the frame and the rest are compared.
  const MeasurementSet compared = prepare_alignment(options, all, &plan, "plan/plan.json");
  if (s.merged) restrict_to(*s.merged, compared);
  const MeasurementSet& set = compared;
  const Comparison c =
      compare_stage(part, set, &plan, &map, job.compare_with_prediction ? &prediction : nullptr, options);
  ComparisonSources sources;
  sources.part = s.part_name;
  sources.measurements = job.simulate ? "measurements.csv" : relative_to_folder(job.output, job.measurement_files[0]);
  if (s.merged && job.measurement_files.size() > 1) {
    sources.merged = &*s.merged;
    sources.measurements.clear();  // as furrow compare names a merged set (measurement_merge.hpp)
    for (const std::string& f : s.merged->files) sources.measurements += (sources.measurements.empty() ? "" : " + ") + f;
  }
  sources.plan = "plan/plan.json";
  sources.regions = "regions.json";
  sources.prediction = job.compare_with_prediction ? "prediction.json" : "";
  sources.measurement_units = job.measurement_read.units;
  std::string text = comparison_to_json_text(c, set, part, options, sources);
  ComparisonDocument doc = parse_comparison(text, "comparison.json");
  s.add_input("comparison", "comparison.json", std::move(text));
  return doc;
}

// The compensation stage of `furrow compensate`, on the comparison.json the
// job wrote (read back, as the command reads it), the job's part, program
// and tool. A program the z-map check still refuses marks the result
// refused: nothing is written (docs/compensation.md "Safety"). Returns the
// record written (COMP.json's name), for the report's Compensation
// section; none when nothing was written.
std::optional<std::string> compensate_job_stage(Staged& s, const Part& part, const PathTools& tools,
                                                const std::optional<std::vector<ToolTableEntry>>& table) {
  const Job& job = s.job;
  std::string comparison_text, generated_program;
  for (const FolderFile& f : s.result.files) {
    if (f.path == "comparison.json") comparison_text = f.bytes;
    if (f.path == "toolpath.nc") generated_program = f.bytes;
  }
  const ComparisonDocument comparison = parse_comparison(comparison_text, "comparison.json");
  // A generated path: the G-code program the job wrote, as it wrote it.
  const std::string ext = job.toolpath_file ? lower_extension(*job.toolpath_file) : ".nc";
  const ProgramFormat format = ext == ".cl" || ext == ".apt" || ext == ".cls" ? ProgramFormat::apt : ProgramFormat::gcode;
  const std::string program = job.toolpath_file ? json_fields::read_text(*job.toolpath_file) : generated_program;
  const std::string program_name =
      job.toolpath_file ? relative_to_folder(job.output, *job.toolpath_file) : std::string("toolpath.nc");
  const std::string out = job.compensate_out;
  const std::string record = std::filesystem::path(out).replace_extension(".json").string();
  // The prediction of the program written (docs/compensation.md "Predicted
  // before it is cut"), beside it: comp.nc -> comp_prediction.json.
  const std::string predicted_name = std::filesystem::path(out).stem().string() + "_prediction.json";
  auto predict_written = [&](const std::string& text, ProgramFormat written_format) {
    const PredictedPath predicted = predict_compensated(part, read_tool_file(job.tool), job.tool, table,
                                                        job.tool_table, text, written_format, job.toolpath_read,
                                                        job.prediction, {s.part_name, out, ""});
    s.add(predicted_name, predicted.json);
  };
  const CompensateOptions& options = *job.compensate;
  const CompensatedProgram done =
      compensate_stage(part, tools, program, format, job.toolpath_read, comparison, options,
                       {s.part_name, "comparison.json", program_name, out, ""});
  if (!done.check.safe()) {
    const CompensationGougeCheck& c = done.check;
    s.result.compensation_refused = true;
    s.result.compensation_message =
        line("compensate: nothing written: after %d clip-back round%s the compensated program would still cut %.4f mm "
             "deeper than its offset allows at (%.3f, %.3f, %.3f), line %d (%zu z-map nodes at %.3f mm)",
             done.clip_back_rounds, done.clip_back_rounds == 1 ? "" : "s", c.worst_excess, c.worst.x(), c.worst.y(),
             c.worst.z(), c.worst_line, c.deeper, c.resolution);
    return std::nullopt;
  }
  if (done.rework) {
    // The rework program instead of the full one (docs/compensation.md
    // "Rework"): none when nothing needs re-cutting, refused as the full
    // program is when its check fails.
    const ReworkProgram& r = *done.rework;
    if (r.text.empty()) {
      s.result.summary.push_back(line("compensate: no rework needed (largest material left %.2f um, threshold "
                                      "%.2f um); nothing written",
                                      r.selection.largest_field * 1000, r.threshold * 1000));
      return std::nullopt;
    }
    if (!r.check.safe()) {
      s.result.compensation_refused = true;
      s.result.compensation_message =
          r.check.deeper > 0
              ? line("compensate: nothing written: the rework program would cut %.4f mm deeper than the compensated "
                     "program at (%.3f, %.3f, %.3f)",
                     r.check.worst_excess, r.check.worst.x(), r.check.worst.y(), r.check.worst.z())
              : line("compensate: nothing written: a rapid of the rework program (line %d) would cut %.4f mm into "
                     "the part at (%.3f, %.3f, %.3f)",
                     r.check.worst_rapid_line, r.check.worst_rapid_depth, r.check.worst_rapid.x(),
                     r.check.worst_rapid.y(), r.check.worst_rapid.z());
      return std::nullopt;
    }
    s.add(out, r.text);
    s.add_input("compensation", record, done.json);
    predict_written(r.text, format);
    s.result.summary.push_back(line("compensate: rework %s, %zu stretches in %zu regions, %zu of %zu moves re-cut "
                                    "beyond %.2f um",
                                    out.c_str(), r.selection.stretches.size(), r.selection.regions.size(),
                                    r.selection.moves_kept, r.selection.moves, r.threshold * 1000));
    return record;
  }
  s.add(out, done.program.text);
  s.add_input("compensation", record, done.json);
  predict_written(done.program.text, format);
  s.result.summary.push_back(line("compensate: %s, %zu tips moved, largest offset %.2f um, %zu clipped at %.2f um, "
                                  "%zu clipped back in %d round%s",
                                  out.c_str(), done.offset.moved, done.offset.largest_offset * 1000,
                                  done.offset.clipped.size(), options.max_offset * 1000, done.clip_back.size(),
                                  done.clip_back_rounds, done.clip_back_rounds == 1 ? "" : "s"));
  return record;
}

// What every report of a job says about the job: its name, description,
// inputs, options and inspection record, and when it was made.
ReportContext job_report_context(const Staged& s) {
  ReportContext context;
  context.title = s.job.name;
  context.description = s.job.description;
  context.generated = utc_timestamp();
  context.inputs = s.inputs;
  context.job_options_json = job_options_json(s.job);
  context.record = s.job.record;
  return context;
}

// PCL reads clouds from files: a job's simulated scan goes through a
// private temporary folder (removed at once, also on failure), so that the
// job reads the very bytes furrow compare would read from scan.ply.
ScanCloud read_scan_bytes(const std::string& bytes, const std::string& name, double mm_per_unit) {
  namespace fs = std::filesystem;
  std::string pattern = (fs::temp_directory_path() / "furrow-scan-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("the simulated scan: cannot create a temporary folder");
  const fs::path folder = pattern;
  struct Remove {
    fs::path path;
    ~Remove() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } remove{folder};
  const fs::path file = folder / name;
  {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("the simulated scan: cannot write " + file.string());
  }
  ScanCloud cloud = read_scan(file.string(), mm_per_unit);
  cloud.file = name;
  return cloud;
}

// A scan instead of probe points (docs/scan.md "In a job"): the cloud
// compared as `furrow compare --scan --regions regions.json --deviations
// deviations.ply` does, then the report of the scan as `furrow report`
// makes it from that comparison (read back from its text).
void scan_job_stages(Staged& s, const Part& part, const RegionMap& map, const Prediction& prediction,
                     const ProcessLookup& process, StageClock& clock) {
  const Job& job = s.job;
  ScanCloud cloud;
  if (job.scan->simulate) {
    // Simulated as furrow simulate-measurement --scan writes it, then read
    // back through the scan reader as compare reads that file: the cloud is
    // the file's, to the bit (the inch file's coordinates included).
    s.note("simulate scan");
    SimulatedScanFile simulated =
        simulate_scan_stage(part, *job.scan->simulate, std::filesystem::path(job.part).filename().string());
    cloud = read_scan_bytes(simulated.ply, "scan.ply", units_to_mm(job.scan->units, "measurements.scan.units"));
    s.add_input("scan", "scan.ply", std::move(simulated.ply));
    clock.done("simulate scan");
  } else {
    s.note("read scan");
    cloud = read_scan(job.scan->file, units_to_mm(job.scan->units, "measurements.scan.units"));
    // Named as the folder's files name it (relative to the folder), as the
    // deviation cloud of furrow compare run there names it.
    cloud.file = relative_to_folder(job.output, job.scan->file);
    clock.done("read scan");
  }
  s.note("compare");
  CompareOptions options = job.compare;
  options.registration.progress = [&](const std::string& what) { s.note("compare: " + what); };
  const ScanComparison c = compare_scan_stage(part, cloud, &map, job.compare_with_prediction ? &prediction : nullptr,
                                              options, job.scan->preprocessing);
  ScanComparisonSources sources;
  sources.part = s.part_name;
  sources.scan = cloud.file;
  sources.regions = "regions.json";
  sources.deviations = "deviations.ply";
  sources.units = job.scan->units;
  sources.prediction = job.compare_with_prediction ? "prediction.json" : "";
  s.add("deviations.ply", scan_deviation_ply(c, cloud));
  std::string text = scan_comparison_json(c, sources);
  const ScanComparisonDocument doc = parse_scan_comparison(text, "comparison.json");
  // The part's place in its batch, as for probe points (`furrow run --db`).
  std::optional<ProcessContext> batch;
  if (process) batch = process(text);
  s.add_input("comparison", "comparison.json", std::move(text));
  clock.done("compare");

  s.note("report");
  PipelineResult& result = s.result;
  ReportContext context = job_report_context(s);
  context.process = std::move(batch);
  const Clock::time_point report_start = Clock::now();
  const std::vector<ReportFigure> figures = make_scan_report_figures(doc, part, &map);
  context.stages = result.stages;
  context.stages.push_back({"report", std::chrono::duration<double>(Clock::now() - report_start).count()});
  context.total_seconds = clock.total();
  context.scan = std::make_shared<const ScanComparisonDocument>(doc);
  std::vector<FolderFile> report = render_report(scan_as_comparison(doc), &map, figures, context);
  clock.done("report");
  for (FolderFile& f : report) result.files.push_back(std::move(f));
  const ComparisonSummary& sum = doc.summary;
  result.measured = true;
  result.pass = sum.pass;
  result.verdict = sum.verdict;
  result.alignment = sum.alignment;
  result.summary.push_back(line("scan: %zu points read, %zu spray far, %zu spray near, %zu off the part; %zu compared",
                                doc.points.read, doc.points.spray_far, doc.points.spray_near, doc.points.off_part,
                                doc.points.kept));
  result.summary.push_back(line("verdict: %s (profile %.1f um, zone %.1f um, %zu of %zu points out of tolerance)",
                                to_string(sum.verdict), sum.profile * 1000, doc.tolerance.width * 1000,
                                sum.out_of_tolerance, sum.evaluated));
}

}  // namespace

PipelineResult run_job(const Job& job, const PipelineProgress& progress, const ProcessLookup& process) {
  PipelineResult result;
  StageClock clock(result.stages);
  Staged s{job, progress, result, {}, relative_to_folder(job.output, job.part), {}};

  s.note("reading inputs");
  if (!job.file.empty()) {
    s.inputs.push_back(digest_file("job", job.file));
    result.files.push_back({"job.json", json_fields::read_text(job.file)});
  }
  s.inputs.push_back(digest_file("part", job.part));
  s.inputs.push_back(digest_file("tool", job.tool));
  if (job.toolpath_file) s.inputs.push_back(digest_file("toolpath", *job.toolpath_file));
  std::optional<std::vector<ToolTableEntry>> table;
  if (!job.tool_table.empty()) {
    s.inputs.push_back(digest_file("tool table", job.tool_table));
    table = read_tool_table(job.tool_table);
    for (const ToolTableEntry& e : *table)
      if (!e.file.empty()) s.inputs.push_back(digest_file("tool", e.file));
  }
  for (const std::string& f : job.measurement_files) s.inputs.push_back(digest_file("measurements", f));
  if (!job.measurement_dialect_file.empty())
    s.inputs.push_back(digest_file("measurement dialect", job.measurement_dialect_file));
  if (!job.measurement_read.ippdme_program.empty())
    s.inputs.push_back(digest_file("I++ DME program", job.measurement_read.ippdme_program));
  if (job.scan && !job.scan->simulate) s.inputs.push_back(digest_file("scan", job.scan->file));
  if (!job.record_file.empty()) s.inputs.push_back(digest_file("record", job.record_file));
  if (!job.rps_file.empty()) s.inputs.push_back(digest_file("rps", job.rps_file));
  if (!job.head_file.empty()) s.inputs.push_back(digest_file("head", job.head_file));
  check_inputs_outside(job.output, s.inputs);  // before the work, not after it
  const Part part = read_part(job.part);
  const Cutter cutter(read_tool_file(job.tool));
  clock.done("read inputs");

  const PartitionResult partition = partition_part(part, job.partition, [&](std::size_t d, std::size_t t) {
    s.note("partition", d, t);
  });
  s.add_input("regions", "regions.json", regions_to_json_text(partition.map));
  s.add("regions.png", as_text(region_image_png(part, partition)));
  const RegionMap& map = partition.map;
  result.summary.push_back(line("partition: %zu regions on %zu faces", map.regions.size(), map.faces.size()));
  clock.done("partition");

  const Toolpath path = toolpath_stage(s, part, cutter);
  clock.done(job.generate ? "toolpath" : "read toolpath");
  // A CL file names its cutter: the job's tool must be that cutter, or the
  // prediction would be of a cut the program does not make (docs/formats.md
  // "APT CL data"); a program that changes tools takes them from the table.
  const PathTools tools = job.toolpath_file ? tools_for_path(path, read_tool_file(job.tool), job.tool, table, job.tool_table)
                                            : single_tool(cutter, path);
  const Prediction prediction = predict_stage(s, part, tools, path, map);
  clock.done("predict");
  const InspectionPlan plan = plan_stage(s, part, map, prediction);
  clock.done("plan");

  if (job.scan) {
    scan_job_stages(s, part, map, prediction, process, clock);
  } else if (job.has_measurements()) {
    const MeasurementSet set = measurement_stage(s, plan, prediction);
    clock.done(job.simulate ? "simulate measurement" : "read measurements");
    const ComparisonDocument doc = compare_stage(s, part, plan, map, prediction, set);
    clock.done("compare");
    // Compensated before the report, whose Compensation section shows what
    // the program is expected to leave (docs/report.md "Compensation").
    std::optional<CompensationRecord> compensation;
    std::string compensation_file;
    if (job.compensate) {
      s.note("compensate");
      if (const std::optional<std::string> name = compensate_job_stage(s, part, tools, table)) {
        for (const FolderFile& f : result.files)
          if (f.path == *name) compensation = parse_compensation_record(f.bytes, *name);
        check_record_against(*compensation, doc, *name);
        compensation_file = *name;
      }
      clock.done("compensate");
      if (result.compensation_refused) {  // nothing is written: no report either
        result.total_seconds = clock.total();
        result.inputs = s.inputs;
        return result;
      }
    }

    s.note("report");
    ReportContext context = job_report_context(s);
    context.compensation = std::move(compensation);
    context.compensation_file = compensation_file;
    if (process)
      for (const FolderFile& f : result.files)
        if (f.path == "comparison.json") context.process = process(f.bytes);
    // The report's stage time is that of its figures (the costly part): it
    // is printed in the report rendered right after.
    const Clock::time_point report_start = Clock::now();
    check_comparison_faces(doc, part);
    context.face_surfaces = face_surfaces(part, doc);
    const std::vector<ReportFigure> figures =
        make_report_figures(doc, part, &map, job.compare_with_prediction ? &prediction : nullptr,
                            context.compensation ? &*context.compensation : nullptr);
    context.stages = result.stages;
    context.stages.push_back({"report", std::chrono::duration<double>(Clock::now() - report_start).count()});
    context.total_seconds = clock.total();
    std::vector<FolderFile> report = render_report(doc, &map, figures, context);
    clock.done("report");
    for (FolderFile& f : report) result.files.push_back(std::move(f));
    result.measured = true;
    result.pass = doc.summary.pass;
    result.verdict = doc.summary.verdict;
    result.alignment = doc.summary.alignment;
    result.summary.push_back(line("verdict: %s (profile %.1f um, zone %.1f um, %zu of %zu points out of tolerance)",
                                  to_string(doc.summary.verdict), doc.summary.profile * 1000,
                                  doc.options.tolerance.width * 1000, doc.summary.out_of_tolerance,
                                  doc.summary.evaluated));
  } else {
    result.summary.push_back("no measurements in the job: stopped after the plan");
  }
  result.total_seconds = clock.total();
  result.inputs = s.inputs;
  return result;
}

void write_job_output(const Job& job, const PipelineResult& result) {
  check_inputs_outside(job.output, result.inputs);
  write_folder_atomically(job.output, [&](const std::string& staging) {
    write_folder_files(staging, result.files);
    // report.pdf from the written page, inside the staging folder: a failed
    // print leaves no folder behind, like any failed job.
    if (job.pdf && result.measured)
      print_pdf(staging + "/report.html", staging + "/report.pdf", PdfOptions{job.paper});
  });
}

}  // namespace furrow
