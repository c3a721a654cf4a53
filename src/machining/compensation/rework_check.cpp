#include "machining/compensation/rework_check.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "machining/prediction/zmap.hpp"

namespace furrow {

namespace {

Eigen::AlignedBox2d tips_box(const Toolpath& path) {
  Eigen::AlignedBox2d box;
  for (const ToolpathPass& p : path.passes)
    for (const ToolpathPoint& q : p.points) box.extend(q.position.head<2>());
  return box;
}

}  // namespace

ReworkCheck check_rework(const Cutter& cutter, const Toolpath& original, const Toolpath& full, const Toolpath& rework,
                         double clearance, double tolerance) {
  ReworkCheck check;
  check.resolution = cutter.radius() / 15;
  check.tolerance = tolerance;
  const double margin = cutter.radius() + 2 * check.resolution;

  // 1. The rework against the full compensated program.
  Eigen::AlignedBox2d box = tips_box(rework);
  if (!box.isEmpty()) {
    box.min().array() -= margin;
    box.max().array() += margin;
    ZMap by_full(box, check.resolution), by_rework(box, check.resolution);
    by_full.cut(cutter, moves_from_toolpath(full));
    by_rework.cut(cutter, moves_from_toolpath(rework));
    for (int j = 0; j < by_rework.ny(); ++j)
      for (int i = 0; i < by_rework.nx(); ++i) {
        const double h = by_rework.node_height(i, j);
        if (!std::isfinite(h)) continue;
        ++check.nodes;
        const double h0 = by_full.node_height(i, j);
        const double excess = std::isfinite(h0) ? h0 - h - tolerance : std::numeric_limits<double>::infinity();
        if (excess <= 0) continue;
        ++check.deeper;
        if (excess > check.worst_excess) {
          check.worst_excess = excess;
          check.worst = Eigen::Vector3d(by_rework.x(i), by_rework.y(j), h);
        }
      }
  }

  // 2. The rework's rapids against the part as machined.
  std::vector<ZMapMove> rapids;
  Eigen::AlignedBox2d area = tips_box(original);
  std::vector<int> lines;
  for (const RapidMove& r : rework.rapids) {
    ++check.rapids;
    if (!r.known) {
      ++check.rapids_unchecked;
      continue;
    }
    ZMapMove m;
    m.from = r.from;
    m.to = r.to;
    m.pass = static_cast<int>(lines.size());
    m.step = 0;
    lines.push_back(r.line);
    rapids.push_back(m);
    area.extend(r.from.head<2>());
    area.extend(r.to.head<2>());
  }
  if (rapids.empty() || area.isEmpty()) return check;
  area.min().array() -= margin;
  area.max().array() += margin;
  ZMap machined(area, check.resolution), by_rapids(area, check.resolution);
  machined.cut(cutter, moves_from_toolpath(original));
  machined.cut(cutter, moves_from_toolpath(rework));
  by_rapids.cut(cutter, rapids);
  for (int j = 0; j < by_rapids.ny(); ++j)
    for (int i = 0; i < by_rapids.nx(); ++i) {
      const double h = by_rapids.node_height(i, j);
      if (!std::isfinite(h)) continue;
      const double h0 = machined.node_height(i, j);
      const double depth = (std::isfinite(h0) ? h0 : clearance) - h - tolerance;
      if (depth <= 0) continue;
      ++check.rapid_nodes_cut;
      if (depth > check.worst_rapid_depth) {
        check.worst_rapid_depth = depth;
        check.worst_rapid = Eigen::Vector3d(by_rapids.x(i), by_rapids.y(j), h);
        const std::int32_t owner = by_rapids.node_owner(i, j);
        check.worst_rapid_line = lines[static_cast<std::size_t>(rapids[static_cast<std::size_t>(owner)].pass)];
      }
    }
  return check;
}

}  // namespace furrow
