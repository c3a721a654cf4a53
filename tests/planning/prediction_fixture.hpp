#pragma once
// A synthetic machining prediction of a part (the machining module's own
// data type, written and read by its prediction.json functions): an error
// field known in closed form, and gouge sites where the test puts them. The
// planner's tests use it so they depend on the prediction's format, not on
// how a prediction is computed.
#include <cmath>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "machining/prediction.hpp"

namespace furrow::test {

// Cell (ci, cj) of the single face gets mean m(u, v) at its centre, band
// [m - 0.002, m + 0.003] (so the worst magnitude is |m| + 0.003 for m >= 0);
// cells with ci == 0 are "not reached". m = 0.04 exp(-|uv - peak|^2 / 0.01).
inline double synthetic_mean(const Eigen::Vector2d& uv, const Eigen::Vector2d& peak) {
  return 0.04 * std::exp(-(uv - peak).squaredNorm() / 0.01);
}

inline Prediction synthetic_prediction(const Part& part, const Eigen::Vector2d& peak,
                                       const std::vector<Eigen::Vector2d>& sites, int cells_u = 50, int cells_v = 40) {
  Prediction p;
  p.part = "synthetic";
  p.toolpath = "synthetic.nc";
  p.tool = {"ball_d20", ToolType::ball, 20, 10};
  p.tolerance = 0.02;
  p.gouge_threshold = 0.04;
  p.zmap.resolution = 0.1;
  p.zmap.nx = 1000;
  p.zmap.ny = 800;
  FaceGridRecord f;
  f.name = part.faces[0].name();
  f.domain = part.faces[0].domain();
  f.cells_u = cells_u;
  f.cells_v = cells_v;
  for (int cj = 0; cj < cells_v; ++cj)
    for (int ci = 0; ci < cells_u; ++ci) {
      const Eigen::Vector2d uv(f.domain.u0 + (ci + 0.5) / cells_u * f.domain.width_u(),
                               f.domain.v0 + (cj + 0.5) / cells_v * f.domain.width_v());
      const double m = synthetic_mean(uv, peak);
      f.status.push_back(ci == 0 ? ErrorCellStatus::not_reached : ErrorCellStatus::reached);
      f.mean.push_back(ci == 0 ? 0 : m);
      f.max_undercut.push_back(ci == 0 ? 0 : m + 0.003);
      f.max_overcut.push_back(ci == 0 ? 0 : m - 0.002);
    }
  p.faces.push_back(f);
  for (std::size_t k = 0; k < sites.size(); ++k) {
    GougeSiteRecord s;
    s.id = static_cast<int>(k) + 1;
    s.face = f.name;
    s.depth = 0.05;
    s.deepest.face = f.name;
    s.deepest.uv = sites[k];
    s.deepest.xyz = part.faces[0].surface().point(sites[k].x(), sites[k].y());
    s.centroid = s.deepest;
    s.area = 2;
    s.samples = 8;
    s.uv_box = Eigen::AlignedBox2d(sites[k] - Eigen::Vector2d(0.01, 0.01), sites[k] + Eigen::Vector2d(0.01, 0.01));
    s.box.extend(s.deepest.xyz);
    p.gouge_sites.push_back(s);
  }
  p.summary.gouge_sites = sites.size();
  return p;
}

}  // namespace furrow::test
