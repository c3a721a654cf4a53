#include "inspection/comparison_file.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "inspection/comparison_json.hpp"
#include "inspection/verification_json.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace jf = json_fields;
namespace cj = comparison_json;
using jf::json;

namespace {

// Placement of the part on the CMM in simulate-measurement's convention:
// x_cmm = Rz(rz) Ry(ry) Rx(rx) x_part + t (degrees, mm).
void set_placement(const Eigen::Isometry3d& cmm_to_part, ComparisonDocument::Registration& r) {
  const Eigen::Isometry3d m = cmm_to_part.inverse();
  const Eigen::Matrix3d& rot = m.linear();
  const double deg = 180 / kPi;
  r.placement_rotation_deg = Eigen::Vector3d(std::atan2(rot(2, 1), rot(2, 2)),
                                             std::asin(std::clamp(-rot(2, 0), -1.0, 1.0)),
                                             std::atan2(rot(1, 0), rot(0, 0))) * deg;
  r.placement_translation = m.translation();
}

// The registration as comparison_document.hpp holds it, so that one writer
// (comparison_json.hpp) serves comparison.json and report.json.
ComparisonDocument::Registration document_registration(const RegistrationResult& r,
                                                       const std::vector<std::string>& ids) {
  ComparisonDocument::Registration d;
  d.transform = r.transform.matrix();
  set_placement(r.transform, d);
  d.coarse_method = to_string(r.coarse.method);
  d.coarse_matched_ids = r.coarse.matched;
  d.coarse_candidates = r.coarse.candidates;
  d.coarse_median_distance = r.coarse.median_distance;
  d.coarse_ambiguous = r.coarse.ambiguous;
  d.rms_before = r.rms_before;
  d.rms_after = r.rms_after;
  d.sigma = r.sigma;
  d.outer_iterations = r.outer_iterations;
  d.solver_iterations = r.solver_iterations;
  d.outlier_passes = r.outlier_passes;
  d.converged = r.converged;
  d.status = r.status;
  d.outcome = to_string(r.outcome);
  d.fitted_dof = r.fitted_dof;
  // Weak at the solution first; a held direction that the solution's
  // points fix after all is listed too (it was not fitted).
  auto record = [&](const WeakDirection& w, bool held) {
    ComparisonDocument::Registration::WeakDirection x;
    x.text = w.describe();
    x.translation = w.translation;
    x.direction = w.direction;
    x.axis_point = w.axis_point;
    x.pitch = w.pitch;
    x.ratio = w.ratio;
    const double sd = w.sigma_mm(r.sigma);
    if (std::isfinite(sd)) x.sigma = sd;
    x.held = held;
    x.from_points = w.from_points;
    return x;
  };
  for (const WeakDirection& w : r.observability.weak) d.weak.push_back(record(w, w.held));
  if (r.observability.weak.empty())
    for (const WeakDirection& w : r.held) d.weak.push_back(record(w, true));
  d.covariance = r.covariance;
  d.covariance_status = r.covariance_status;
  for (const std::size_t i : r.ambiguous_outliers)
    d.ambiguous_outliers.push_back(i < ids.size() ? ids[i] : std::to_string(i + 1));
  return d;
}

json registration_json(const RegistrationResult& r, const RegistrationOptions& o, const std::vector<std::string>& ids) {
  json j = cj::registration_json(document_registration(r, ids));
  json dof = json::array();
  for (int k = 0; k < 6; ++k)
    if (o.dof.free[k]) dof.push_back(dof_name(k));
  j["dof"] = std::move(dof);
  j["loss"] = to_string(o.loss);
  j["loss_scale"] = jf::finite(o.loss_scale, "loss scale");
  j["outlier_rule"] = {{"sigmas", jf::finite(o.outlier_sigma, "sigmas")},
                       {"floor", jf::finite(o.outlier_floor, "floor")},
                       {"edge_tolerance", jf::finite(o.edge_tolerance, "edge tolerance")},
                       {"confirm_neighbours", o.confirm_neighbours},
                       {"neighbour_radius", jf::finite(o.neighbour_radius, "radius")}};
  return j;
}

// The alignment method, with datums each datum's fit, and the best-fit
// profile of the same points next to the frame's (docs/formats.md
// "Comparison").
json alignment_json(const Comparison& c) {
  json j = {{"method", to_string(c.align)}};
  if (c.align == AlignMethod::bestfit) return j;
  j["note"] = c.align == AlignMethod::cmm
                  ? "the measurement frame is the part frame (the CMM program aligned the part): no fit, so "
                    "observability is not a question"
                  : c.align == AlignMethod::rps
                        ? "the reference point system fixes the part: no fit, so observability is not a question"
                        : "the datum frame fixes the part: no fit, so observability is not a question";
  json datums = json::array();
  if (c.datum_frame)
    for (const DatumFit& d : c.datum_frame->datums)
      datums.push_back({{"label", d.label},
                        {"kind", to_string(d.kind)},
                        {"points", d.point_ids},
                        {"origin", jf::vector_json(d.origin)},
                        {"direction", jf::vector_json(d.direction)},
                        {"form_error", jf::finite(d.form_error, "datum form error")}});
  // An RPS point: its contact (CMM frame), the axes it fixes and its
  // residual along them (part frame); form_error the largest of those.
  if (c.datum_frame)
    for (const ReferencePointFit& r : c.datum_frame->reference_points)
      datums.push_back({{"label", r.id},
                        {"kind", "rps"},
                        {"points", json::array({r.id})},
                        {"origin", jf::vector_json(r.contact)},
                        {"direction", jf::vector_json(r.normal)},
                        {"directions", r.directions},
                        {"residual", jf::vector_json(r.residual)},
                        {"weight", jf::finite(r.weight, "rps weight")},
                        {"form_error", jf::finite(r.residual.cwiseAbs().maxCoeff(), "rps residual")}});
  j["datums"] = std::move(datums);
  j["bestfit"] = {{"profile", jf::finite(c.bestfit_profile.value_or(0), "best-fit profile")},
                  {"status", c.bestfit ? c.bestfit->status : std::string("not computed")},
                  {"transform", c.bestfit ? cj::matrix_json(c.bestfit->transform.matrix(), "best-fit transform")
                                          : json(nullptr)}};
  return j;
}

// The options as comparison_document.hpp holds them (see above).
ComparisonDocument::Options document_options(const CompareOptions& o, const MeasurementSet& set,
                                             const ComparisonSources& sources) {
  const RegistrationOptions& r = o.registration;
  ComparisonDocument::Options d;
  d.tolerance = o.tolerance;
  d.disposition = o.tolerance.disposition();
  d.dof = r.dof.to_string();
  d.loss = to_string(r.loss);
  d.loss_scale = r.loss_scale;
  d.points = to_string(set.kind);
  d.probe_diameter = 2 * set.probe_radius;
  d.units = sources.measurement_units;
  d.outlier_rejection = r.flag_outliers;
  d.outlier_sigma = r.outlier_sigma;
  d.outlier_floor = r.outlier_floor;
  d.edge_tolerance = r.edge_tolerance;
  d.confirm_neighbours = r.confirm_neighbours;
  d.neighbour_radius = r.neighbour_radius;
  d.max_outer_iterations = r.max_outer_iterations;
  d.max_solver_iterations = r.max_solver_iterations;
  d.max_outlier_passes = r.max_outlier_passes;
  d.motion_tolerance = r.motion_tolerance;
  d.prediction = o.prediction;
  d.gouges = o.gouges;
  return d;
}

// Everything the comparison ran with (docs/formats.md "Comparison").
json options_json(const CompareOptions& o, const MeasurementSet& set, const ComparisonSources& sources) {
  json j = cj::run_options_json(document_options(o, set, sources));
  j["tolerance"] = jf::finite(o.tolerance.width, "tolerance");
  j["outside"] = jf::finite(o.tolerance.outside, "outside");
  return j;
}

json inconclusive_json(const std::vector<InconclusiveReason>& reasons) {
  json out = json::array();
  for (const InconclusiveReason& r : reasons)
    out.push_back({{"kind", r.kind}, {"subject", r.subject}, {"text", r.text}});
  return out;
}

json outlier_counts_json(const RegistrationResult& r) {
  json counts = json::object();
  for (OutlierReason reason : {OutlierReason::blunder, OutlierReason::large_deviation,
                               OutlierReason::beyond_edge, OutlierReason::no_foot_point})
    counts[to_string(reason)] = 0;
  for (const RegisteredPoint& p : r.points)
    if (p.outlier != OutlierReason::none)
      counts[to_string(p.outlier)] = counts[to_string(p.outlier)].get<std::size_t>() + 1;
  return counts;
}

json point_json(const Comparison& c, const MeasurementSet& set, const Part& part, const MergedMeasurements* merged,
                std::size_t i) {
  const RegisteredPoint& p = c.registration.points[i];
  const bool have_covariance = c.registration.covariance.has_value();
  json j;
  j["id"] = set.points[i].id;
  if (merged && merged->files.size() > 1) j["file"] = merged->origin.at(i);
  j["measured"] = jf::vector_json(set.points[i].xyz);
  j["registered"] = jf::vector_json(p.registered);
  j["contact"] = jf::vector_json(Eigen::Vector3d(p.registered - set.probe_radius * p.foot.normal));
  j["face"] = part.faces[p.foot.face].name();
  j["face_index"] = p.foot.face;
  j["u"] = jf::finite(p.foot.uv.x(), "u");
  j["v"] = jf::finite(p.foot.uv.y(), "v");
  j["foot"] = jf::vector_json(p.foot.point);
  j["normal"] = jf::vector_json(p.foot.normal);
  j["foot_location"] = to_string(p.foot.location);
  j["deviation"] = jf::finite(p.deviation, "deviation");
  j["uncertainty"] = have_covariance ? jf::finite(p.uncertainty, "uncertainty") : json(nullptr);
  j["redundancy"] = have_covariance ? jf::finite(p.redundancy, "redundancy") : json(nullptr);
  j["evaluated"] = p.evaluated;
  j["in_tolerance"] = p.evaluated ? json(bool(c.in_tolerance[i])) : json(nullptr);
  j["in_fit"] = p.in_fit;
  j["outlier"] = p.outlier == OutlierReason::none
                     ? json(nullptr)
                     : json({{"reason", to_string(p.outlier)}, {"detail", p.outlier_detail}});
  if (i < c.region.size() && c.region[i]) j["region"] = *c.region[i];
  j["prediction"] = c.prediction ? verification_json::point_prediction_json(c.prediction->points[i])
                                 : json(nullptr);
  return j;
}

}  // namespace

std::string comparison_to_json_text(const Comparison& c, const MeasurementSet& set,
                                    const Part& part, const CompareOptions& options,
                                    const ComparisonSources& sources) {
  if (c.prediction.has_value() == sources.prediction.empty())
    throw std::logic_error("comparison_to_json_text: the prediction file and its results go together");
  const ComparisonSummary& s = c.summary;
  json doc;
  doc["version"] = kComparisonFormatVersion;
  doc["units"] = "mm";
  doc["part"] = sources.part;
  doc["measurements"] = sources.measurements;
  json files = json::array(), replaced = json::array();
  if (sources.merged) {
    if (sources.merged->set.points.size() != set.points.size())
      throw std::logic_error("comparison_to_json_text: the merged measurements are not the compared set");
    for (std::size_t f = 0; f < sources.merged->files.size(); ++f)
    {
      json file = {{"path", sources.merged->files[f]}, {"points", sources.merged->file_points[f]}};
      // With several files only: one file's comparison stays the bytes
      // `furrow run` writes (its report.json records the digests).
      if (sources.merged->files.size() > 1 && f < sources.merged->sha256.size())
        file["sha256"] = sources.merged->sha256[f];
      files.push_back(std::move(file));
    }
    for (const MeasurementReplacement& r : sources.merged->replaced)
      replaced.push_back({{"id", r.id}, {"file", r.file}, {"by_file", r.by_file}, {"was", jf::vector_json(r.was)}});
  } else {
    files.push_back({{"path", sources.measurements}, {"points", set.points.size()}});
  }
  doc["measurement_files"] = std::move(files);
  doc["replaced"] = std::move(replaced);
  auto optional_path = [](const std::string& p) { return p.empty() ? json(nullptr) : json(p); };
  doc["plan"] = optional_path(sources.plan);
  doc["regions_file"] = optional_path(sources.regions);
  doc["prediction_file"] = optional_path(sources.prediction);
  doc["options"] = options_json(options, set, sources);
  doc["probe"] = {{"points", to_string(set.kind)},
                  {"diameter", jf::finite(2 * set.probe_radius, "probe diameter")}};
  doc["tolerance"] = {{"zone", jf::finite(c.tolerance.width, "tolerance")},
                      {"lower", jf::finite(c.tolerance.lower(), "lower limit")},
                      {"upper", jf::finite(c.tolerance.upper(), "upper limit")},
                      {"disposition", c.tolerance.disposition()}};
  doc["registration"] = registration_json(c.registration, options.registration, c.point_ids);
  doc["alignment"] = alignment_json(c);
  doc["summary"] = {{"points", s.points},
                    {"in_fit", s.in_fit},
                    {"evaluated", s.evaluated},
                    {"outliers", s.outliers},
                    {"not_measured", s.not_measured},
                    {"outlier_reasons", outlier_counts_json(c.registration)},
                    {"in_tolerance", s.in_tolerance},
                    {"out_of_tolerance", s.out_of_tolerance},
                    {"deviation", cj::statistics_json(s.deviations)},
                    {"profile", jf::finite(s.profile, "profile")},
                    {"confirmed_gouges", s.confirmed_gouges},
                    {"unexplained_overcuts", s.unexplained_overcuts},
                    {"verdict", to_string(s.verdict)},
                    {"alignment", s.alignment},
                    {"inconclusive", inconclusive_json(s.inconclusive)},
                    {"pass", s.pass}};
  json regions = json::array();
  for (const RegionStatistics& r : s.regions) {
    json jr = cj::statistics_json(r.deviations);
    jr["region"] = r.region;
    jr["out_of_tolerance"] = r.out_of_tolerance;
    regions.push_back(std::move(jr));
  }
  doc["regions"] = std::move(regions);
  json unmeasured = json::array();
  for (const UnmeasuredPoint& u : c.not_measured)
    unmeasured.push_back({{"id", u.id},
                          {"nominal", u.nominal ? jf::vector_json(*u.nominal) : json(nullptr)},
                          {"reason", u.reason},
                          {"line", u.line}});
  doc["not_measured"] = std::move(unmeasured);
  std::vector<std::string> ids;
  for (const MeasuredPoint& p : set.points) ids.push_back(p.id);
  doc["prediction_comparison"] =
      c.prediction ? verification_json::prediction_comparison_json(*c.prediction) : json(nullptr);
  doc["gouge_sites"] = c.gouges ? verification_json::gouge_sites_json(*c.gouges, ids) : json(nullptr);
  doc["unexplained"] = c.gouges ? verification_json::unexplained_json(*c.gouges, ids) : json(nullptr);
  std::string text = jf::to_text(doc);

  // Splice the points in before the closing brace, one compact line each,
  // appended to the one string returned: a million points' text (hundreds
  // of MB) is not built apart and then copied into the document.
  const std::size_t close = text.rfind('}');
  std::size_t end_of_last = close;
  while (end_of_last > 0 && (text[end_of_last - 1] == '\n' || text[end_of_last - 1] == ' '))
    --end_of_last;
  text.resize(end_of_last);
  text += ",\n  \"points\": [";
  for (std::size_t i = 0; i < c.registration.points.size(); ++i) {
    text += i == 0 ? "\n    " : ",\n    ";
    text += point_json(c, set, part, sources.merged, i).dump();
  }
  text += c.registration.points.empty() ? "]\n" : "\n  ]\n";
  text += "}\n";
  return text;
}

}  // namespace furrow
