// read_comparison: comparison.json back into plain structs
// (comparison_file.hpp). Every member is checked; the first problem is
// reported with its path.
#include <algorithm>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/comparison_json.hpp"
#include "inspection/verification_json.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;
using comparison_json::read_statistics;

namespace {


template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> matrix(const json& value, const std::string& where) {
  jf::array(value, where);
  if (value.size() != Rows)
    throw InputError(where + ": expected " + std::to_string(Rows) + " rows, got " + std::to_string(value.size()));
  Eigen::Matrix<double, Rows, Cols> m;
  for (int i = 0; i < Rows; ++i) {
    const std::vector<double> row = jf::numbers(value[i], jf::child(where, static_cast<std::size_t>(i)));
    if (row.size() != Cols)
      throw InputError(jf::child(where, static_cast<std::size_t>(i)) + ": expected " + std::to_string(Cols) +
                       " numbers, got " + std::to_string(row.size()));
    for (int j = 0; j < Cols; ++j) m(i, j) = row[static_cast<std::size_t>(j)];
  }
  return m;
}

ComparisonDocument::Options read_options(const JsonCursor& n) {
  ComparisonDocument::Options o;
  o.tolerance = ToleranceZone::make(n.number("tolerance"), n.number("outside"), n.path("tolerance"));
  o.disposition = o.tolerance.disposition();
  o.dof = n.string("dof");
  o.loss = n.string("loss");
  o.loss_scale = n.non_negative("loss_scale");
  o.points = n.string("points");
  o.probe_diameter = n.non_negative("probe_diameter");
  o.units = n.string("units");
  o.outlier_rejection = n.boolean("outlier_rejection");
  o.outlier_sigma = n.non_negative("outlier_sigma");
  o.outlier_floor = n.non_negative("outlier_floor");
  o.edge_tolerance = n.non_negative("edge_tolerance");
  o.confirm_neighbours = n.integer("confirm_neighbours");
  o.neighbour_radius = n.non_negative("neighbour_radius");
  o.max_outer_iterations = n.integer("max_outer_iterations");
  o.max_solver_iterations = n.integer("max_solver_iterations");
  o.max_outlier_passes = n.integer("max_outlier_passes");
  o.motion_tolerance = n.non_negative("motion_tolerance");
  o.prediction = verification_json::read_prediction_options(n.at("prediction"));
  o.gouges = verification_json::read_gouge_options(n.at("gouges"));
  return o;
}

ComparisonDocument::Registration read_registration(const JsonCursor& n) {
  ComparisonDocument::Registration r;
  r.transform = matrix<4, 4>(n.raw("transform"), n.path("transform"));
  const JsonCursor placement = n.at("placement");
  r.placement_rotation_deg = placement.vector3("rotation_deg");
  r.placement_translation = placement.vector3("translation");
  const JsonCursor coarse = n.at("coarse");
  r.coarse_method = coarse.string("method");
  r.coarse_matched_ids = coarse.integer("matched_ids");
  r.coarse_candidates = coarse.integer("candidates");
  r.coarse_median_distance = coarse.number("median_distance");
  r.coarse_ambiguous = coarse.boolean("ambiguous");
  r.rms_before = n.non_negative("rms_before");
  r.rms_after = n.non_negative("rms_after");
  r.sigma = n.non_negative("sigma");
  r.outer_iterations = n.integer("outer_iterations");
  r.solver_iterations = n.integer("solver_iterations");
  r.outlier_passes = n.integer("outlier_passes");
  r.converged = n.boolean("converged");
  r.status = n.string("status");
  r.covariance_status = n.string("covariance_status");
  // Written since the weak-direction analysis; older files have neither.
  if (n.has("outcome")) {
    r.outcome = n.string("outcome");
    if (r.outcome != "converged" && r.outcome != "not_converged" && r.outcome != "too_few_points")
      throw InputError(n.path("outcome") + ": unknown outcome " + quote_field(r.outcome) +
                       " (valid: converged, not_converged, too_few_points)");
    r.fitted_dof = n.integer("fitted_dof");
    if (r.fitted_dof < 0 || r.fitted_dof > 6) throw InputError(n.path("fitted_dof") + ": must lie in 0..6");
    const json& list = n.array("weak_directions");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JsonCursor w(list[k], jf::child(n.path("weak_directions"), k));
      ComparisonDocument::Registration::WeakDirection d;
      d.text = w.string("text");
      const std::string kind = w.string("kind");
      if (kind != "translation" && kind != "rotation")
        throw InputError(w.path("kind") + ": expected \"translation\" or \"rotation\"");
      d.translation = kind == "translation";
      d.direction = w.vector3("direction");
      d.ratio = w.non_negative("ratio");
      d.sigma = w.nullable_number("sigma");
      d.held = w.boolean("held");
      d.from_points = w.boolean("from_points");
      if (!d.translation) {
        d.axis_point = w.vector3("axis_point");
        d.pitch = w.number("pitch");
      }
      r.weak.push_back(d);
    }
  }
  if (!n.is_null("covariance")) r.covariance = matrix<6, 6>(n.raw("covariance"), n.path("covariance"));
  if (n.has("ambiguous_outliers")) {
    const json& list = n.array("ambiguous_outliers");
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (!list[k].is_string())
        throw InputError(jf::child(n.path("ambiguous_outliers"), k) + ": expected a point id (a string)");
      r.ambiguous_outliers.push_back(list[k].get<std::string>());
    }
  }
  return r;
}

ComparisonDocument::Alignment read_alignment(const JsonCursor& n) {
  ComparisonDocument::Alignment a;
  a.method = n.string("method");
  if (a.method != "bestfit" && a.method != "cmm" && a.method != "datums" && a.method != "rps")
    throw InputError(n.path("method") + ": unknown alignment " + quote_field(a.method) +
                     " (valid: bestfit, cmm, datums, rps)");
  if (a.method == "bestfit") return a;
  a.note = n.string("note");
  const json& list = n.array("datums");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const JsonCursor d(list[k], jf::child(n.path("datums"), k));
    ComparisonDocument::Alignment::Datum x;
    x.label = d.string("label");
    x.kind = d.string("kind");
    const json& ids = d.array("points");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (!ids[i].is_string()) throw InputError(jf::child(d.path("points"), i) + ": expected a point id");
      x.points.push_back(ids[i].get<std::string>());
    }
    x.origin = d.vector3("origin");
    x.direction = d.vector3("direction");
    x.form_error = d.non_negative("form_error");
    if (x.kind == "rps") {
      x.directions = d.string("directions");
      x.residual = d.vector3("residual");
      x.weight = d.positive("weight");
    }
    a.datums.push_back(x);
  }
  const JsonCursor b = n.at("bestfit");
  a.bestfit_profile = b.non_negative("profile");
  a.bestfit_status = b.string("status");
  return a;
}

ComparisonDocument::Point read_point(const JsonCursor& n) {
  ComparisonDocument::Point p;
  p.id = n.string("id");
  p.measured = n.vector3("measured");
  p.registered = n.vector3("registered");
  p.contact = n.vector3("contact");
  p.face = n.string("face");
  p.face_index = n.integer("face_index");
  p.uv = Eigen::Vector2d(n.number("u"), n.number("v"));
  p.foot = n.vector3("foot");
  p.normal = n.vector3("normal");
  p.foot_location = n.string("foot_location");
  p.deviation = n.number("deviation");
  p.uncertainty = n.nullable_number("uncertainty");
  // Optional: files written before it was reported read as without it.
  if (n.has("redundancy") && !n.is_null("redundancy")) p.redundancy = n.number("redundancy");
  if (p.redundancy && !(*p.redundancy >= 0 && *p.redundancy <= 1))
    throw InputError(n.path("redundancy") + ": must lie between 0 and 1");
  p.evaluated = n.boolean("evaluated");
  if (!n.is_null("in_tolerance")) p.in_tolerance = n.boolean("in_tolerance");
  if (p.evaluated != p.in_tolerance.has_value())
    throw InputError(n.path("in_tolerance") + (p.evaluated ? ": an evaluated point needs true or false"
                                                           : ": must be null for a point not evaluated"));
  p.in_fit = n.boolean("in_fit");
  if (!n.is_null("outlier")) {
    const JsonCursor o = n.at("outlier");
    p.outlier = o.string("reason");
    p.outlier_detail = o.string("detail");
  }
  if (n.has("region")) p.region = n.integer("region");
  if (!n.is_null("prediction")) p.prediction = verification_json::read_point_prediction(n.at("prediction"));
  return p;
}

ComparisonSummary read_summary(const JsonCursor& n) {
  ComparisonSummary s;
  s.points = n.count("points");
  s.in_fit = n.count("in_fit");
  s.evaluated = n.count("evaluated");
  s.outliers = n.count("outliers");
  if (n.has("not_measured")) s.not_measured = n.count("not_measured");  // files before it had none
  s.in_tolerance = n.count("in_tolerance");
  s.out_of_tolerance = n.count("out_of_tolerance");
  s.deviations = read_statistics(n.at("deviation"));
  s.profile = n.non_negative("profile");
  s.confirmed_gouges = n.count("confirmed_gouges");
  s.unexplained_overcuts = n.count("unexplained_overcuts");
  s.pass = n.boolean("pass");
  // Files written before the three-state verdict have only "pass".
  s.verdict = n.has("verdict") ? parse_verdict(n.string("verdict"), n.path("verdict"))
                               : s.pass ? Verdict::pass : Verdict::fail;
  if (s.pass != (s.verdict == Verdict::pass))
    throw InputError(n.path("verdict") + ": " + to_string(s.verdict) + " contradicts \"pass\"");
  if (n.has("alignment")) {
    s.alignment = n.string("alignment");
    if (s.alignment != "ok" && s.alignment != "not_converged" && s.alignment != "too_few_points" &&
        s.alignment != "ambiguous_outliers" && s.alignment != "weakly_constrained" &&
        s.alignment != "ambiguous_orientation")
      throw InputError(n.path("alignment") + ": unknown alignment state " + quote_field(s.alignment) +
                       " (valid: ok, not_converged, too_few_points, ambiguous_outliers, weakly_constrained, "
                       "ambiguous_orientation)");
  }
  if (n.has("inconclusive")) {
    const json& list = n.array("inconclusive");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JsonCursor r(list[k], jf::child(n.path("inconclusive"), k));
      s.inconclusive.push_back({r.string("kind"), r.string("subject"), r.string("text")});
    }
  }
  if ((s.verdict == Verdict::inconclusive) == s.inconclusive.empty())
    throw InputError(n.path("inconclusive") + ": an INCONCLUSIVE verdict and its reasons go together");
  return s;
}

}  // namespace

ComparisonDocument parse_comparison(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  ComparisonDocument d;
  d.version = root.integer("version");
  if (d.version != kComparisonFormatVersion)
    throw InputError(root.path("version") + ": version " + std::to_string(d.version) +
                     " is not supported (this furrow reads version " +
                     std::to_string(kComparisonFormatVersion) + ")");
  if (root.string("units") != "mm") throw InputError(root.path("units") + ": comparisons are written in mm");
  d.sources.part = root.string("part");
  d.sources.measurements = root.string("measurements");
  // Written since several measurement files can be merged; absent before.
  if (root.has("measurement_files")) {
    const json& files = root.array("measurement_files");
    for (std::size_t k = 0; k < files.size(); ++k) {
      const JsonCursor f(files[k], jf::child(root.path("measurement_files"), k));
      d.sources.measurement_files.push_back(
          {f.string("path"), f.count("points"), f.has("sha256") ? f.string("sha256") : std::string()});
    }
  }
  const std::size_t file_count = d.sources.measurement_files.size();
  auto file_index = [&](const JsonCursor& n, const std::string& key) {
    const std::size_t f = n.count(key);
    if (f >= file_count)
      throw InputError(n.path(key) + ": file " + std::to_string(f) + " but measurement_files lists " +
                       std::to_string(file_count));
    return f;
  };
  if (root.has("replaced")) {
    const json& replaced = root.array("replaced");
    for (std::size_t k = 0; k < replaced.size(); ++k) {
      const JsonCursor r(replaced[k], jf::child(root.path("replaced"), k));
      d.sources.replaced.push_back({r.string("id"), file_index(r, "file"), file_index(r, "by_file"), r.vector3("was")});
    }
  }
  d.sources.plan = root.nullable_string("plan");
  d.sources.regions = root.nullable_string("regions_file");
  d.sources.prediction = root.nullable_string("prediction_file");
  d.options = read_options(root.at("options"));
  d.registration = read_registration(root.at("registration"));
  if (root.has("alignment")) d.alignment = read_alignment(root.at("alignment"));

  d.summary = read_summary(root.at("summary"));
  const JsonCursor reasons = root.at("summary").at("outlier_reasons");
  for (auto it = reasons.value().begin(); it != reasons.value().end(); ++it)
    d.registration.outliers[it.key()] = reasons.count(it.key());
  const json& regions = root.array("regions");
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const JsonCursor r(regions[k], jf::child(root.path("regions"), k));
    RegionStatistics rs;
    rs.region = r.integer("region");
    rs.deviations = read_statistics(r);
    rs.out_of_tolerance = r.count("out_of_tolerance");
    d.summary.regions.push_back(rs);
  }

  const json& points = root.array("points");
  d.points.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::string where = jf::child(root.path("points"), k);
    const JsonCursor point(points[k], where);
    d.points.push_back(read_point(point));
    if (point.has("file")) d.points.back().file = file_index(point, "file");
    if (!d.points_by_id.emplace(d.points.back().id, k).second)
      throw InputError(where + ".id: duplicate id " + quote_field(d.points.back().id));
  }
  if (d.points.size() != d.summary.points)
    throw InputError(root.path("points") + ": " + std::to_string(d.points.size()) +
                     " points but summary.points says " + std::to_string(d.summary.points));

  const bool predicted = !d.sources.prediction.empty();
  for (const char* key : {"prediction_comparison", "gouge_sites", "unexplained"})
    if (root.is_null(key) == predicted)
      throw InputError(root.path(key) + (predicted ? ": missing although a prediction_file is named"
                                                   : ": present without a prediction_file"));
  for (std::size_t k = 0; k < d.points.size(); ++k)
    if (d.points[k].prediction.has_value() != predicted)
      throw InputError(jf::child(jf::child(root.path("points"), k), "prediction") +
                       (predicted ? ": missing although a prediction_file is named"
                                  : ": present without a prediction_file"));
  if (!predicted) return d;
  d.prediction = verification_json::read_prediction_comparison(root.at("prediction_comparison"));
  for (const ComparisonDocument::Point& p : d.points) d.prediction->points.push_back(*p.prediction);
  d.gouges = verification_json::read_gouge_confirmation(root, d.points_by_id);
  return d;
}

ComparisonDocument read_comparison(const std::string& path) {
  return parse_comparison(jf::read_text(path), path);
}

}  // namespace furrow
