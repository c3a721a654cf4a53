#include "job/job.hpp"

#include <filesystem>
#include <set>

#include "base/error.hpp"
#include "report/print_style.hpp"
#include "base/text_fields.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "stage/compare_stage.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

// One JSON object of the job: members are read by name and remembered, so
// that finish() can refuse the ones nobody read (typos, unknown options).
class Section {
 public:
  Section(const json& value, std::string where) : where_(std::move(where)), object_(jf::object(value, where_)) {}

  const std::string& where() const { return where_; }
  std::string at(const std::string& key) const { return jf::child(where_, key); }

  const json* find(const std::string& key) {
    read_.insert(key);
    const json* value = jf::optional_member(object_, key, where_);
    return value && !value->is_null() ? value : nullptr;
  }
  const json& required(const std::string& key) {
    read_.insert(key);
    return jf::member(object_, key, where_);
  }
  std::optional<Section> section(const std::string& key) {
    if (const json* v = find(key)) return Section(*v, at(key));
    return std::nullopt;
  }

  std::optional<double> number(const std::string& key) {
    if (const json* v = find(key)) return jf::number(*v, at(key));
    return std::nullopt;
  }
  void positive(const std::string& key, double& target) {
    if (const json* v = find(key)) target = jf::positive_number(*v, at(key));
  }
  void non_negative(const std::string& key, double& target) {
    if (const json* v = find(key)) target = jf::non_negative_number(*v, at(key));
  }
  void optional_positive(const std::string& key, std::optional<double>& target) {
    if (const json* v = find(key)) target = jf::positive_number(*v, at(key));
  }
  void optional_non_negative(const std::string& key, std::optional<double>& target) {
    if (const json* v = find(key)) target = jf::non_negative_number(*v, at(key));
  }
  void integer(const std::string& key, int& target, int min_value) {
    if (const json* v = find(key)) {
      target = jf::integer(*v, at(key));
      if (target < min_value)
        throw InputError(at(key) + ": must be at least " + std::to_string(min_value) + ", got " +
                         std::to_string(target));
    }
  }
  void boolean(const std::string& key, bool& target) {
    if (const json* v = find(key)) target = jf::boolean(*v, at(key));
  }
  std::optional<std::string> string(const std::string& key) {
    if (const json* v = find(key)) return jf::string(*v, at(key));
    return std::nullopt;
  }

  void finish() const {
    for (auto it = object_.begin(); it != object_.end(); ++it)
      if (!read_.count(it.key())) throw InputError(at(it.key()) + ": unknown member (see docs/formats.md \"Job file\")");
  }

 private:
  std::string where_;
  const json& object_;
  std::set<std::string> read_;
};

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

std::string path_member(Section& s, const std::string& key, const std::string& folder) {
  const std::string text = jf::string(s.required(key), s.at(key));
  if (text.empty()) throw InputError(s.at(key) + ": empty path");
  return resolve(folder, text);
}

StepRule parse_step_rule(const std::string& text, const std::string& where) {
  for (StepRule r : {StepRule::exact, StepRule::chord, StepRule::circular_arc})
    if (text == to_string(r)) return r;
  throw InputError(where + ": unknown rule " + quote_field(text) + " (valid: exact, chord, circular_arc)");
}

void read_generation(Section g, Job& job) {
  ToolpathGeneration gen;
  ContactPlanOptions& c = gen.contacts;
  g.positive("tolerance", c.forward.tolerance);
  g.positive("scallop", c.scallop);
  g.non_negative("max_step", c.forward.max_step);
  if (const auto d = g.string("direction")) gen.direction = parse_pass_direction(*d, g.at("direction"));
  if (const auto r = g.string("rule")) c.forward.rule = parse_step_rule(*r, g.at("rule"));
  g.positive("clearance", gen.write.clearance);
  g.positive("feed", gen.write.feed);
  g.finish();
  job.generate = gen;
}

void read_toolpath(Section& root, Job& job, const std::string& folder) {
  const json& value = root.required("toolpath");
  const std::string where = root.at("toolpath");
  if (value.is_string()) {
    job.toolpath_file = path_member(root, "toolpath", folder);
    return;
  }
  Section t(value, where);
  if (auto g = t.section("generate")) {
    read_generation(*g, job);
  } else if (t.find("file")) {
    job.toolpath_file = path_member(t, "file", folder);
    if (const auto units = t.string("units")) job.toolpath_read.units = *units;
  } else {
    throw InputError(where + ": expected a file name, {\"file\": ...} or {\"generate\": {...}}");
  }
  t.finish();
}

void read_tolerance(Section& root, Job& job) {
  const json& value = root.required("tolerance");
  const std::string where = root.at("tolerance");
  double zone = 0;
  std::optional<double> outside;
  if (value.is_number()) {
    zone = jf::positive_number(value, where);
  } else {
    Section t(value, where);
    zone = jf::positive_number(t.required("zone"), t.at("zone"));
    t.optional_non_negative("outside", outside);
    t.finish();
  }
  job.compare.tolerance = ToleranceZone::make(zone, outside.value_or(zone / 2), where);
}

void read_partition(Section p, Job& job) {
  PartitionOptions& o = job.partition;
  if (const json* grid = p.find("grid")) {
    const std::vector<double> counts = jf::numbers(*grid, p.at("grid"));
    if (counts.size() != 2) throw InputError(p.at("grid") + ": expected [cells along u, cells along v]");
    const int nu = jf::integer((*grid)[0], jf::child(p.at("grid"), 0));
    const int nv = jf::integer((*grid)[1], jf::child(p.at("grid"), 1));
    if (nu < 1 || nv < 1) throw InputError(p.at("grid") + ": cell counts must be at least 1");
    o.grid = GridSize{nu, nv};
  }
  p.optional_positive("spacing", o.spacing);
  if (o.grid && o.spacing) throw InputError(p.where() + ": grid and spacing exclude each other");
  p.optional_non_negative("eps", o.eps);
  p.optional_non_negative("min_area", o.min_area);
  p.finish();
}

void read_prediction(Section p, Job& job) {
  PathPredictionOptions& o = job.prediction;
  p.positive("tolerance", o.tolerance);
  p.positive("gouge_threshold", o.gouge_threshold);
  p.positive("resolution", o.resolution);
  p.positive("cell", o.map.cell_size);
  p.positive("map_scale", job.prediction_map_scale);
  if (const json* v = p.find("stock")) {
    // The raw stock box, as `furrow predict --stock` (docs/architecture.md "Rapid moves").
    const std::string w = p.at("stock");
    const json& a = jf::array(*v, w);
    if (a.size() != 6) throw InputError(w + ": expected [xmin, ymin, zmin, xmax, ymax, zmax]");
    double b[6];
    for (std::size_t k = 0; k < 6; ++k) b[k] = jf::number(a[k], jf::child(w, k));
    for (int k = 0; k < 3; ++k)
      if (!(b[k] < b[k + 3]))
        throw InputError(w + ": each min must be below its max (" + std::string(1, char('x' + k)) + ")");
    o.stock = Eigen::AlignedBox3d(Eigen::Vector3d(b[0], b[1], b[2]), Eigen::Vector3d(b[3], b[4], b[5]));
  }
  p.finish();
}

void read_plan(Section p, Job& job) {
  PlannerOptions& o = job.plan;
  p.boolean("prediction", job.plan_with_prediction);
  p.boolean("allow_uncovered", job.plan_allow_uncovered);
  if (const json* v = p.find("points")) {
    const int n = jf::integer(*v, p.at("points"));
    if (n < 1) throw InputError(p.at("points") + ": a plan needs at least 1 point");
    o.points = n;
  }
  p.optional_positive("density", o.density);
  p.integer("min_per_region", o.min_per_region, 0);
  if (const auto s = p.string("strategy")) o.strategy = parse_sampling_strategy(*s, p.at("strategy"));
  int seed = 1;
  p.integer("seed", seed, 0);
  o.seed = static_cast<std::uint64_t>(seed);
  p.optional_non_negative("border", o.border);
  if (const auto name = p.string("probe_name")) o.probe_name = *name;
  p.positive("probe_diameter", o.probe_diameter);
  p.positive("stylus_length", o.stylus_length);
  p.positive("stylus_diameter", o.stylus_diameter);
  p.positive("approach", o.approach);
  p.positive("retract", o.retract);
  p.optional_positive("search", o.search);
  p.non_negative("clearance", o.clearance);
  p.positive("max_tilt", o.max_tilt_degrees);
  p.positive("move_speed", o.motion.move_speed);
  p.positive("touch_speed", o.motion.touch_speed);
  p.positive("acceleration", o.motion.acceleration);
  p.non_negative("dwell", o.motion.dwell);
  p.integer("gouge_points", o.gouge_points, 1);
  if (const auto r = p.string("revision")) o.program.revision = *r;
  if (const auto d = p.string("program_date")) o.program.date = *d;
  if (const auto d = p.string("datums")) o.datums = parse_datum_choice(*d, p.at("datums"));
  std::optional<double> head_length;
  p.optional_positive("head_length", head_length);
  o.program.head_length = head_length;
  p.finish();
  with_context(p.where(), [&] { validate(o); });
  if (needs_risk(o.strategy) && !job.plan_with_prediction)
    throw InputError(p.at("strategy") + ": the risk strategy needs the prediction (\"prediction\": true)");
}

void read_simulation(Section s, Job& job) {
  MeasurementSimulationJob sim;
  SimulationOptions& o = sim.options;
  s.boolean("prediction", sim.from_prediction);
  if (const json* m = s.find("misalign")) {
    const std::vector<double> v = jf::numbers(*m, s.at("misalign"));
    if (v.size() != 6) throw InputError(s.at("misalign") + ": expected [rx, ry, rz, tx, ty, tz] (degrees, mm)");
    o.misalignment.rotation_deg = {v[0], v[1], v[2]};
    o.misalignment.translation = {v[3], v[4], v[5]};
  }
  s.non_negative("noise", o.noise_sigma);
  s.integer("blunders", o.blunders, 0);
  if (const json* b = s.find("blunder_size")) {
    const std::vector<double> v = jf::numbers(*b, s.at("blunder_size"));
    if (v.size() != 2 || !(v[0] > 0) || !(v[1] >= v[0]))
      throw InputError(s.at("blunder_size") + ": expected [smallest, largest] in mm, 0 < smallest <= largest");
    o.blunder_min = v[0];
    o.blunder_max = v[1];
  }
  int seed = 1;
  s.integer("seed", seed, 0);
  o.seed = static_cast<std::uint32_t>(seed);
  if (const auto kind = s.string("points")) o.kind = parse_probe_point_kind(*kind, s.at("points"));
  if (const json* bumps = s.find("bumps")) {
    const json& list = jf::array(*bumps, s.at("bumps"));
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string where = jf::child(s.at("bumps"), k);
      const std::vector<double> v = jf::numbers(list[k], where);
      if (v.size() != 5) throw InputError(where + ": expected [x, y, z, radius, height] in mm");
      if (!(v[3] > 0)) throw InputError(where + ": the radius must be positive");
      o.bumps.push_back({Eigen::Vector3d(v[0], v[1], v[2]), v[3], v[4]});
    }
  }
  s.finish();
  job.simulate = sim;
}

// The CSV dialect and the I++ DME program of a measurement file, as
// `furrow compare` takes them (docs/formats.md "Measurements"), checked
// here, before any stage runs.
void read_measurement_dialect(Section& m, Job& job, const std::string& folder) {
  MeasurementReadOptions& r = job.measurement_read;
  CsvDialect base;
  if (m.find("dialect")) {
    job.measurement_dialect_file = path_member(m, "dialect", folder);
    base = read_csv_dialect(job.measurement_dialect_file);
    if (base.units && m.find("units") && *base.units != r.units)
      throw InputError(m.at("units") + ": \"" + r.units + "\" contradicts the units \"" + *base.units + "\" of " +
                       job.measurement_dialect_file);
    if (base.units) r.units = *base.units;
  }
  std::optional<char> delimiter;
  if (const auto d = m.string("delimiter")) delimiter = parse_csv_delimiter(*d, m.at("delimiter"));
  std::optional<bool> decimal_comma;
  if (m.find("decimal_comma")) {
    bool value = false;
    m.boolean("decimal_comma", value);
    decimal_comma = value;
  }
  std::map<std::string, std::string> columns;
  if (auto c = m.section("columns")) {
    for (const char* field : {"id", "x", "y", "z", "i", "j", "k", "nx", "ny", "nz"})
      if (const auto header = c->string(field)) {
        if (trim(*header).empty()) throw InputError(c->at(field) + ": an empty header name");
        columns[field] = trim(*header);
      }
    c->finish();
  }
  r.dialect = merge_csv_dialect(base, delimiter, decimal_comma, columns, m.where());
  units_to_mm(r.units, m.at("units"));
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

void read_measurements(Section& root, Job& job, const std::string& folder) {
  const json* value = root.find("measurements");
  if (!value) return;
  const std::string where = root.at("measurements");
  if (value->is_string() || value->is_array()) {
    job.measurement_files = measurement_paths(*value, where, folder);
    return;
  }
  Section m(*value, where);
  if (auto sim = m.section("simulate")) {
    read_simulation(*sim, job);
  } else if (const json* files = m.find("file")) {
    job.measurement_files = measurement_paths(*files, m.at("file"), folder);
    if (const auto kind = m.string("points")) job.measurement_read.kind = parse_probe_point_kind(*kind, m.at("points"));
    m.positive("probe_diameter", job.measurement_read.probe_diameter);
    if (const auto units = m.string("units")) job.measurement_read.units = *units;
    read_measurement_dialect(m, job, folder);
  } else {
    throw InputError(where + ": expected a file name, a list of them, {\"file\": ...} or {\"simulate\": {...}}");
  }
  m.finish();
}

void read_comparison(Section c, Job& job) {
  CompareOptions& o = job.compare;
  RegistrationOptions& r = o.registration;
  if (const auto align = c.string("align")) o.align = parse_align_method(*align, c.at("align"));
  if (const auto dof = c.string("dof")) r.dof = DegreesOfFreedom::parse(*dof, c.at("dof"));
  if (const auto loss = c.string("loss")) r.loss = parse_robust_loss(*loss, c.at("loss"));
  c.positive("outlier_sigma", r.outlier_sigma);
  bool rejection = true;
  c.boolean("outlier_rejection", rejection);
  r.flag_outliers = rejection;
  c.boolean("prediction", job.compare_with_prediction);
  PredictionComparisonOptions& p = o.prediction;
  c.positive("probe_sigma", p.probe_sigma);
  c.positive("explained_rms", p.max_normalised_rms);
  c.boolean("prediction_alignment", p.align);
  GougeConfirmationOptions& g = o.gouges;
  c.positive("overcut_sigmas", g.overcut_sigmas);
  c.non_negative("overcut_fraction", g.tolerance_fraction);
  if (g.tolerance_fraction > 1) throw InputError(c.at("overcut_fraction") + ": must lie between 0 and 1");
  c.non_negative("site_margin", g.site_margin);
  c.non_negative("contact_cluster", g.contact_cluster_distance);
  c.non_negative("overcut_cluster", g.overcut_cluster_distance);
  c.finish();
}

}  // namespace

Job parse_job(const std::string& text, const std::string& name, const std::string& folder) {
  const json doc = jf::parse_text(text, name);
  Section root(doc, name + ":");
  Job job;
  job.file = name;
  job.folder = folder;
  if (const json* v = root.find("version")) {
    if (jf::integer(*v, root.at("version")) != kJobFormatVersion)
      throw InputError(root.at("version") + ": this furrow reads job files of version " +
                       std::to_string(kJobFormatVersion));
  }
  job.name = root.string("name").value_or(std::filesystem::path(name).stem().string());
  if (job.name.empty()) throw InputError(root.at("name") + ": empty name");
  job.description = root.string("description").value_or("");
  job.part = path_member(root, "part", folder);
  job.tool = path_member(root, "tool", folder);
  read_toolpath(root, job, folder);
  read_tolerance(root, job);
  if (auto s = root.section("partition")) read_partition(*s, job);
  if (auto s = root.section("prediction")) read_prediction(*s, job);
  if (auto s = root.section("plan")) read_plan(*s, job);
  read_measurements(root, job, folder);
  if (auto s = root.section("comparison")) read_comparison(*s, job);
  if (const json* v = root.find("record")) {
    if (v->is_string()) {
      job.record_file = path_member(root, "record", folder);
      job.record = read_inspection_record(job.record_file);
    } else if (v->is_object()) {
      job.record = parse_inspection_record(v->dump(), root.at("record"));
    } else {
      throw InputError(root.at("record") + ": expected a record file name or the record as an object");
    }
  }
  job.output = path_member(root, "output", folder);
  root.boolean("pdf", job.pdf);
  if (auto paper = root.string("paper")) job.paper = *paper;
  paper_size_css(job.paper, root.at("paper"));  // a4 or letter, checked before any work
  root.finish();
  scale_registration_to_tolerance(job.compare);
  for (const std::string* input : {&job.part, &job.tool, &job.record_file})
    if (*input == job.output) throw InputError(root.at("output") + ": the output folder is an input file");
  return job;
}

Job read_job(const std::string& path) {
  const std::string text = jf::read_text(path);
  return parse_job(text, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace furrow
