#include "job/job_options.hpp"

#include "base/json_fields.hpp"
#include "stage/compare_options.hpp"
#include "stage/compensate_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/scan_options.hpp"
#include "stage/scan_simulation_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"

namespace furrow {


namespace jf = json_fields;
using jf::json;

namespace {

json bumps_json(const std::vector<SurfaceBump>& bumps) {
  json out = json::array();
  for (const SurfaceBump& b : bumps)
    out.push_back({json_fields::finite(b.centre.x(), "bump"), json_fields::finite(b.centre.y(), "bump"),
                   json_fields::finite(b.centre.z(), "bump"), json_fields::finite(b.radius, "bump"),
                   json_fields::finite(b.height, "bump")});
  return out;
}

}  // namespace

std::string job_options_json(const Job& job) {
  json j;
  j["name"] = job.name;
  j["description"] = job.description;
  j["part"] = job.part;
  j["tool"] = job.tool;
  j["pdf"] = job.pdf;
  j["paper"] = job.paper;
  if (job.generate) {
    j["toolpath"] = {{"generate", option_members(toolpath_option_table(), *job.generate)}};
  } else {
    j["toolpath"] = {{"file", *job.toolpath_file}, {"units", job.toolpath_read.units}};
    if (!job.tool_table.empty()) j["toolpath"]["tools"] = job.tool_table;
  }
  const ToleranceZone& z = job.compare.tolerance;
  j["tolerance"] = {{"zone", jf::finite(z.width, "zone")}, {"outside", jf::finite(z.outside, "outside")}};
  j["partition"] = option_members(partition_option_table(), job.partition);
  j["prediction"] = option_members(prediction_option_table(), job.prediction);
  // Only when given, so that a job without it echoes what it always did.
  if (!job.prediction.stock) j["prediction"].erase("stock");
  j["plan"] = option_members(plan_option_table(), job.plan);
  j["plan"]["prediction"] = job.plan_with_prediction;
  j["plan"]["allow_uncovered"] = job.plan_allow_uncovered;
  if (!job.head_file.empty()) {
    // The head gives the stylus and its length; echoing their values would
    // contradict it on reading.
    j["plan"]["head"] = job.head_file;
    for (const char* key : {"probe_diameter", "stylus_diameter", "stylus_length", "head_length"}) j["plan"].erase(key);
  }
  if (job.simulate) {
    const SimulationOptions& s = job.simulate->options;
    json simulate = option_members(simulation_option_table(), s);
    simulate["prediction"] = job.simulate->from_prediction;
    simulate["bumps"] = bumps_json(s.bumps);
    j["measurements"] = {{"simulate", std::move(simulate)}};
  } else if (job.scan) {
    json scan = option_members(scan_option_table(), job.scan->preprocessing);
    if (const auto& sim = job.scan->simulate) {
      json simulate = option_members(scan_simulation_option_table(), *sim);
      SimulationOptions placement;
      placement.misalignment = sim->scanner.part_to_scanner;
      placement.seed = sim->scanner.seed;
      simulate.update(option_members(scan_simulation_placement_table(), placement));
      simulate["bumps"] = bumps_json(sim->scanner.bumps);
      scan["simulate"] = std::move(simulate);
    } else {
      scan["file"] = job.scan->file;
    }
    scan["units"] = job.scan->units;
    j["measurements"] = {{"scan", std::move(scan)}};
  } else if (!job.measurement_files.empty()) {
    const MeasurementReadOptions& r = job.measurement_read;
    const json files = job.measurement_files.size() == 1 ? json(job.measurement_files[0]) : json(job.measurement_files);
    j["measurements"] = {{"file", files},
                         {"points", r.kind ? json(to_string(*r.kind)) : json(nullptr)},
                         {"probe_diameter", r.probe_diameter > 0 ? jf::finite(r.probe_diameter, "probe") : json(nullptr)},
                         {"units", r.units}};
    // The CSV dialect in force (the saved one merged with the job's members).
    const CsvDialect& d = r.dialect;
    j["measurements"]["delimiter"] = d.delimiter ? json(csv_delimiter_name(*d.delimiter)) : json(nullptr);
    j["measurements"]["decimal_comma"] = d.decimal_comma ? json(*d.decimal_comma) : json(nullptr);
    j["measurements"]["columns"] = d.columns.empty() ? json(nullptr) : json(d.columns);
    j["measurements"]["dialect"] = job.measurement_dialect_file.empty() ? json(nullptr) : json(job.measurement_dialect_file);
    j["measurements"]["ipp_program"] = r.ippdme_program.empty() ? json(nullptr) : json(r.ippdme_program);
  } else {
    j["measurements"] = nullptr;
  }
  j["comparison"] = option_members(compare_option_table(), job.compare);
  j["comparison"]["prediction"] = job.compare_with_prediction;
  if (!job.rps_file.empty()) j["comparison"]["rps"] = job.rps_file;
  // Only when given, so that a job without it echoes what it always did.
  if (job.compensate) {
    j["compensate"] = option_members(compensate_option_table(), *job.compensate);
    j["compensate"]["out"] = job.compensate_out;
  }
  j["output"] = job.output;
  return jf::to_text(j);
}

}  // namespace furrow
