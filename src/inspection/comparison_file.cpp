#include "inspection/comparison_file.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "inspection/verification_json.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

json statistics_json(const DeviationStatistics& s) {
  return {{"count", s.count},
          {"mean", jf::finite(s.mean, "mean")},
          {"sigma", jf::finite(s.sigma, "sigma")},
          {"min", jf::finite(s.min, "min")},
          {"max", jf::finite(s.max, "max")}};
}

// Placement of the part on the CMM in simulate-measurement's convention:
// x_cmm = Rz(rz) Ry(ry) Rx(rx) x_part + t (degrees, mm).
json placement_json(const Eigen::Isometry3d& cmm_to_part) {
  const Eigen::Isometry3d m = cmm_to_part.inverse();
  const Eigen::Matrix3d& r = m.linear();
  const double deg = 180 / M_PI;
  const Eigen::Vector3d angles(std::atan2(r(2, 1), r(2, 2)),
                               std::asin(std::clamp(-r(2, 0), -1.0, 1.0)),
                               std::atan2(r(1, 0), r(0, 0)));
  return {{"rotation_deg", jf::vector_json(Eigen::Vector3d(angles * deg))},
          {"translation", jf::vector_json(Eigen::Vector3d(m.translation()))}};
}

json matrix_json(const Eigen::MatrixXd& m, const char* what) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(jf::finite(m(i, j), what));
    rows.push_back(std::move(row));
  }
  return rows;
}

json registration_json(const RegistrationResult& r, const RegistrationOptions& o) {
  json j;
  json dof = json::array();
  for (int k = 0; k < 6; ++k)
    if (o.dof.free[k]) dof.push_back(dof_name(k));
  j["dof"] = std::move(dof);
  j["loss"] = to_string(o.loss);
  j["loss_scale"] = jf::finite(o.loss_scale, "loss scale");
  j["coarse"] = {{"method", to_string(r.coarse.method)},
                 {"matched_ids", r.coarse.matched},
                 {"candidates", r.coarse.candidates},
                 {"median_distance", jf::finite(r.coarse.median_distance, "coarse median")},
                 {"ambiguous", r.coarse.ambiguous}};
  j["transform"] = matrix_json(r.transform.matrix(), "transform");
  j["placement"] = placement_json(r.transform);
  j["rms_before"] = jf::finite(r.rms_before, "rms before");
  j["rms_after"] = jf::finite(r.rms_after, "rms after");
  j["sigma"] = jf::finite(r.sigma, "sigma");
  j["outer_iterations"] = r.outer_iterations;
  j["solver_iterations"] = r.solver_iterations;
  j["outlier_passes"] = r.outlier_passes;
  j["converged"] = r.converged;
  j["status"] = r.status;
  j["covariance_status"] = r.covariance_status;
  if (r.covariance) {
    j["covariance"] = matrix_json(*r.covariance, "covariance");
    json sd = json::array();
    for (int k = 0; k < 6; ++k) sd.push_back(jf::finite(std::sqrt((*r.covariance)(k, k)), "sd"));
    j["standard_deviation"] = std::move(sd);
  } else {
    j["covariance"] = nullptr;
    j["standard_deviation"] = nullptr;
  }
  j["outlier_rule"] = {{"sigmas", jf::finite(o.outlier_sigma, "sigmas")},
                       {"floor", jf::finite(o.outlier_floor, "floor")},
                       {"edge_tolerance", jf::finite(o.edge_tolerance, "edge tolerance")},
                       {"confirm_neighbours", o.confirm_neighbours},
                       {"neighbour_radius", jf::finite(o.neighbour_radius, "radius")}};
  return j;
}

// Everything the comparison ran with (docs/formats.md "Comparison").
json options_json(const CompareOptions& o, const MeasurementSet& set,
                  const ComparisonSources& sources) {
  const RegistrationOptions& r = o.registration;
  return {{"tolerance", jf::finite(o.tolerance.width, "tolerance")},
          {"outside", jf::finite(o.tolerance.outside, "outside")},
          {"dof", r.dof.to_string()},
          {"loss", to_string(r.loss)},
          {"loss_scale", jf::finite(r.loss_scale, "loss scale")},
          {"points", to_string(set.kind)},
          {"probe_diameter", jf::finite(2 * set.probe_radius, "probe diameter")},
          {"units", sources.measurement_units},
          {"outlier_rejection", r.flag_outliers},
          {"outlier_sigma", jf::finite(r.outlier_sigma, "outlier sigma")},
          {"outlier_floor", jf::finite(r.outlier_floor, "outlier floor")},
          {"edge_tolerance", jf::finite(r.edge_tolerance, "edge tolerance")},
          {"confirm_neighbours", r.confirm_neighbours},
          {"neighbour_radius", jf::finite(r.neighbour_radius, "neighbour radius")},
          {"max_outer_iterations", r.max_outer_iterations},
          {"max_solver_iterations", r.max_solver_iterations},
          {"max_outlier_passes", r.max_outlier_passes},
          {"motion_tolerance", jf::finite(r.motion_tolerance, "motion tolerance")},
          {"prediction", verification_json::options_json(o.prediction)},
          {"gouges", verification_json::options_json(o.gouges)}};
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

json point_json(const Comparison& c, const MeasurementSet& set, const Part& part, std::size_t i) {
  const RegisteredPoint& p = c.registration.points[i];
  const bool have_covariance = c.registration.covariance.has_value();
  json j;
  j["id"] = set.points[i].id;
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
  doc["registration"] = registration_json(c.registration, options.registration);
  doc["summary"] = {{"points", s.points},
                    {"in_fit", s.in_fit},
                    {"evaluated", s.evaluated},
                    {"outliers", s.outliers},
                    {"outlier_reasons", outlier_counts_json(c.registration)},
                    {"in_tolerance", s.in_tolerance},
                    {"out_of_tolerance", s.out_of_tolerance},
                    {"deviation", statistics_json(s.deviations)},
                    {"profile", jf::finite(s.profile, "profile")},
                    {"confirmed_gouges", s.confirmed_gouges},
                    {"unexplained_overcuts", s.unexplained_overcuts},
                    {"pass", s.pass}};
  json regions = json::array();
  for (const RegionStatistics& r : s.regions) {
    json jr = statistics_json(r.deviations);
    jr["region"] = r.region;
    jr["out_of_tolerance"] = r.out_of_tolerance;
    regions.push_back(std::move(jr));
  }
  doc["regions"] = std::move(regions);
  std::vector<std::string> ids;
  for (const MeasuredPoint& p : set.points) ids.push_back(p.id);
  doc["prediction_comparison"] =
      c.prediction ? verification_json::prediction_comparison_json(*c.prediction) : json(nullptr);
  doc["gouge_sites"] = c.gouges ? verification_json::gouge_sites_json(*c.gouges, ids) : json(nullptr);
  doc["unexplained"] = c.gouges ? verification_json::unexplained_json(*c.gouges, ids) : json(nullptr);
  std::string text = jf::to_text(doc);

  // Splice the points in before the closing brace, one compact line each.
  const std::size_t close = text.rfind('}');
  std::string points = ",\n  \"points\": [";
  for (std::size_t i = 0; i < c.registration.points.size(); ++i) {
    points += i == 0 ? "\n    " : ",\n    ";
    points += point_json(c, set, part, i).dump();
  }
  points += c.registration.points.empty() ? "]\n" : "\n  ]\n";
  std::size_t end_of_last = close;
  while (end_of_last > 0 && (text[end_of_last - 1] == '\n' || text[end_of_last - 1] == ' '))
    --end_of_last;
  return text.substr(0, end_of_last) + points + "}\n";
}

}  // namespace furrow
