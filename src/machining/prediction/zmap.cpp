#include "machining/prediction/zmap.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

#include "base/error.hpp"

namespace furrow {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

std::vector<ZMapMove> moves_from_toolpath(const Toolpath& path) {
  std::vector<ZMapMove> moves;
  for (std::size_t p = 0; p < path.passes.size(); ++p) {
    const auto& points = path.passes[p].points;
    for (std::size_t k = 1; k < points.size(); ++k)
      moves.push_back({points[k - 1].position, points[k].position, static_cast<int>(p), static_cast<int>(k - 1)});
  }
  return moves;
}

double default_zmap_resolution(const Cutter& cutter, double tolerance) {
  const double r = cutter.corner_radius() > 0 ? cutter.corner_radius() : cutter.radius();
  const double e = std::min(tolerance, r);
  const double w = 2 * std::sqrt(std::max(2 * r * e - e * e, 0.0));
  const double target = w / 10;
  if (!(target > 0) || !std::isfinite(target)) return 0.05;
  // Nearest of 1, 2, 5 x 10^k on a log scale.
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  double best = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (std::fabs(std::log(m * decade / target)) < std::fabs(std::log(best / target))) best = m * decade;
  return best;
}

Eigen::AlignedBox2d part_xy_extent(const Part& part) {
  const Eigen::AlignedBox3d box = part.control_box();
  return Eigen::AlignedBox2d(box.min().head<2>(), box.max().head<2>());
}

ZMap::ZMap(const Eigen::AlignedBox2d& extent, double cell, const ZMapOptions& options) : options_(options) {
  if (!(cell > 0) || !std::isfinite(cell)) {
    std::ostringstream s;
    s << "z-map: the resolution must be a positive number of millimetres, got " << cell;
    throw InputError(s.str());
  }
  if (extent.isEmpty() || !extent.min().allFinite() || !extent.max().allFinite())
    throw InputError("z-map: the part has an empty or non-finite xy extent");
  const Eigen::Vector2d size = extent.sizes();
  const double cols = std::ceil(size.x() / cell) + 1, rows = std::ceil(size.y() / cell) + 1;
  if (cols * rows > double(options.max_nodes)) {
    std::ostringstream s;
    s << "z-map: resolution " << cell << " mm over " << size.x() << " x " << size.y() << " mm needs "
      << cols * rows << " nodes, more than the limit of " << options.max_nodes << " (use a coarser resolution)";
    throw InputError(s.str());
  }
  x0_ = extent.min().x();
  y0_ = extent.min().y();
  cell_ = cell;
  nx_ = std::max(2, static_cast<int>(cols));
  ny_ = std::max(2, static_cast<int>(rows));
  heights_.assign(static_cast<std::size_t>(nx_) * ny_, kInf);
  owners_.assign(heights_.size(), -1);
}

void ZMap::cut(const Cutter& cutter, const std::vector<ZMapMove>& moves,
               const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t first = moves_.size();
  if (first + moves.size() > std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw InputError("z-map: too many moves (more than 2^31)");
  struct RowRange {
    int lo, hi;
  };
  std::vector<RowRange> rows;
  rows.reserve(moves.size());
  for (const ZMapMove& m : moves) {
    moves_.push_back(m);
    envelopes_.emplace_back(cutter, m.from, m.to, options_.envelope);
    const Eigen::AlignedBox2d box = envelopes_.back().shadow_box();
    const double lo = std::ceil((box.min().y() - y0_) / cell_), hi = std::floor((box.max().y() - y0_) / cell_);
    rows.push_back({static_cast<int>(std::clamp(lo, 0.0, double(ny_))),
                    static_cast<int>(std::clamp(hi, -1.0, double(ny_ - 1)))});
  }
  const int band = std::max(1, options_.band_rows);
  const int bands = (ny_ + band - 1) / band;
  std::atomic<std::size_t> done{0};
#pragma omp parallel
  {
    std::vector<double> buffer(nx_);
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < bands; ++b) {
      const int j0 = b * band, j1 = std::min(ny_, j0 + band) - 1;
      for (std::size_t k = 0; k < moves.size(); ++k) {
        const RowRange& r = rows[k];
        if (r.hi < j0 || r.lo > j1) continue;
        const SweptEnvelope& env = envelopes_[first + k];
        const auto owner = static_cast<std::int32_t>(first + k);
        for (int j = std::max(j0, r.lo); j <= std::min(j1, r.hi); ++j) {
          const double yj = y(j);
          double xl = 0, xh = 0;
          if (!env.row_span(yj, xl, xh)) continue;
          const int i0 = static_cast<int>(std::max(0.0, std::ceil((xl - x0_) / cell_)));
          const int i1 = static_cast<int>(std::min(double(nx_ - 1), std::floor((xh - x0_) / cell_)));
          if (i1 < i0) continue;
          env.row(yj, x(i0), cell_, i1 - i0 + 1, buffer.data());
          double* h = heights_.data() + index(i0, j);
          std::int32_t* o = owners_.data() + index(i0, j);
          for (int i = 0; i <= i1 - i0; ++i) {
            if (buffer[i] < h[i]) {
              h[i] = buffer[i];
              o[i] = owner;
            }
          }
        }
      }
      const std::size_t d = ++done;
      if (progress && omp_get_thread_num() == 0) progress(d, bands);
    }
  }
  if (progress) progress(bands, bands);
}

std::size_t ZMap::cut_node_count() const {
  return static_cast<std::size_t>(std::count_if(owners_.begin(), owners_.end(), [](std::int32_t o) { return o >= 0; }));
}

double ZMap::height_at(double x, double y) const {
  const int i = std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 2);
  const int j = std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 2);
  const std::int32_t candidates[4] = {owners_[index(i, j)], owners_[index(i + 1, j)], owners_[index(i, j + 1)],
                                      owners_[index(i + 1, j + 1)]};
  double best = kInf;
  for (int k = 0; k < 4; ++k) {
    const std::int32_t m = candidates[k];
    if (m < 0) continue;
    bool seen = false;
    for (int l = 0; l < k; ++l) seen = seen || candidates[l] == m;
    if (!seen) best = std::min(best, envelopes_[m].height_at(x, y));
  }
  return best;
}

double ZMap::interpolated_height_at(double x, double y) const {
  const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
  if (!(fx >= 0 && fy >= 0 && fx <= nx_ - 1 && fy <= ny_ - 1)) return kInf;
  const int i = std::min(static_cast<int>(fx), nx_ - 2), j = std::min(static_cast<int>(fy), ny_ - 2);
  const double a = fx - i, b = fy - j;
  const double h00 = heights_[index(i, j)], h10 = heights_[index(i + 1, j)];
  const double h01 = heights_[index(i, j + 1)], h11 = heights_[index(i + 1, j + 1)];
  if (!std::isfinite(h00) || !std::isfinite(h10) || !std::isfinite(h01) || !std::isfinite(h11)) return kInf;
  return (1 - b) * ((1 - a) * h00 + a * h10) + b * ((1 - a) * h01 + a * h11);
}

}  // namespace furrow
