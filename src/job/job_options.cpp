#include "job/job_options.hpp"

#include "base/json_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

json optional_number(const std::optional<double>& v, const char* what) {
  return v ? jf::finite(*v, what) : json(nullptr);
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
    const ToolpathGeneration& g = *job.generate;
    j["toolpath"] = {{"generate",
                      {{"tolerance", jf::finite(g.contacts.forward.tolerance, "tolerance")},
                       {"scallop", jf::finite(g.contacts.scallop, "scallop")},
                       {"max_step", jf::finite(g.contacts.forward.max_step, "max step")},
                       {"direction", to_string(g.direction)},
                       {"rule", to_string(g.contacts.forward.rule)},
                       {"clearance", jf::finite(g.write.clearance, "clearance")},
                       {"feed", jf::finite(g.write.feed, "feed")}}}};
  } else {
    j["toolpath"] = {{"file", *job.toolpath_file}, {"units", job.toolpath_read.units}};
    if (!job.tool_table.empty()) j["toolpath"]["tools"] = job.tool_table;
  }
  const ToleranceZone& z = job.compare.tolerance;
  j["tolerance"] = {{"zone", jf::finite(z.width, "zone")}, {"outside", jf::finite(z.outside, "outside")}};
  const PartitionOptions& p = job.partition;
  j["partition"] = {{"grid", p.grid ? json::array({p.grid->nu, p.grid->nv}) : json(nullptr)},
                    {"spacing", optional_number(p.spacing, "spacing")},
                    {"eps", optional_number(p.eps, "eps")},
                    {"min_area", optional_number(p.min_area, "min area")}};
  const PathPredictionOptions& pr = job.prediction;
  j["prediction"] = {{"tolerance", jf::finite(pr.tolerance, "tolerance")},
                     {"gouge_threshold", jf::finite(pr.gouge_threshold > 0 ? pr.gouge_threshold : 2 * pr.tolerance,
                                                    "gouge threshold")},
                     {"resolution", pr.resolution > 0 ? jf::finite(pr.resolution, "resolution") : json(nullptr)},
                     {"cell", jf::finite(pr.map.cell_size, "cell")}};
  // Only when given, so that a job without it echoes what it always did.
  if (pr.stock)
    j["prediction"]["stock"] = {jf::finite(pr.stock->min().x(), "stock"), jf::finite(pr.stock->min().y(), "stock"),
                                jf::finite(pr.stock->min().z(), "stock"), jf::finite(pr.stock->max().x(), "stock"),
                                jf::finite(pr.stock->max().y(), "stock"), jf::finite(pr.stock->max().z(), "stock")};
  const PlannerOptions& o = job.plan;
  j["plan"] = {{"prediction", job.plan_with_prediction},
               {"allow_uncovered", job.plan_allow_uncovered},
               {"points", o.points ? json(*o.points) : json(nullptr)},
               {"density", jf::finite(o.density.value_or(o.points ? 0.0 : kDefaultDensity), "density")},
               {"min_per_region", o.min_per_region},
               {"strategy", to_string(o.strategy)},
               {"seed", o.seed},
               {"border", jf::finite(border_clearance(o), "border")},
               {"probe_name", o.probe_name},
               {"probe_diameter", jf::finite(o.probe_diameter, "probe diameter")},
               {"stylus_length", jf::finite(o.stylus_length, "stylus length")},
               {"stylus_diameter", jf::finite(o.stylus_diameter, "stylus diameter")},
               {"approach", jf::finite(o.approach, "approach")},
               {"retract", jf::finite(o.retract, "retract")},
               {"search", jf::finite(search_distance(o), "search")},
               {"clearance", jf::finite(o.clearance, "clearance")},
               {"max_tilt", jf::finite(o.max_tilt_degrees, "max tilt")},
               {"move_speed", jf::finite(o.motion.move_speed, "move speed")},
               {"touch_speed", jf::finite(o.motion.touch_speed, "touch speed")},
               {"acceleration", jf::finite(o.motion.acceleration, "acceleration")},
               {"dwell", jf::finite(o.motion.dwell, "dwell")},
               {"gouge_points", o.gouge_points},
               {"revision", o.program.revision},
               {"datums", to_string(o.datums)},
               {"program_date", o.program.date.empty() ? json(nullptr) : json(o.program.date)},
               {"head_length", jf::finite(o.program.head_length.value_or(o.stylus_length), "head length")}};
  if (job.simulate) {
    const SimulationOptions& s = job.simulate->options;
    json bumps = json::array();
    for (const SurfaceBump& b : s.bumps)
      bumps.push_back({jf::finite(b.centre.x(), "bump"), jf::finite(b.centre.y(), "bump"),
                       jf::finite(b.centre.z(), "bump"), jf::finite(b.radius, "bump"), jf::finite(b.height, "bump")});
    const Misalignment& m = s.misalignment;
    j["measurements"] = {{"simulate",
                          {{"prediction", job.simulate->from_prediction},
                           {"misalign", {jf::finite(m.rotation_deg.x(), "misalign"), jf::finite(m.rotation_deg.y(), "misalign"),
                                         jf::finite(m.rotation_deg.z(), "misalign"), jf::finite(m.translation.x(), "misalign"),
                                         jf::finite(m.translation.y(), "misalign"), jf::finite(m.translation.z(), "misalign")}},
                           {"noise", jf::finite(s.noise_sigma, "noise")},
                           {"blunders", s.blunders},
                           {"blunder_size", {jf::finite(s.blunder_min, "blunder"), jf::finite(s.blunder_max, "blunder")}},
                           {"seed", s.seed},
                           {"points", to_string(s.kind)},
                           {"bumps", std::move(bumps)}}}};
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
  const RegistrationOptions& r = job.compare.registration;
  const PredictionComparisonOptions& pc = job.compare.prediction;
  const GougeConfirmationOptions& g = job.compare.gouges;
  j["comparison"] = {{"align", to_string(job.compare.align)},
                     {"dof", r.dof.to_string()},
                     {"loss", to_string(r.loss)},
                     {"outlier_sigma", jf::finite(r.outlier_sigma, "outlier sigma")},
                     {"outlier_rejection", r.flag_outliers},
                     {"prediction", job.compare_with_prediction},
                     {"probe_sigma", jf::finite(pc.probe_sigma, "probe sigma")},
                     {"explained_rms", jf::finite(pc.max_normalised_rms, "explained rms")},
                     {"prediction_alignment", pc.align},
                     {"overcut_sigmas", jf::finite(g.overcut_sigmas, "overcut sigmas")},
                     {"overcut_fraction", jf::finite(g.tolerance_fraction, "overcut fraction")},
                     {"site_margin", jf::finite(g.site_margin, "site margin")},
                     {"contact_cluster", jf::finite(g.contact_cluster_distance, "contact cluster")},
                     {"overcut_cluster", jf::finite(g.overcut_cluster_distance, "overcut cluster")}};
  j["output"] = job.output;
  return jf::to_text(j);
}

}  // namespace furrow
