// The fit options of a scan comparison (contract in scan_fit_options_json.hpp).
#include "inspection/scan_fit_options_json.hpp"

#include "base/error.hpp"

namespace furrow {

namespace jf = json_fields;
using nlohmann::json;

json scan_fit_options_json(const RegistrationOptions& r) {
  return {{"dof", r.dof.to_string()},
          {"loss", to_string(r.loss)},
          {"loss_scale", jf::finite(r.loss_scale, "loss scale")},
          {"outlier_rejection", r.flag_outliers},
          {"outlier_sigma", jf::finite(r.outlier_sigma, "outlier sigma")},
          {"outlier_floor", jf::finite(r.outlier_floor, "outlier floor")},
          {"edge_tolerance", jf::finite(r.edge_tolerance, "edge tolerance")},
          {"confirm_neighbours", r.confirm_neighbours},
          {"neighbour_radius", jf::finite(r.neighbour_radius, "neighbour radius")},
          {"max_outer_iterations", r.max_outer_iterations},
          {"max_solver_iterations", r.max_solver_iterations},
          {"max_outlier_passes", r.max_outlier_passes},
          {"motion_tolerance", jf::finite(r.motion_tolerance, "motion tolerance")}};
}

void read_scan_fit_options(const JsonCursor& n, ComparisonDocument::Options& o) {
  o.dof = n.string("dof");
  o.loss = n.string("loss");
  if (o.loss != "cauchy" && o.loss != "huber" && o.loss != "none")
    throw InputError(n.path("loss") + ": expected cauchy, huber or none");
  o.loss_scale = n.non_negative("loss_scale");
  o.outlier_rejection = n.boolean("outlier_rejection");
  o.outlier_sigma = n.non_negative("outlier_sigma");
  o.outlier_floor = n.non_negative("outlier_floor");
  o.edge_tolerance = n.non_negative("edge_tolerance");
  o.confirm_neighbours = n.integer("confirm_neighbours", 0);
  o.neighbour_radius = n.non_negative("neighbour_radius");
  o.max_outer_iterations = n.integer("max_outer_iterations", 0);
  o.max_solver_iterations = n.integer("max_solver_iterations", 0);
  o.max_outlier_passes = n.integer("max_outlier_passes", 0);
  o.motion_tolerance = n.non_negative("motion_tolerance");
  n.finish("docs/formats.md \"comparison.json of a scan\"");
}

}  // namespace furrow
