#include "job/job.hpp"

#include <filesystem>
#include <set>

#include "base/error.hpp"
#include "report/print_style.hpp"
#include "base/text_fields.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "stage/compare_options.hpp"
#include "stage/compare_stage.hpp"
#include "stage/compensate_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/scan_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

// One JSON object of the job: members are read by name and remembered, so
// that finish() can refuse the ones nobody read (typos, unknown options).

// Library validators speak in command-line option names; in a job file the
// section is named first so the user finds the member.
template <class F>
void with_context(const std::string& where, F&& check) {
  try {
    check();
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

std::string resolve(const std::string& folder, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || folder.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(folder) / p).lexically_normal().string();
}

std::string path_member(const JsonCursor& s, const std::string& key, const std::string& folder) {
  const std::string text = jf::string(s.raw(key), s.path(key));
  if (text.empty()) throw InputError(s.path(key) + ": empty path");
  return resolve(folder, text);
}

void read_generation(const JsonCursor& g, Job& job) {
  ToolpathGeneration gen;
  read_option_members(g, toolpath_option_table(), gen);
  g.finish("docs/formats.md \"Job file\"");
  job.generate = gen;
}

void read_toolpath(const JsonCursor& root, Job& job, const std::string& folder) {
  const json& value = root.raw("toolpath");
  const std::string where = root.path("toolpath");
  if (value.is_string()) {
    job.toolpath_file = path_member(root, "toolpath", folder);
    return;
  }
  JsonCursor t(value, where);
  if (auto g = t.optional_at("generate")) {
    read_generation(*g, job);
  } else if (t.find("file")) {
    job.toolpath_file = path_member(t, "file", folder);
    if (const auto units = t.optional_string("units")) job.toolpath_read.units = *units;
    if (t.find("tools")) job.tool_table = path_member(t, "tools", folder);
  } else {
    throw InputError(where + ": expected a file name, {\"file\": ...} or {\"generate\": {...}}");
  }
  t.finish("docs/formats.md \"Job file\"");
}

void read_tolerance(const JsonCursor& root, Job& job) {
  const json& value = root.raw("tolerance");
  const std::string where = root.path("tolerance");
  double zone = 0;
  std::optional<double> outside;
  if (value.is_number()) {
    zone = jf::positive_number(value, where);
  } else {
    JsonCursor t(value, where);
    zone = jf::positive_number(t.raw("zone"), t.path("zone"));
    t.non_negative("outside", outside);
    t.finish("docs/formats.md \"Job file\"");
  }
  job.compare.tolerance = ToleranceZone::make(zone, outside.value_or(zone / 2), where);
}

void read_partition(const JsonCursor& p, Job& job) {
  read_option_members(p, partition_option_table(), job.partition);
  check_partition_options(job.partition, p.where());
  p.finish("docs/formats.md \"Job file\"");
}

void read_prediction(const JsonCursor& p, Job& job) {
  read_option_members(p, prediction_option_table(), job.prediction);
  p.positive("map_scale", job.prediction_map_scale);
  p.finish("docs/formats.md \"Job file\"");
}

void read_plan(const JsonCursor& p, Job& job, const std::string& folder) {
  PlannerOptions& o = job.plan;
  p.boolean("prediction", job.plan_with_prediction);
  p.boolean("allow_uncovered", job.plan_allow_uncovered);
  read_option_members(p, plan_option_table(), o);
  if (p.find("head")) {
    job.head_file = path_member(p, "head", folder);
    const bool stylus_given = stylus_changed(o) || p.find("probe_diameter") || p.find("stylus_diameter") ||
                              p.find("stylus_length");
    use_head_file(o, job.head_file, stylus_given, kHeadJobMembers);
  }
  p.finish("docs/formats.md \"Job file\"");
  with_context(p.where(), [&] { validate(o); });
  if (needs_risk(o.strategy) && !job.plan_with_prediction)
    throw InputError(p.path("strategy") + ": the risk strategy needs the prediction (\"prediction\": true)");
  // A job compares one plan folder's measurements (docs/cmm.md "Setups").
  if (setup_count(o) > 1)
    throw InputError(p.path(p.find("setups") ? "setups" : "setup_faces") +
                     ": a job plans and compares one setup; plan several with furrow plan --setups");
}

// "bumps": [[x, y, z, radius, height], ...] in mm.
std::vector<SurfaceBump> read_bumps(const JsonCursor& s) {
  std::vector<SurfaceBump> out;
  if (const json* bumps = s.find("bumps")) {
    const json& list = jf::array(*bumps, s.path("bumps"));
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string where = jf::child(s.path("bumps"), k);
      const std::vector<double> v = jf::numbers(list[k], where);
      if (v.size() != 5) throw InputError(where + ": expected [x, y, z, radius, height] in mm");
      if (!(v[3] > 0)) throw InputError(where + ": the radius must be positive");
      out.push_back({Eigen::Vector3d(v[0], v[1], v[2]), v[3], v[4]});
    }
  }
  return out;
}

void read_simulation(const JsonCursor& s, Job& job) {
  MeasurementSimulationJob sim;
  SimulationOptions& o = sim.options;
  s.boolean("prediction", sim.from_prediction);
  read_option_members(s, simulation_option_table(), o);
  o.bumps = read_bumps(s);
  s.finish("docs/formats.md \"Job file\"");
  job.simulate = sim;
}

// measurements.scan.simulate: the scanner model's options, and the
// placement, seed and bumps of the measurement simulation (the members
// furrow simulate-measurement --scan takes).
ScanSimulationOptions read_scan_simulation(const JsonCursor& s) {
  ScanSimulationOptions o;
  read_option_members(s, scan_simulation_option_table(), o);
  SimulationOptions common;
  read_option_members(s, scan_simulation_placement_table(), common);
  o.scanner.part_to_scanner = common.misalignment;
  o.scanner.seed = common.seed;
  o.scanner.bumps = read_bumps(s);
  s.finish("docs/formats.md \"Job file\"");
  return o;
}

// The CSV dialect and the I++ DME program of a measurement file, as
// `furrow compare` takes them (docs/formats.md "Measurements"), checked
// here, before any stage runs.
void read_measurement_dialect(const JsonCursor& m, Job& job, const std::string& folder) {
  MeasurementReadOptions& r = job.measurement_read;
  CsvDialect base;
  if (m.find("dialect")) {
    job.measurement_dialect_file = path_member(m, "dialect", folder);
    base = read_csv_dialect(job.measurement_dialect_file);
    if (base.units && m.find("units") && *base.units != r.units)
      throw InputError(m.path("units") + ": \"" + r.units + "\" contradicts the units \"" + *base.units + "\" of " +
                       job.measurement_dialect_file);
    if (base.units) r.units = *base.units;
  }
  std::optional<char> delimiter;
  if (const auto d = m.optional_string("delimiter")) delimiter = parse_csv_delimiter(*d, m.path("delimiter"));
  std::optional<bool> decimal_comma;
  if (m.find("decimal_comma")) {
    bool value = false;
    m.boolean("decimal_comma", value);
    decimal_comma = value;
  }
  std::map<std::string, std::string> columns;
  if (auto c = m.optional_at("columns")) {
    for (const char* field : {"id", "x", "y", "z", "i", "j", "k", "nx", "ny", "nz"})
      if (const auto header = c->optional_string(field)) {
        if (trim(*header).empty()) throw InputError(c->path(field) + ": an empty header name");
        columns[field] = trim(*header);
      }
    c->finish("docs/formats.md \"Job file\"");
  }
  r.dialect = merge_csv_dialect(base, delimiter, decimal_comma, columns, m.where());
  units_to_mm(r.units, m.path("units"));
  if (m.find("ipp_program")) r.ippdme_program = path_member(m, "ipp_program", folder);
}

// A file name or a list of them (a re-measure: merged by id in list order).
std::vector<std::string> measurement_paths(const json& value, const std::string& where, const std::string& folder) {
  std::vector<std::string> paths;
  if (value.is_array()) {
    if (value.empty()) throw InputError(where + ": an empty list of measurement files");
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::string at = jf::child(where, k);
      const std::string text = jf::string(value[k], at);
      if (text.empty()) throw InputError(at + ": empty path");
      paths.push_back(resolve(folder, text));
    }
    return paths;
  }
  const std::string text = jf::string(value, where);
  if (text.empty()) throw InputError(where + ": empty path");
  return {resolve(folder, text)};
}

void read_measurements(const JsonCursor& root, Job& job, const std::string& folder) {
  const json* value = root.find("measurements");
  if (!value) return;
  const std::string where = root.path("measurements");
  if (value->is_string() || value->is_array()) {
    job.measurement_files = measurement_paths(*value, where, folder);
    return;
  }
  JsonCursor m(*value, where);
  if (auto sim = m.optional_at("simulate")) {
    read_simulation(*sim, job);
  } else if (auto scan = m.optional_at("scan")) {
    ScanJob sj;
    if (auto sim = scan->optional_at("simulate")) {
      if (scan->find("file"))
        throw InputError(scan->path("file") + ": a simulated scan is written by the job (scan.ply in its folder): "
                                              "give \"file\" or \"simulate\", not both");
      sj.simulate = read_scan_simulation(*sim);
      sj.units = sj.simulate->inch ? "inch" : "mm";
    } else {
      sj.file = path_member(*scan, "file", folder);
    }
    if (const auto units = scan->optional_string("units")) {
      if (*units != "mm" && *units != "inch") throw InputError(scan->path("units") + ": expected mm or inch");
      if (sj.simulate && *units != sj.units)
        throw InputError(scan->path("units") + ": the simulated scan is written in " + sj.units +
                         " (simulate.scan_inch)");
      sj.units = *units;
    }
    read_option_members(*scan, scan_option_table(), sj.preprocessing);
    scan->finish("docs/formats.md \"Job file\"");
    job.scan = sj;
  } else if (const json* files = m.find("file")) {
    job.measurement_files = measurement_paths(*files, m.path("file"), folder);
    if (const auto kind = m.optional_string("points")) job.measurement_read.kind = parse_probe_point_kind(*kind, m.path("points"));
    m.positive("probe_diameter", job.measurement_read.probe_diameter);
    if (const auto units = m.optional_string("units")) job.measurement_read.units = *units;
    read_measurement_dialect(m, job, folder);
  } else {
    throw InputError(where + ": expected a file name, a list of them, {\"file\": ...}, {\"simulate\": {...}} or "
                             "{\"scan\": {...}}");
  }
  m.finish("docs/formats.md \"Job file\"");
}

void read_comparison(const JsonCursor& c, Job& job, const std::string& folder) {
  read_option_members(c, compare_option_table(), job.compare);
  c.boolean("prediction", job.compare_with_prediction);
  if (c.find("rps")) {
    job.rps_file = path_member(c, "rps", folder);
    job.compare.rps = read_reference_points(job.rps_file);
  }
  if ((job.compare.align == AlignMethod::rps) != job.compare.rps.has_value())
    throw InputError(job.compare.rps ? c.path("rps") + ": the reference point system is for \"align\": \"rps\""
                                     : c.path("align") + ": rps needs the reference point system (\"rps\": FILE)");
  c.finish("docs/formats.md \"Job file\"");
}

bool is_apt_extension(const std::string& ext) { return ext == ".cl" || ext == ".apt" || ext == ".cls"; }

// The compensation member, checked against the rest of the job before any
// work: it moves the program the job read, after the comparison it made.
void read_compensate(const JsonCursor& c, Job& job) {
  CompensateOptions options;
  read_option_members(c, compensate_option_table(), options);
  const std::string out = jf::string(c.raw("out"), c.path("out"));
  c.finish("docs/formats.md \"Job file\"");
  if (options.rework_threshold && !options.rework)
    throw InputError(c.path("rework_threshold") + ": is given without \"rework\": true");
  if (out.empty() || out.find('/') != std::string::npos || out.find('\\') != std::string::npos || out == "." ||
      out == "..")
    throw InputError(c.path("out") + ": expected a file name inside the output folder, got '" + out + "'");
  // A generated path is compensated as the G-code program the job writes
  // (toolpath.nc, docs/compensation.md "In a job").
  const std::string ext = job.toolpath_file ? lower_extension(*job.toolpath_file) : ".nc";
  if (ext == ".csv" || ext == ".txt")
    throw InputError(c.where() + ": compensation writes the program back: the toolpath must be the G-code program or "
                     "the APT CL file, not a CSV path");
  if (!job.tool_table.empty() && options.rework)
    throw InputError(c.where() + ": the program changes tools (toolpath.tools); \"rework\" takes a program of one "
                     "tool");
  if (!job.has_measurements())
    throw InputError(c.where() + ": compensation needs the measured comparison: the job has no \"measurements\"");
  if (job.scan) throw InputError(c.where() + ": compensation is made from probe points, not from a scan");
  const std::string out_ext = lower_extension(out);
  if (out_ext == ".json")
    throw InputError(c.path("out") + ": expected a program file name (its record is written beside it as .json)");
  if (is_apt_extension(out_ext) != is_apt_extension(ext))
    throw InputError(c.path("out") + ": the compensated program is written in the format it was read in (" +
                     (is_apt_extension(ext) ? "APT CL: .apt, .cl or .cls" : "G-code: not .apt, .cl or .cls") + ")");
  job.compensate = options;
  job.compensate_out = out;
}

}  // namespace

Job parse_job(const std::string& text, const std::string& name, const std::string& folder) {
  const json doc = jf::parse_text(text, name);
  JsonCursor root(doc, name + ":");
  Job job;
  job.file = name;
  job.folder = folder;
  if (const json* v = root.find("version")) {
    if (jf::integer(*v, root.path("version")) != kJobFormatVersion)
      throw InputError(root.path("version") + ": this furrow reads job files of version " +
                       std::to_string(kJobFormatVersion));
  }
  job.name = root.optional_string("name").value_or(std::filesystem::path(name).stem().string());
  if (job.name.empty()) throw InputError(root.path("name") + ": empty name");
  job.description = root.optional_string("description").value_or("");
  job.part = path_member(root, "part", folder);
  job.tool = path_member(root, "tool", folder);
  read_toolpath(root, job, folder);
  read_tolerance(root, job);
  if (auto s = root.optional_at("partition")) read_partition(*s, job);
  if (auto s = root.optional_at("prediction")) read_prediction(*s, job);
  if (auto s = root.optional_at("plan")) read_plan(*s, job, folder);
  read_measurements(root, job, folder);
  if (auto s = root.optional_at("comparison")) read_comparison(*s, job, folder);
  if (const json* v = root.find("record")) {
    if (v->is_string()) {
      job.record_file = path_member(root, "record", folder);
      job.record = read_inspection_record(job.record_file);
    } else if (v->is_object()) {
      job.record = parse_inspection_record(v->dump(), root.path("record"));
    } else {
      throw InputError(root.path("record") + ": expected a record file name or the record as an object");
    }
  }
  if (auto s = root.optional_at("compensate")) read_compensate(*s, job);
  job.output = path_member(root, "output", folder);
  root.boolean("pdf", job.pdf);
  if (auto paper = root.optional_string("paper")) job.paper = *paper;
  paper_size_css(job.paper, root.path("paper"));  // a4 or letter, checked before any work
  root.finish("docs/formats.md \"Job file\"");
  scale_registration_to_tolerance(job.compare);
  for (const std::string* input :
       {&job.part, &job.tool, &job.record_file, &job.tool_table, &job.rps_file, &job.head_file})
    if (*input == job.output) throw InputError(root.path("output") + ": the output folder is an input file");
  return job;
}

Job read_job(const std::string& path) {
  const std::string text = jf::read_text(path);
  return parse_job(text, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace furrow
