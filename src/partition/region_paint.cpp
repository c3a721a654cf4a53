#include "partition/region_paint.hpp"

#include <algorithm>

#include "partition/region_labels.hpp"

namespace furrow {

namespace {

const Rgb kOutside{215, 215, 215};
const Rgb kDegenerate{110, 110, 110};

Rgb class_colour(CurvatureClass c) { return curvature_class_colour(to_string(c)); }

}  // namespace

SurfacePainter region_map_painter(const RegionMap& map) {
  return [&map](std::size_t face, const Eigen::Vector2d& uv) {
    const std::optional<int> id = map.region_at(static_cast<int>(face), uv.x(), uv.y());
    if (!id) return SurfacePaint{kOutside, -1};
    return SurfacePaint{class_colour(map.regions[static_cast<std::size_t>(*id)].curvature_class), *id};
  };
}

SurfacePainter partition_cells_painter(const PartitionResult& result) {
  return [&result](std::size_t face, const Eigen::Vector2d& uv) {
    const RegionFace& info = result.map.faces[face];
    const FaceCells& cells = result.cells[face];
    const ParameterDomain& d = info.domain;
    const int nu = cells.labels.nu, nv = cells.labels.nv;
    const int i = std::clamp(static_cast<int>((uv.x() - d.u0) / d.width_u() * nu), 0, nu - 1);
    const int j = std::clamp(static_cast<int>((uv.y() - d.v0) / d.width_v() * nv), 0, nv - 1);
    const int label = cells.labels.at(i, j);
    if (label >= 0) {
      const int id = cells.first_id + label;
      return SurfacePaint{class_colour(result.map.regions[static_cast<std::size_t>(id)].curvature_class), id};
    }
    const bool degenerate = cells.cell_class[static_cast<std::size_t>(i) * nv + j] == kDegenerateCell;
    return SurfacePaint{degenerate ? kDegenerate : kOutside, -1};
  };
}

std::vector<LegendEntry> class_legend(const RegionMap& map) {
  bool present[kCurvatureClassCount] = {false, false, false, false};
  for (const Region& r : map.regions) present[static_cast<int>(r.curvature_class)] = true;
  std::vector<LegendEntry> out;
  for (int k = 0; k < kCurvatureClassCount; ++k)
    if (present[k]) out.push_back({class_colour(static_cast<CurvatureClass>(k)), to_string(static_cast<CurvatureClass>(k))});
  out.push_back({kOutside, "outside every region"});
  return out;
}

std::vector<ViewLabel> region_labels(const RegionMap& map) {
  std::vector<ViewLabel> out;
  for (const Region& r : map.regions) out.push_back({r.interior_xyz, "R" + std::to_string(r.id), r.id, 200});
  return out;
}

}  // namespace furrow
