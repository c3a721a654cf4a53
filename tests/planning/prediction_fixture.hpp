#pragma once
// The planner's synthetic prediction (support/synthetic_prediction.hpp): a
// single Gaussian error peak known in closed form, an asymmetric band, a
// first column of cells the tool never reached, and gouge sites where the
// test puts them. The planner's tests depend on the prediction's format
// only, not on how a prediction is computed.
#include <cmath>
#include <vector>

#include "support/synthetic_prediction.hpp"

namespace furrow::test {

// m(u, v) = 0.04 exp(-|uv - peak|^2 / 0.01); the band is [m - 0.002,
// m + 0.003], so the worst magnitude is m + 0.003 where m >= 0.
inline double synthetic_mean(const Eigen::Vector2d& uv, const Eigen::Vector2d& peak) {
  return 0.04 * std::exp(-(uv - peak).squaredNorm() / 0.01);
}

// Cells with ci == 0 are "not reached"; every site is 0.05 deep.
inline Prediction synthetic_prediction(const Part& part, const Eigen::Vector2d& peak,
                                       const std::vector<Eigen::Vector2d>& sites, int cells_u = 50, int cells_v = 40) {
  const ParameterDomain& d = part.faces[0].domain();
  const double first_column_end = d.u0 + d.width_u() / cells_u;
  Prediction p = field_prediction(
      part, [&](const Eigen::Vector2d& uv) { return synthetic_mean(uv, peak); }, ErrorBand(0.002, 0.003),
      [=](const Eigen::Vector2d& uv) { return uv.x() > first_column_end; }, cells_u, cells_v);
  p.part = "synthetic";
  p.tool = {"ball_d20", ToolType::ball, 20, 10};
  p.tolerance = 0.02;
  p.gouge_threshold = 0.04;
  p.zmap.nx = 1000;
  p.zmap.ny = 800;
  for (const Eigen::Vector2d& uv : sites) add_zmap_site(p, part, uv, {0.01, 0.01}, 0.05);
  return p;
}

}  // namespace furrow::test
