#include "inspection/verification_json.hpp"

#include "base/error.hpp"

namespace furrow::verification_json {

namespace jf = json_fields;

namespace {

json optional_json(const std::optional<double>& x, const char* what) {
  return x ? jf::finite(*x, what) : json(nullptr);
}

json box_json(const Eigen::AlignedBox2d& b) {
  return {{"min", jf::vector_json(Eigen::Vector2d(b.min()))}, {"max", jf::vector_json(Eigen::Vector2d(b.max()))}};
}

Eigen::AlignedBox2d read_box(const JsonCursor& n) {
  const Eigen::Vector2d lo = n.vector2("min"), hi = n.vector2("max");
  if ((hi.array() < lo.array()).any()) throw InputError(n.where() + ": max lies below min");
  return Eigen::AlignedBox2d(lo, hi);
}

std::size_t point_index(const JsonCursor& n, const std::string& key, const json& id,
                        const std::map<std::string, std::size_t>& index_of) {
  const std::string text = jf::string(id, n.path(key));
  const auto it = index_of.find(text);
  if (it == index_of.end()) throw InputError(n.path(key) + ": \"" + text + "\" is not a point id of this file");
  return it->second;
}

std::vector<std::size_t> point_indices(const JsonCursor& n, const std::string& key,
                                       const std::map<std::string, std::size_t>& index_of) {
  std::vector<std::size_t> out;
  const json& ids = n.array(key);
  for (std::size_t k = 0; k < ids.size(); ++k)
    out.push_back(point_index(n, key + "[" + std::to_string(k) + "]", ids[k], index_of));
  return out;
}

json id_list(const std::vector<std::size_t>& points, const std::vector<std::string>& ids) {
  json out = json::array();
  for (std::size_t i : points) out.push_back(ids[i]);
  return out;
}

json statistics_json(const ResidualStatistics& s) {
  return {{"count", s.count},
          {"mean_predicted", jf::finite(s.mean_predicted, "mean predicted")},
          {"mean_measured", jf::finite(s.mean_measured, "mean measured")},
          {"residual_mean", jf::finite(s.mean, "residual mean")},
          {"residual_sigma", jf::finite(s.sigma, "residual sigma")},
          {"residual_rms", jf::finite(s.rms, "residual rms")},
          {"residual_max_abs", jf::finite(s.max_abs, "residual max")},
          {"correlation", optional_json(s.correlation, "correlation")},
          {"normalised_rms", jf::finite(s.normalised_rms, "normalised rms")},
          {"within_share", jf::finite(s.within_share, "within share")},
          {"verdict", to_string(s.verdict)}};
}

ResidualStatistics read_statistics(const JsonCursor& n) {
  ResidualStatistics s;
  s.count = n.count("count");
  s.mean_predicted = n.number("mean_predicted");
  s.mean_measured = n.number("mean_measured");
  s.mean = n.number("residual_mean");
  s.sigma = n.non_negative("residual_sigma");
  s.rms = n.non_negative("residual_rms");
  s.max_abs = n.non_negative("residual_max_abs");
  s.correlation = n.nullable_number("correlation");
  s.normalised_rms = n.non_negative("normalised_rms");
  s.within_share = n.non_negative("within_share");
  s.verdict = parse_prediction_verdict(n.string("verdict"), n.path("verdict"));
  return s;
}

ErrorCellStatus parse_cell_status(const std::string& text, const std::string& where) {
  for (ErrorCellStatus s : {ErrorCellStatus::reached, ErrorCellStatus::not_reached, ErrorCellStatus::outside,
                            ErrorCellStatus::not_machinable})
    if (text == to_string(s)) return s;
  throw InputError(where + ": \"" + text +
                   "\" is not a prediction status (reached, not_reached, outside, not_machinable, "
                   "face_not_predicted)");
}

}  // namespace

json options_json(const PredictionComparisonOptions& o) {
  return {{"probe_sigma", jf::finite(o.probe_sigma, "probe sigma")},
          {"align", o.align},
          {"max_alignment_iterations", o.max_alignment_iterations},
          {"max_normalised_rms", jf::finite(o.max_normalised_rms, "normalised rms limit")},
          {"within_sigmas", jf::finite(o.within_sigmas, "within sigmas")},
          {"required_share", jf::finite(o.required_share, "required share")},
          {"min_points", o.min_points}};
}

json options_json(const GougeConfirmationOptions& o) {
  return {{"overcut_sigmas", jf::finite(o.overcut_sigmas, "overcut sigmas")},
          {"tolerance_fraction", jf::finite(o.tolerance_fraction, "tolerance fraction")},
          {"site_margin", jf::finite(o.site_margin, "site margin")},
          {"contact_cluster_distance", jf::finite(o.contact_cluster_distance, "contact cluster distance")},
          {"overcut_cluster_distance", jf::finite(o.overcut_cluster_distance, "overcut cluster distance")}};
}

PredictionComparisonOptions read_prediction_options(const JsonCursor& n) {
  PredictionComparisonOptions o;
  o.probe_sigma = n.non_negative("probe_sigma");
  o.align = n.boolean("align");
  o.max_alignment_iterations = n.integer("max_alignment_iterations");
  o.max_normalised_rms = n.non_negative("max_normalised_rms");
  o.within_sigmas = n.non_negative("within_sigmas");
  o.required_share = n.non_negative("required_share");
  o.min_points = n.integer("min_points");
  return o;
}

GougeConfirmationOptions read_gouge_options(const JsonCursor& n) {
  GougeConfirmationOptions o;
  o.overcut_sigmas = n.non_negative("overcut_sigmas");
  o.tolerance_fraction = n.non_negative("tolerance_fraction");
  o.site_margin = n.non_negative("site_margin");
  o.contact_cluster_distance = n.non_negative("contact_cluster_distance");
  o.overcut_cluster_distance = n.non_negative("overcut_cluster_distance");
  return o;
}

json point_prediction_json(const PointPrediction& p) {
  json j;
  j["status"] = p.face_predicted ? to_string(p.status) : "face_not_predicted";
  j["compared"] = p.compared;
  if (!p.reached()) return j;
  j["predicted"] = jf::finite(p.predicted, "predicted error");
  j["band"] = json::array({jf::finite(p.band_low, "band"), jf::finite(p.band_high, "band")});
  j["measured"] = jf::finite(p.measured, "aligned deviation");
  j["residual"] = jf::finite(p.residual, "residual");
  j["sigma"] = jf::finite(p.sigma, "residual sigma");
  return j;
}

PointPrediction read_point_prediction(const JsonCursor& n) {
  PointPrediction p;
  const std::string status = n.string("status");
  p.face_predicted = status != "face_not_predicted";
  if (p.face_predicted) p.status = parse_cell_status(status, n.path("status"));
  p.compared = n.boolean("compared");
  if (p.compared && !p.reached()) throw InputError(n.path("compared") + ": a point the prediction did not reach is not compared");
  if (!p.reached()) return p;
  p.predicted = n.number("predicted");
  const Eigen::Vector2d band = n.vector2("band");
  p.band_low = band.x();
  p.band_high = band.y();
  p.measured = n.number("measured");
  p.residual = n.number("residual");
  p.sigma = n.non_negative("sigma");
  return p;
}

json prediction_comparison_json(const PredictionComparison& c) {
  const PredictionAlignment& a = c.alignment;
  json parameters = json::array();
  for (int k = 0; k < 6; ++k) parameters.push_back(jf::finite(a.parameters(k), "alignment"));
  json regions = json::array();
  for (const RegionResidualStatistics& r : c.regions) {
    json jr = statistics_json(r.statistics);
    jr["region"] = r.region;
    regions.push_back(std::move(jr));
  }
  return {{"alignment",
           {{"applied", a.applied},
            {"status", a.status},
            {"parameters", std::move(parameters)},
            {"points", a.points},
            {"iterations", a.iterations},
            {"rms_before", jf::finite(a.rms_before, "alignment rms")},
            {"rms_after", jf::finite(a.rms_after, "alignment rms")}}},
          {"overall", statistics_json(c.overall)},
          {"regions", std::move(regions)},
          {"uncompared",
           {{"face_not_predicted", c.uncompared.face_not_predicted},
            {"not_reached", c.uncompared.not_reached},
            {"outside", c.uncompared.outside},
            {"not_machinable", c.uncompared.not_machinable}}}};
}

PredictionComparison read_prediction_comparison(const JsonCursor& n) {
  PredictionComparison c;
  const JsonCursor a = n.at("alignment");
  c.alignment.applied = a.boolean("applied");
  c.alignment.status = a.string("status");
  const std::vector<double> p = jf::numbers(a.raw("parameters"), a.path("parameters"));
  if (p.size() != 6) throw InputError(a.path("parameters") + ": expected 6 numbers (rx, ry, rz, tx, ty, tz)");
  for (int k = 0; k < 6; ++k) c.alignment.parameters(k) = p[static_cast<std::size_t>(k)];
  c.alignment.points = a.count("points");
  c.alignment.iterations = a.integer("iterations");
  c.alignment.rms_before = a.non_negative("rms_before");
  c.alignment.rms_after = a.non_negative("rms_after");
  c.overall = read_statistics(n.at("overall"));
  const json& regions = n.array("regions");
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const JsonCursor r(regions[k], jf::child(n.path("regions"), k));
    c.regions.push_back({r.integer("region"), read_statistics(r)});
  }
  const JsonCursor u = n.at("uncompared");
  c.uncompared.face_not_predicted = u.count("face_not_predicted");
  c.uncompared.not_reached = u.count("not_reached");
  c.uncompared.outside = u.count("outside");
  c.uncompared.not_machinable = u.count("not_machinable");
  return c;
}

json gouge_site_json(const GougeSiteCheck& s, json points, json deepest) {
  json j;
  j["id"] = s.id;
  j["source"] = to_string(s.source);
  j["face"] = s.face;
  j["face_index"] = s.face_index;
  j["uv_box"] = box_json(s.uv_box);
  j["search_box"] = box_json(s.search_box);
  j["centroid"] = jf::vector_json(s.centroid);
  j["predicted_depth"] = optional_json(s.predicted_depth, "predicted depth");
  j["contacts"] = s.contacts;
  j["status"] = to_string(s.status);
  j["points"] = std::move(points);
  j["deepest"] = std::move(deepest);
  j["measured_depth"] = optional_json(s.measured_depth, "measured depth");
  j["uncertainty"] = optional_json(s.uncertainty, "uncertainty");
  j["threshold"] = optional_json(s.threshold, "threshold");
  j["predicted_error"] = optional_json(s.predicted_error, "predicted error");
  j["depth_consistent"] = s.depth_consistent ? json(*s.depth_consistent) : json(nullptr);
  return j;
}

json gouge_sites_json(const GougeConfirmation& g, const std::vector<std::string>& ids) {
  json sites = json::array();
  for (const GougeSiteCheck& s : g.sites)
    sites.push_back(gouge_site_json(s, id_list(s.points, ids), s.deepest ? json(ids[*s.deepest]) : json(nullptr)));
  return sites;
}

json overcut_cluster_json(const OvercutCluster& u, json points, json deepest) {
  return {{"id", u.id},
          {"points", std::move(points)},
          {"deepest", std::move(deepest)},
          {"face", u.face},
          {"face_index", u.face_index},
          {"uv", jf::vector_json(u.uv)},
          {"xyz", jf::vector_json(u.xyz)},
          {"depth", jf::finite(u.depth, "depth")},
          {"uncertainty", jf::finite(u.uncertainty, "uncertainty")},
          {"threshold", jf::finite(u.threshold, "threshold")},
          {"centroid", jf::vector_json(u.centroid)}};
}

json unexplained_json(const GougeConfirmation& g, const std::vector<std::string>& ids) {
  json clusters = json::array();
  for (const OvercutCluster& u : g.unexplained)
    clusters.push_back(overcut_cluster_json(u, id_list(u.points, ids), ids[u.deepest]));
  return clusters;
}

GougeSiteCheck read_gouge_site_fields(const JsonCursor& n) {
  GougeSiteCheck s;
  s.id = n.string("id");
  s.source = parse_gouge_site_source(n.string("source"), n.path("source"));
  s.face = n.string("face");
  s.face_index = n.integer("face_index");
  s.uv_box = read_box(n.at("uv_box"));
  s.search_box = read_box(n.at("search_box"));
  s.centroid = n.vector3("centroid");
  s.predicted_depth = n.nullable_number("predicted_depth");
  s.contacts = n.count("contacts");
  s.status = parse_gouge_site_status(n.string("status"), n.path("status"));
  s.measured_depth = n.nullable_number("measured_depth");
  s.uncertainty = n.nullable_number("uncertainty");
  s.threshold = n.nullable_number("threshold");
  s.predicted_error = n.nullable_number("predicted_error");
  if (!n.is_null("depth_consistent")) s.depth_consistent = n.boolean("depth_consistent");
  return s;
}

OvercutCluster read_overcut_cluster_fields(const JsonCursor& n) {
  OvercutCluster u;
  u.id = n.string("id");
  u.face = n.string("face");
  u.face_index = n.integer("face_index");
  u.uv = n.vector2("uv");
  u.xyz = n.vector3("xyz");
  u.depth = n.number("depth");
  u.uncertainty = n.non_negative("uncertainty");
  u.threshold = n.non_negative("threshold");
  u.centroid = n.vector3("centroid");
  return u;
}

GougeConfirmation read_gouge_confirmation(const JsonCursor& root,
                                          const std::map<std::string, std::size_t>& index_of) {
  GougeConfirmation g;
  const json& sites = root.array("gouge_sites");
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const JsonCursor n(sites[k], jf::child(root.path("gouge_sites"), k));
    GougeSiteCheck s = read_gouge_site_fields(n);
    s.points = point_indices(n, "points", index_of);
    if (!n.is_null("deepest")) s.deepest = point_index(n, "deepest", n.raw("deepest"), index_of);
    if ((s.status == GougeSiteStatus::not_measured) != s.points.empty() ||
        s.deepest.has_value() == s.points.empty() || s.measured_depth.has_value() == s.points.empty())
      throw InputError(n.where() + ": a site is NOT MEASURED exactly when it has no points, and then has no deepest point or depth");
    g.sites.push_back(std::move(s));
  }
  const json& unexplained = root.array("unexplained");
  for (std::size_t k = 0; k < unexplained.size(); ++k) {
    const JsonCursor n(unexplained[k], jf::child(root.path("unexplained"), k));
    OvercutCluster u = read_overcut_cluster_fields(n);
    u.points = point_indices(n, "points", index_of);
    u.deepest = point_index(n, "deepest", n.raw("deepest"), index_of);
    g.unexplained.push_back(std::move(u));
  }
  return g;
}

}  // namespace furrow::verification_json
