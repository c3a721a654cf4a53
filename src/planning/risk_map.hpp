#pragma once
// What the planner needs to know about predicted machining errors: how large
// the error is expected to be at a surface point, and where local gouges are
// predicted. The machining prediction (prediction.json) is one
// source; tests use synthetic maps. The planner never sees a file format,
// only this interface, so it is tested without the predictor.
//
// Units: mm. Sign: error_magnitude is |e| >= 0 whatever the sign of the
// predicted error (undercut or overcut both deserve a look); a gouge's depth
// is the predicted overcut as a positive number.
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace furrow {

struct RiskSite {
  std::string id;                // unique label ("G1"), used in the plan report
  int face = 0;                  // face index in the part
  Eigen::AlignedBox2d uv_box;    // extent of the site on the face (u, v)
  Eigen::Vector2d uv_centre = Eigen::Vector2d::Zero();  // where it is deepest; inside uv_box
  double depth = 0;              // predicted overcut [mm], > 0
};

class RiskMap {
 public:
  virtual ~RiskMap() = default;
  // Predicted |error| [mm] at (u, v) of face `face`; 0 where nothing is
  // predicted (including outside the predictor's coverage). Must be finite
  // and >= 0; may be called concurrently.
  virtual double error_magnitude(int face, const Eigen::Vector2d& uv) const = 0;
  // Predicted gouge sites (may be empty).
  virtual const std::vector<RiskSite>& gouge_sites() const = 0;
};

}  // namespace furrow
