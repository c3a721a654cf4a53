#include "machining/compensation/rework_selection.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "base/error.hpp"
#include "machining/prediction/path_contacts.hpp"

namespace furrow {

namespace {

// Union-find over stretches, smallest index as the root (deterministic).
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

ReworkSelection select_rework(const Part& part, const Cutter& cutter, const Toolpath& original,
                              const PathOffset& offset, const ErrorField& field, const ReworkOptions& options) {
  if (!(options.threshold >= 0) || !std::isfinite(options.threshold))
    throw InputError("rework: the threshold must be a length >= 0 in mm");
  ReworkSelection out;
  bool any_rapid = false;
  for (const RapidMove& r : original.rapids)
    if (r.known) {
      const double z = std::max(r.from.z(), r.to.z());
      out.clearance = any_rapid ? std::max(out.clearance, z) : z;
      any_rapid = true;
    }
  if (!any_rapid)
    throw InputError(original.source + ": rework needs a clearance height, the highest rapid of the program, and "
                                       "it has no rapid in the part frame");
  out.step = options.step > 0 ? options.step : cutter.radius() / 4;

  // The division points of every move, on the original path (to locate them)
  // and on the compensated one (fraction t of the compensated move).
  Toolpath dense;
  dense.kind = original.kind;
  dense.source = original.source;
  struct Piece {
    std::size_t move = 0;  // index of the original move in its pass (ends at point move + 1)
    double t = 0;          // fraction along it of the division point
  };
  std::vector<std::vector<Piece>> where(original.passes.size());
  for (std::size_t p = 0; p < original.passes.size(); ++p) {
    const auto& points = original.passes[p].points;
    ToolpathPass pass;
    pass.tool = original.passes[p].tool;
    ToolpathPoint first = points.front();
    pass.points.push_back(first);
    where[p].push_back({0, 0});
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      ++out.moves;
      const Eigen::Vector3d a = points[k].position, b = points[k + 1].position;
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / out.step)));
      for (int i = 1; i <= n; ++i) {
        ToolpathPoint q = points[k + 1];
        const double t = static_cast<double>(i) / n;
        q.position = a + t * (b - a);
        pass.points.push_back(q);
        where[p].push_back({k, t});
      }
    }
    dense.passes.push_back(std::move(pass));
  }
  const PathGeometry located = locate_path(part, cutter, dense);

  std::vector<std::size_t> parent;
  for (std::size_t p = 0; p < dense.passes.size(); ++p) {
    const auto& points = original.passes[p].points;
    const auto& geo = located.passes[p];
    std::vector<double> e(geo.size(), 0.0);
    for (std::size_t i = 0; i < geo.size(); ++i) {
      const PathContact& c = geo[i].contact;
      if (!c.valid || geo[i].in_air) continue;
      e[i] = field.value(static_cast<std::size_t>(c.at.face), c.at.uv.x(), c.at.uv.y());
      out.largest_field = std::max(out.largest_field, e[i]);
    }
    // The compensated tip at division point i.
    auto tip = [&](std::size_t i) -> Eigen::Vector3d {
      const Piece& w = where[p][i];
      if (i == 0) return offset.tips[p][0];
      const Eigen::Vector3d& a = offset.tips[p][w.move];
      const Eigen::Vector3d& b = offset.tips[p][w.move + 1];
      return w.t == 1 ? b : Eigen::Vector3d(a + w.t * (b - a));
    };
    ReworkStretch open;
    std::size_t last_move = static_cast<std::size_t>(-1);
    auto close = [&] {
      if (open.tips.size() >= 2) out.stretches.push_back(std::move(open));
      open = {};
    };
    for (std::size_t i = 1; i < geo.size(); ++i) {
      ++out.pieces;
      const bool keep = e[i - 1] > options.threshold || e[i] > options.threshold;
      if (!keep) {
        close();
        continue;
      }
      ++out.pieces_kept;
      const std::size_t move = where[p][i].move;
      if (move != last_move) ++out.moves_kept, last_move = move;
      const ToolpathPoint& end = points[move + 1];
      if (open.tips.empty()) {
        open.tips.push_back(tip(i - 1));
        open.feeds.push_back(end.feed);
        open.first_line = end.line;
      }
      open.tips.push_back(tip(i));
      open.feeds.push_back(end.feed);
      open.last_line = end.line;
    }
    close();
  }

  // Regions: stretches whose grown xy boxes overlap.
  const std::size_t n = out.stretches.size();
  std::vector<Eigen::AlignedBox2d> boxes(n);
  for (std::size_t s = 0; s < n; ++s) {
    for (const Eigen::Vector3d& t : out.stretches[s].tips) boxes[s].extend(t.head<2>());
  }
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const double r = cutter.radius();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      Eigen::AlignedBox2d ga = boxes[a], gb = boxes[b];
      ga.min().array() -= r, ga.max().array() += r;
      gb.min().array() -= r, gb.max().array() += r;
      if (!ga.intersects(gb)) continue;
      const std::size_t ra = root(parent, a), rb = root(parent, b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  std::vector<std::size_t> index_of(n, static_cast<std::size_t>(-1));
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t g = root(parent, s);
    if (index_of[g] == static_cast<std::size_t>(-1)) {
      index_of[g] = out.regions.size();
      out.regions.emplace_back();
    }
    ReworkRegion& region = out.regions[index_of[g]];
    region.box.extend(boxes[s]);
    region.stretches.push_back(s);
  }
  return out;
}

}  // namespace furrow
