#include "inspection/comparison_json.hpp"

#include <algorithm>
#include <cmath>

#include "inspection/verification_json.hpp"

namespace furrow::comparison_json {

namespace jf = json_fields;

json matrix_json(const Eigen::MatrixXd& m, const char* what) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(jf::finite(m(i, j), what));
    rows.push_back(std::move(row));
  }
  return rows;
}

json statistics_json(const DeviationStatistics& s) {
  return {{"count", s.count},
          {"mean", jf::finite(s.mean, "mean")},
          {"sigma", jf::finite(s.sigma, "sigma")},
          {"min", jf::finite(s.min, "min")},
          {"max", jf::finite(s.max, "max")}};
}

DeviationStatistics read_statistics(const JsonCursor& n) {
  DeviationStatistics s;
  s.count = n.count("count");
  s.mean = n.number("mean");
  s.sigma = n.non_negative("sigma");
  s.min = n.number("min");
  s.max = n.number("max");
  return s;
}

json run_options_json(const ComparisonDocument::Options& o) {
  return {{"dof", o.dof},
          {"loss", o.loss},
          {"loss_scale", jf::finite(o.loss_scale, "loss scale")},
          {"points", o.points},
          {"probe_diameter", jf::finite(o.probe_diameter, "probe diameter")},
          {"units", o.units},
          {"outlier_rejection", o.outlier_rejection},
          {"outlier_sigma", jf::finite(o.outlier_sigma, "outlier sigma")},
          {"outlier_floor", jf::finite(o.outlier_floor, "outlier floor")},
          {"edge_tolerance", jf::finite(o.edge_tolerance, "edge tolerance")},
          {"confirm_neighbours", o.confirm_neighbours},
          {"neighbour_radius", jf::finite(o.neighbour_radius, "neighbour radius")},
          {"max_outer_iterations", o.max_outer_iterations},
          {"max_solver_iterations", o.max_solver_iterations},
          {"max_outlier_passes", o.max_outlier_passes},
          {"motion_tolerance", jf::finite(o.motion_tolerance, "motion tolerance")},
          {"prediction", verification_json::options_json(o.prediction)},
          {"gouges", verification_json::options_json(o.gouges)}};
}

json registration_json(const ComparisonDocument::Registration& r) {
  json j;
  j["transform"] = matrix_json(r.transform, "transform");
  j["placement"] = {{"rotation_deg", jf::vector_json(r.placement_rotation_deg)},
                    {"translation", jf::vector_json(r.placement_translation)}};
  j["coarse"] = {{"method", r.coarse_method},
                 {"matched_ids", r.coarse_matched_ids},
                 {"candidates", r.coarse_candidates},
                 {"median_distance", jf::finite(r.coarse_median_distance, "coarse median")},
                 {"ambiguous", r.coarse_ambiguous}};
  j["rms_before"] = jf::finite(r.rms_before, "rms before");
  j["rms_after"] = jf::finite(r.rms_after, "rms after");
  j["sigma"] = jf::finite(r.sigma, "sigma");
  j["outer_iterations"] = r.outer_iterations;
  j["solver_iterations"] = r.solver_iterations;
  j["outlier_passes"] = r.outlier_passes;
  j["converged"] = r.converged;
  j["status"] = r.status;
  j["outcome"] = r.outcome;
  j["fitted_dof"] = r.fitted_dof;
  json weak = json::array();
  for (const auto& w : r.weak) {
    json d = {{"text", w.text},
              {"kind", w.translation ? "translation" : "rotation"},
              {"direction", jf::vector_json(w.direction)},
              {"ratio", jf::finite(w.ratio, "weak ratio")},
              {"sigma", w.sigma ? json(jf::finite(*w.sigma, "weak sigma")) : json(nullptr)},
              {"held", w.held},
              {"from_points", w.from_points}};
    if (!w.translation) {
      d["axis_point"] = jf::vector_json(w.axis_point);
      d["pitch"] = jf::finite(w.pitch, "pitch");
    }
    weak.push_back(std::move(d));
  }
  j["weak_directions"] = std::move(weak);
  j["ambiguous_outliers"] = r.ambiguous_outliers;
  j["covariance_status"] = r.covariance_status;
  if (r.covariance) {
    j["covariance"] = matrix_json(*r.covariance, "covariance");
    json sd = json::array();
    // Clamp round-off: a locked parameter's variance is 0 and must not become NaN.
    for (int k = 0; k < 6; ++k) sd.push_back(jf::finite(std::sqrt(std::max(0.0, (*r.covariance)(k, k))), "sd"));
    j["standard_deviation"] = std::move(sd);
  } else {
    j["covariance"] = nullptr;
    j["standard_deviation"] = nullptr;
  }
  return j;
}

}  // namespace furrow::comparison_json
