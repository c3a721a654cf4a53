#include "report/report_json.hpp"

#include <algorithm>

#include "inspection/comparison_json.hpp"
#include "inspection/verification_json.hpp"
#include "inspection/scan_verification_json.hpp"
#include "base/json_fields.hpp"
#include "base/json_text.hpp"
#include "io/part_file.hpp"
#include "report/compensation_section.hpp"
#include "report/face_summary.hpp"
#include "report/merged_surfaces.hpp"
#include "report/scan_report.hpp"

namespace furrow {

namespace jf = json_fields;
namespace vj = verification_json;
namespace cj = comparison_json;
using jf::json;

namespace {

json num(double v, const char* what) { return jf::finite(v, what); }
json opt(const std::optional<double>& v, const char* what) { return v ? num(*v, what) : json(nullptr); }

json zone_json(const ToleranceZone& z) {
  return {{"zone", num(z.width, "zone")},
          {"lower", num(z.lower(), "lower")},
          {"upper", num(z.upper(), "upper")},
          {"disposition", z.disposition()}};
}

json verdict_json(const ReportVerdict& v) {
  json j;
  j["result"] = v.result();
  j["pass"] = v.pass;
  j["reasons"] = v.reasons;
  json open = json::array();
  for (const InconclusiveReason& r : v.inconclusive)
    open.push_back({{"kind", r.kind}, {"subject", r.subject}, {"text", r.text}});
  j["inconclusive"] = std::move(open);
  j["profile"] = num(v.profile, "profile");
  j["tolerance"] = zone_json(v.zone);
  j["evaluated"] = v.evaluated;
  j["out_of_tolerance"] = v.out_of_tolerance;
  j["registration_converged"] = v.registration_converged;
  j["alignment"] = v.alignment;
  j["gouge_sites"] = v.has_prediction ? json({{"predicted", v.sites},
                                               {"confirmed", v.confirmed},
                                               {"not_confirmed", v.not_confirmed},
                                               {"not_measured", v.not_measured}})
                                       : json(nullptr);
  j["unexplained_overcuts"] = v.has_prediction ? json(v.unexplained) : json(nullptr);
  j["prediction_verdict"] = v.prediction_verdict ? json(*v.prediction_verdict) : json(nullptr);
  return j;
}

json options_json(const ComparisonDocument::Options& o) {
  json j = cj::run_options_json(o);
  j["tolerance"] = zone_json(o.tolerance);
  return j;
}

// The record as its file spells it, filled members only (docs/formats.md
// "Inspection record"); null without one.
json record_json(const std::optional<InspectionRecord>& record) {
  if (!record) return nullptr;
  json j = json::object();
  for (const InspectionRecord::Field& f : record->fields())
    if (std::string(f.key) != "temperature") j[f.key] = f.value;
  if (record->temperature)
    j["temperature"] = {{"value", num(record->temperature->value, "temperature")}, {"unit", record->temperature->unit}};
  json sign = json::object();
  for (const auto& [role, s] : {std::pair<const char*, const SignOff*>{"prepared", &record->prepared},
                                {"checked", &record->checked},
                                {"approved", &record->approved}}) {
    json one = json::object();
    if (!s->name.empty()) one["name"] = s->name;
    if (!s->date.empty()) one["date"] = s->date;
    if (!one.empty()) sign[role] = std::move(one);
  }
  if (!sign.empty()) j["sign_off"] = std::move(sign);
  return j;
}

json faces_json(const ComparisonDocument& doc, const std::vector<std::optional<AnalyticSurface>>& surfaces) {
  json out = json::array();
  for (const FaceDeviationSummary& f : face_summaries(doc)) {
    const std::optional<AnalyticSurface>* surface =
        f.face_index >= 0 && static_cast<std::size_t>(f.face_index) < surfaces.size()
            ? &surfaces[static_cast<std::size_t>(f.face_index)]
            : nullptr;
    out.push_back({{"face", f.face},
                   {"face_index", f.face_index},
                   {"points", f.points},
                   {"evaluated", f.evaluated},
                   {"out_of_tolerance", f.out_of_tolerance},
                   {"min", opt(f.min_deviation, "min")},
                   {"max", opt(f.max_deviation, "max")},
                   {"mean", opt(f.mean_deviation, "mean")},
                   {"beyond_zone", num(f.worst_excess, "beyond_zone")},
                   {"worst_point", f.worst_point.empty() ? json(nullptr) : json(f.worst_point)},
                   {"surface", surface && *surface ? analytic_json(**surface) : json(nullptr)}});
  }
  return out;
}

json alignment_json(const ComparisonDocument& doc) {
  const ComparisonDocument::Registration& r = doc.registration;
  json j = cj::registration_json(r);
  json outliers = json::object();
  for (const auto& [reason, count] : r.outliers) outliers[reason] = count;
  j["outliers"] = std::move(outliers);
  // The alignment's share of each deviation's uncertainty, summarised.
  std::vector<double> u;
  for (const auto& p : doc.points)
    if (p.uncertainty) u.push_back(*p.uncertainty);
  if (u.empty()) {
    j["point_uncertainty"] = nullptr;
  } else {
    std::sort(u.begin(), u.end());
    const double median = u.size() % 2 ? u[u.size() / 2] : 0.5 * (u[u.size() / 2 - 1] + u[u.size() / 2]);
    j["point_uncertainty"] = {{"min", num(u.front(), "u")}, {"median", num(median, "u")}, {"max", num(u.back(), "u")}};
  }
  // How the points reached the part frame; with the CMM's or a datum frame
  // the best-fit profile of the same points beside it (form alone), as the
  // HTML report shows them (docs/registration.md "Alignments").
  const ComparisonDocument::Alignment& a = doc.alignment;
  j["method"] = a.method;
  if (a.method != "bestfit") {
    j["note"] = a.note;
    json datums = json::array();
    for (const auto& d : a.datums) {
      json entry = {{"label", d.label},
                    {"kind", d.kind},
                    {"points", d.points},
                    {"origin", jf::vector_json(d.origin)},
                    {"direction", jf::vector_json(d.direction)},
                    {"form_error", num(d.form_error, "datum form error")}};
      if (d.kind == "rps") {
        entry["directions"] = d.directions;
        entry["residual"] = jf::vector_json(d.residual);
        entry["weight"] = num(d.weight, "rps weight");
      }
      datums.push_back(std::move(entry));
    }
    j["datums"] = std::move(datums);
    j["bestfit_profile"] = a.bestfit_profile ? num(*a.bestfit_profile, "best-fit profile") : json(nullptr);
    j["bestfit_status"] = a.bestfit_status;
  }
  return j;
}

json regions_json(const ComparisonDocument& doc, const RegionMap* regions) {
  json out = json::array();
  for (const RegionStatistics& r : doc.summary.regions) {
    json j = cj::statistics_json(r.deviations);
    j["region"] = r.region;
    j["out_of_tolerance"] = r.out_of_tolerance;
    const Region* known = regions && r.region >= 0 && static_cast<std::size_t>(r.region) < regions->regions.size()
                              ? &regions->regions[static_cast<std::size_t>(r.region)]
                              : nullptr;
    j["face"] = known ? json(regions->faces[static_cast<std::size_t>(known->face)].name) : json(nullptr);
    j["class"] = known ? json(to_string(known->curvature_class)) : json(nullptr);
    j["area"] = known ? num(known->area, "area") : json(nullptr);
    j["group"] = known && known->group >= 0 ? json(known->group) : json(nullptr);
    out.push_back(std::move(j));
  }
  return out;
}

json surfaces_json(const ComparisonDocument& doc, const RegionMap* regions) {
  json out = json::array();
  for (const MergedSurface& m : merged_surfaces(doc, regions)) {
    json j = cj::statistics_json(m.deviations);
    j["group"] = m.group->id;
    j["class"] = to_string(m.group->curvature_class);
    j["area"] = num(m.group->area, "area");
    j["regions"] = m.group->regions;
    json faces = json::array();
    for (int f : m.group->faces) faces.push_back(regions->faces[static_cast<std::size_t>(f)].name);
    j["faces"] = std::move(faces);
    j["out_of_tolerance"] = m.out_of_tolerance;
    out.push_back(std::move(j));
  }
  return out;
}

// The points, streamed: one object each, members in key order as the tree
// of the other members has them (json_text.hpp). Only the prediction, a
// few members, goes through a tree, so that its fields are spelled in one
// place (verification_json).
void write_points(json_text::Writer& w, const ComparisonDocument& doc) {
  w.begin_array();
  for (const auto& p : doc.points) {
    w.begin_object();
    w.key("deviation");
    w.number(p.deviation, "deviation");
    w.key("evaluated");
    w.boolean(p.evaluated);
    w.key("face");
    w.string(p.face);
    w.key("foot");
    w.vector(p.foot);
    w.key("id");
    w.string(p.id);
    w.key("in_fit");
    w.boolean(p.in_fit);
    w.key("in_tolerance");
    if (p.in_tolerance)
      w.boolean(*p.in_tolerance);
    else
      w.null();
    w.key("measured");
    w.vector(p.measured);
    w.key("normal");
    w.vector(p.normal);
    w.key("outlier");
    if (p.outlier.empty())
      w.null();
    else
      w.string(p.outlier);
    w.key("prediction");
    if (p.prediction)
      w.value(vj::point_prediction_json(*p.prediction));
    else
      w.null();
    w.key("region");
    if (p.region)
      w.integer(*p.region);
    else
      w.null();
    w.key("uncertainty");
    if (p.uncertainty)
      w.number(*p.uncertainty, "uncertainty");
    else
      w.null();
    w.key("uv");
    w.vector(p.uv);
    w.end_object();
  }
  w.end_array();
}

// Where the part sits in its batch; null without a results database.
json process_json(const std::optional<ProcessContext>& process) {
  if (!process) return nullptr;
  json regions = json::array();
  for (const RegionProcess& r : process->regions) {
    json recent = json::array();
    for (std::size_t k = 0; k < r.recent.size(); ++k)
      recent.push_back({{"serial", r.serials[k]}, {"value", num(r.recent[k], "process value")}});
    regions.push_back({{"region", std::stoi(r.region)},
                       {"lower", num(r.lower, "process zone")},
                       {"upper", num(r.upper, "process zone")},
                       {"n", r.n},
                       {"mean", r.mean ? num(*r.mean, "process mean") : json(nullptr)},
                       {"cpk", r.cpk ? num(*r.cpk, "process cpk") : json(nullptr)},
                       {"recent", std::move(recent)},
                       {"this_part", r.has_part},
                       {"rules_at_part", r.rules_at_part}});
  }
  return {{"source", process->source},   {"serial", process->serial},   {"stored", process->stored},
          {"parts", process->parts},     {"position", process->position}, {"recent_parts", kProcessRecentParts},
          {"regions", std::move(regions)}};
}

}  // namespace

std::string report_json_text(const ComparisonDocument& doc, const ReportVerdict& verdict, const RegionMap* regions,
                             const ReportContext& context, const std::vector<ReportFigure>& figures) {
  json d;
  d["format"] = "furrow-report";
  d["version"] = kReportFormatVersion;
  d["furrow_version"] = FURROW_VERSION;
  d["title"] = context.title;
  d["generated"] = context.generated;
  d["record"] = record_json(context.record);
  d["process"] = process_json(context.process);
  d["units"] = "mm";
  d["verdict"] = verdict_json(verdict);
  json inputs = json::array();
  for (const InputDigest& in : context.inputs)
    inputs.push_back({{"role", in.role},
                      {"path", in.path},
                      {"sha256", in.sha256},
                      {"bytes", in.bytes},
                      {"generated", in.generated}});
  d["inputs"] = std::move(inputs);
  d["options"] = {{"comparison", options_json(doc.options)},
                  {"job", context.job_options_json.empty()
                              ? json(nullptr)
                              : jf::parse_text(context.job_options_json, "job options")}};
  d["alignment"] = alignment_json(doc);
  const ComparisonSummary& s = doc.summary;
  json dev = cj::statistics_json(s.deviations);
  dev["points"] = s.points;
  dev["in_fit"] = s.in_fit;
  dev["evaluated"] = s.evaluated;
  dev["outliers"] = s.outliers;
  dev["in_tolerance"] = s.in_tolerance;
  dev["out_of_tolerance"] = s.out_of_tolerance;
  dev["profile"] = num(s.profile, "profile");
  d["deviations"] = std::move(dev);
  d["regions"] = regions_json(doc, regions);
  d["surfaces"] = surfaces_json(doc, regions);
  // The verification parts as comparison.json writes them.
  d["prediction"] = doc.prediction ? vj::prediction_comparison_json(*doc.prediction) : json(nullptr);
  if (doc.gouges && context.scan && context.scan->verification) {
    // A scan's sites and clusters as its comparison.json writes them
    // (counts and cloud indices, scan_verification_json.hpp).
    const ScanVerification& v = *context.scan->verification;
    d["gouges"] = {{"sites", scan_verification_json::sites_json(v.sites)},
                   {"unexplained", scan_verification_json::clusters_json(v.unexplained)}};
  } else if (doc.gouges) {
    std::vector<std::string> ids;
    for (const auto& p : doc.points) ids.push_back(p.id);
    d["gouges"] = {{"sites", vj::gouge_sites_json(*doc.gouges, ids)},
                   {"unexplained", vj::unexplained_json(*doc.gouges, ids)}};
  } else {
    d["gouges"] = nullptr;
  }
  d["compensation"] = compensation_section_json(context.compensation, context.compensation_file);
  d["scan"] = scan_section_json(context.scan.get());
  d["faces"] = faces_json(doc, context.face_surfaces);
  d["points"] = nullptr;  // streamed below, in its place among the members
  json figs = json::array();
  for (const ReportFigure& f : figures) figs.push_back({{"file", f.file}, {"section", f.section}, {"title", f.title}});
  d["figures"] = std::move(figs);
  d["files"] = {{"html", "report.html"}, {"points", "points.csv"}, {"json", "report.json"}};
  if (context.stages.empty()) {
    d["timing"] = nullptr;
  } else {
    json stages = json::array();
    for (const StageTime& t : context.stages) stages.push_back({{"stage", t.stage}, {"seconds", num(t.seconds, "seconds")}});
    d["timing"] = {{"stages", std::move(stages)}, {"total_seconds", num(context.total_seconds, "total")}};
  }
  // About 860 bytes a point, written in one piece.
  std::string out;
  out.reserve(20000 + 900 * doc.points.size());
  json_text::Writer w(out);
  w.begin_object();
  for (auto it = d.begin(); it != d.end(); ++it) {
    w.key(it.key());
    if (it.key() == "points")
      write_points(w, doc);
    else
      w.value(*it);
  }
  w.end_object();
  w.finish();
  return out;
}

}  // namespace furrow
