#pragma once
// Synthetic machining predictions whose error field, gouge sites and local
// gouges the test chooses: the known answers for the planner's risk weights,
// predicted-vs-measured and gouge confirmation. The prediction is the
// machining module's own data type (written and read by its prediction.json
// functions), so nothing here depends on how a real prediction is computed.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow::test {

using ErrorField = std::function<double(const Eigen::Vector2d& uv)>;

// The band of z-map samples around a cell's mean: [mean - below, mean + above].
struct ErrorBand {
  double below = 0.001, above = 0.001;
  ErrorBand(double symmetric = 0.001) : below(symmetric), above(symmetric) {}
  ErrorBand(double below_mean, double above_mean) : below(below_mean), above(above_mean) {}
};

// Face 0's cells get mean field(centre) and the band around it; cells whose
// centre fails `reached` are "not reached" (all zero).
inline Prediction field_prediction(const Part& part, const ErrorField& field, ErrorBand band = {},
                                   const std::function<bool(const Eigen::Vector2d&)>& reached = {},
                                   int cells_u = 100, int cells_v = 80) {
  Prediction p;
  p.part = "mould.json";
  p.toolpath = "synthetic.nc";
  p.tool = {"ball_d10", ToolType::ball, 10, 5};
  p.tolerance = 0.01;
  p.gouge_threshold = 0.01;
  p.zmap.resolution = 0.1;
  p.zmap.nx = 1001;
  p.zmap.ny = 801;
  FaceGridRecord f;
  f.name = part.faces[0].name();
  f.domain = part.faces[0].domain();
  f.cells_u = cells_u;
  f.cells_v = cells_v;
  for (int cj = 0; cj < cells_v; ++cj)
    for (int ci = 0; ci < cells_u; ++ci) {
      const Eigen::Vector2d uv(f.domain.u0 + (ci + 0.5) / cells_u * f.domain.width_u(),
                               f.domain.v0 + (cj + 0.5) / cells_v * f.domain.width_v());
      const bool in = !reached || reached(uv);
      const double m = in ? field(uv) : 0.0;
      f.status.push_back(in ? ErrorCellStatus::reached : ErrorCellStatus::not_reached);
      f.mean.push_back(m);
      f.max_undercut.push_back(in ? m + band.above : 0.0);
      f.max_overcut.push_back(in ? m - band.below : 0.0);
    }
  p.faces.push_back(f);
  return p;
}

// A z-map gouge site centred at `uv` with a uv box of +-half.
inline void add_zmap_site(Prediction& p, const Part& part, const Eigen::Vector2d& uv,
                          const Eigen::Vector2d& half, double depth) {
  GougeSiteRecord s;
  s.id = static_cast<int>(p.gouge_sites.size()) + 1;
  s.face = part.faces[0].name();
  s.depth = depth;
  s.deepest.face = s.face;
  s.deepest.uv = uv;
  s.deepest.xyz = part.faces[0].surface().point(uv.x(), uv.y());
  s.centroid = s.deepest;
  s.area = 4 * half.x() * half.y() * 8000;
  s.samples = 10;
  s.uv_box = Eigen::AlignedBox2d(uv - half, uv + half);
  s.box.extend(part.faces[0].surface().point(s.uv_box.min().x(), s.uv_box.min().y()));
  s.box.extend(part.faces[0].surface().point(s.uv_box.max().x(), s.uv_box.max().y()));
  p.gouge_sites.push_back(s);
  p.summary.gouge_sites = p.gouge_sites.size();
}

// A local-gouge contact point at `uv` (path pass 0, point = index).
inline void add_local_gouge(Prediction& p, const Part& part, const Eigen::Vector2d& uv) {
  LocalGougeRecord g;
  g.pass = 0;
  g.point = static_cast<int>(p.local_gouges.size());
  g.line = g.point + 1;
  g.at.face = part.faces[0].name();
  g.at.uv = uv;
  g.at.xyz = part.faces[0].surface().point(uv.x(), uv.y());
  g.status = "gouge";
  g.max_excess = 0.01;
  g.directions_deg.push_back({10, 20});
  p.local_gouges.push_back(g);
  p.summary.local_gouge_points = p.local_gouges.size();
}

}  // namespace furrow::test
