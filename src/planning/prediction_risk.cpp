#include "planning/prediction_risk.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"

namespace furrow {

PredictionRiskMap::PredictionRiskMap(const Prediction& prediction, const Part& part,
                                     const std::string& prediction_name, const std::string& part_name)
    : prediction_(&prediction), grids_(part.faces.size(), nullptr) {
  check_prediction_against_part(prediction, part, prediction_name, part_name);
  for (const FaceGridRecord& g : prediction.faces) grids_[*part.find_face(g.name)] = &g;
  for (std::size_t k = 0; k < prediction.gouge_sites.size(); ++k) {
    const GougeSiteRecord& s = prediction.gouge_sites[k];
    const std::optional<std::size_t> f = part.find_face(s.face);
    if (!grids_[*f])
      throw InputError(prediction_name + ": gouge_sites[" + std::to_string(k) + "]: face \"" + s.face +
                       "\" is not a predicted face of the part");
    RiskSite site;
    site.id = "G" + std::to_string(s.id);
    site.face = static_cast<int>(*f);
    site.uv_box = s.uv_box;
    site.uv_centre = s.deepest.uv;
    site.uv_box.extend(site.uv_centre);
    site.depth = s.depth;
    sites_.push_back(site);
  }
}

double PredictionRiskMap::error_magnitude(int face, const Eigen::Vector2d& uv) const {
  if (face < 0 || face >= static_cast<int>(grids_.size()) || !grids_[static_cast<std::size_t>(face)]) return 0;
  const PredictedError e = prediction_->predicted_error_at(grids_[static_cast<std::size_t>(face)]->name, uv.x(), uv.y());
  if (!e.reached()) return 0;
  return std::max({std::abs(e.max_undercut), std::abs(e.max_overcut), std::abs(e.value)});
}

}  // namespace furrow
