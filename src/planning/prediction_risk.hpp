#pragma once
// The machining prediction (prediction.json, machining/prediction/prediction.hpp) seen
// through the planner's RiskMap: the predicted |error| at a surface point
// and the predicted gouge sites.
//
//   error_magnitude  the worst error predicted in the prediction cell that
//                    holds (u, v), either sign: max(max_undercut,
//                    -max_overcut) of the cell [mm]; 0 where the tool did
//                    not reach, outside the face, or on a face the
//                    prediction does not cover;
//   gouge_sites      one per predicted gouge site: id "G<n>", the part's
//                    face index, the site's uv box and its deepest point as
//                    centre, the depth.
//
// The constructor checks that the prediction belongs to the part
// (check_prediction_against_part, InputError naming both files) and that
// every gouge site lies on a face the prediction covers.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "machining/prediction/prediction.hpp"
#include "planning/risk_map.hpp"

namespace furrow {

class PredictionRiskMap : public RiskMap {
 public:
  // The prediction and part must outlive the map.
  PredictionRiskMap(const Prediction& prediction, const Part& part, const std::string& prediction_name,
                    const std::string& part_name);

  double error_magnitude(int face, const Eigen::Vector2d& uv) const override;
  const std::vector<RiskSite>& gouge_sites() const override { return sites_; }

 private:
  const Prediction* prediction_;
  std::vector<const FaceGridRecord*> grids_;  // per part face, null when not predicted
  std::vector<RiskSite> sites_;
};

}  // namespace furrow
