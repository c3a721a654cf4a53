#include "machining/compensation/zmap_check.hpp"

#include <stdexcept>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "machining/prediction/zmap.hpp"

namespace furrow {

CompensationGougeCheck check_compensation_zmap(const Cutter& cutter, const Toolpath& original,
                                               const Toolpath& written, const PathOffset& offset, double half_unit) {
  CompensationGougeCheck check;
  // Only where tips moved can the programs differ.
  Eigen::AlignedBox2d box;
  for (std::size_t p = 0; p < original.passes.size(); ++p)
    for (std::size_t k = 0; k < original.passes[p].points.size(); ++k)
      if (offset.tips[p][k] != original.passes[p].points[k].position) {
        box.extend(original.passes[p].points[k].position.head<2>());
        box.extend(offset.tips[p][k].head<2>());
      }
  if (box.isEmpty()) return check;
  // A fifteenth of the shank radius (0.2 mm for a 6 mm ball): a gouge
  // narrower than a cell can fall between nodes (a stated limit).
  check.resolution = cutter.radius() / 15;
  check.tolerance = 1e-3 + std::sqrt(3.0) * half_unit;
  const double margin = cutter.radius() + 2 * check.resolution;
  box.min().array() -= margin;
  box.max().array() += margin;
  ZMap before(box, check.resolution), after(box, check.resolution);
  before.cut(cutter, moves_from_toolpath(original));
  const std::vector<ZMapMove> moves = moves_from_toolpath(written);
  after.cut(cutter, moves);
  // The offset of each written move: per move when the written program has
  // the original's points (arcs are split through the same points), else
  // the largest anywhere.
  bool same_points = written.passes.size() == original.passes.size();
  for (std::size_t p = 0; same_points && p < original.passes.size(); ++p)
    same_points = written.passes[p].points.size() == original.passes[p].points.size();
  const double c = check.resolution;
  for (int j = 0; j < after.ny(); ++j)
    for (int i = 0; i < after.nx(); ++i) {
      const double h = after.node_height(i, j), h0 = before.node_height(i, j);
      if (!std::isfinite(h) || !std::isfinite(h0)) continue;
      ++check.nodes;
      if (h >= h0) continue;
      double d = offset.largest_offset;
      const std::int32_t owner = after.node_owner(i, j);
      const ZMapMove& move = moves[static_cast<std::size_t>(owner)];
      const auto pass = static_cast<std::size_t>(move.pass), step = static_cast<std::size_t>(move.step);
      if (same_points)
        d = std::max(std::abs(offset.offsets[pass][step]), std::abs(offset.offsets[pass][step + 1]));
      // The original machined surface's slope at the node. At the rim of
      // the swept region (a neighbour uncut) and where it is steeper than
      // n_z = 0.2 (a ball's side, where a lateral move of a micrometre
      // changes the height a lot) a z-map cannot tell: not judged.
      if (i == 0 || j == 0 || i + 1 == after.nx() || j + 1 == after.ny()) {
        ++check.not_judged;
        continue;
      }
      const double xm = before.node_height(i - 1, j), xp = before.node_height(i + 1, j);
      const double ym = before.node_height(i, j - 1), yp = before.node_height(i, j + 1);
      if (!std::isfinite(xm) || !std::isfinite(xp) || !std::isfinite(ym) || !std::isfinite(yp)) {
        ++check.not_judged;
        continue;
      }
      const double sx = (xp - xm) / (2 * c), sy = (yp - ym) / (2 * c);
      const double nz = 1 / std::sqrt(1 + sx * sx + sy * sy);
      if (nz < 0.2) {
        ++check.not_judged;
        continue;
      }
      const double excess = (h0 - h) - (d / nz + check.tolerance);
      if (excess <= 0) continue;
      ++check.deeper;
      if (same_points) check.blamed.emplace_back(pass, step);
      if (excess > check.worst_excess) {
        check.worst_excess = excess;
        check.worst = Eigen::Vector3d(after.x(i), after.y(j), h);
        check.worst_line = written.passes[pass].points[step + 1].line;
      }
    }
  std::sort(check.blamed.begin(), check.blamed.end());
  check.blamed.erase(std::unique(check.blamed.begin(), check.blamed.end()), check.blamed.end());
  return check;
}

CompensationGougeCheck check_compensation_zmap(const PathTools& tools, const Toolpath& original,
                                               const Toolpath& written, const PathOffset& offset, double half_unit) {
  if (tools.cutters.size() == 1) return check_compensation_zmap(tools.cutters[0], original, written, offset, half_unit);
  if (written.passes.size() != original.passes.size() || tools.of_pass.size() < original.passes.size())
    throw std::logic_error("check_compensation_zmap: the written program lost the original's passes");
  CompensationGougeCheck all;
  for (std::size_t c = 0; c < tools.cutters.size(); ++c) {
    std::vector<std::size_t> passes;
    Toolpath before, after;
    before.kind = original.kind;
    after.kind = written.kind;
    PathOffset sub;
    sub.largest_offset = offset.largest_offset;
    for (std::size_t p = 0; p < original.passes.size(); ++p) {
      if (static_cast<std::size_t>(tools.of_pass[p]) != c) continue;
      passes.push_back(p);
      before.passes.push_back(original.passes[p]);
      after.passes.push_back(written.passes[p]);
      sub.tips.push_back(offset.tips[p]);
      sub.offsets.push_back(offset.offsets[p]);
      sub.tilts.push_back(offset.tilts[p]);
    }
    if (passes.empty()) continue;
    const CompensationGougeCheck one = check_compensation_zmap(tools.cutters[c], before, after, sub, half_unit);
    if (one.resolution > 0) all.resolution = all.resolution > 0 ? std::min(all.resolution, one.resolution) : one.resolution;
    all.tolerance = std::max(all.tolerance, one.tolerance);
    all.nodes += one.nodes;
    all.not_judged += one.not_judged;
    all.deeper += one.deeper;
    if (one.worst_excess > all.worst_excess) {
      all.worst_excess = one.worst_excess;
      all.worst = one.worst;
      all.worst_line = one.worst_line;
    }
    for (const auto& [pass, step] : one.blamed) all.blamed.emplace_back(passes[pass], step);
  }
  std::sort(all.blamed.begin(), all.blamed.end());
  return all;
}

}  // namespace furrow
