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
// Nodes per piece of a row that the sweep bounds before evaluating it.
constexpr int kPiece = 16;
// [mm] a piece is skipped only when its bound exceeds every height by more.
constexpr double kBoundMargin = 1e-7;

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
    int lo, hi;    // rows of the move's shadow box
    int blo, bhi;  // its blocks of kPiece columns (the first holding column 0)
  };
  std::vector<RowRange> rows;
  rows.reserve(moves.size());
  for (const ZMapMove& m : moves) {
    moves_.push_back(m);
    envelopes_.emplace_back(cutter, m.from, m.to, options_.envelope);
    const Eigen::AlignedBox2d box = envelopes_.back().shadow_box();
    shadow_.extend(box);
    lowest_tip_ = std::min({lowest_tip_, m.from.z(), m.to.z()});
    const double lo = std::ceil((box.min().y() - y0_) / cell_), hi = std::floor((box.max().y() - y0_) / cell_);
    // One column more on each side than the box: a row's span, computed
    // apart, may round across a node the box's own rounding leaves out.
    const double il = std::ceil((box.min().x() - x0_) / cell_) - 1, ih = std::floor((box.max().x() - x0_) / cell_) + 1;
    rows.push_back({static_cast<int>(std::clamp(lo, 0.0, double(ny_))),
                    static_cast<int>(std::clamp(hi, -1.0, double(ny_ - 1))),
                    static_cast<int>(std::clamp(il, 0.0, double(nx_ - 1))) / kPiece,
                    static_cast<int>(std::clamp(ih, 0.0, double(nx_ - 1))) / kPiece});
  }
  const int band = std::max(1, options_.band_rows);
  const int bands = (ny_ + band - 1) / band;
  std::atomic<std::size_t> done{0};
#pragma omp parallel
  {
    std::vector<double> buffer(nx_);
    std::vector<double> piece_high;
    // Per block of kPiece columns, the highest node of the band's rows so
    // far (heights only fall, so a value computed earlier stays above), and
    // the blocks a move changed, whose value is then computed again.
    const int blocks = (nx_ + kPiece - 1) / kPiece;
    std::vector<double> block_high(static_cast<std::size_t>(blocks));
    std::vector<char> touched(static_cast<std::size_t>(blocks), 0);
    struct Visit {
      double distance;
      std::size_t move;
    };
    std::vector<Visit> order;
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < bands; ++b) {
      const int j0 = b * band, j1 = std::min(ny_, j0 + band) - 1;
      // The band's moves, nearest to its middle row first. A node keeps the
      // minimum over moves with the lowest index among equal heights, which
      // does not depend on the order; visiting the near moves first makes
      // the heights low early, so that far moves are mostly skipped by their
      // lower bounds below.
      const double ym = 0.5 * (y(j0) + y(j1));
      order.clear();
      for (std::size_t k = 0; k < moves.size(); ++k) {
        const RowRange& r = rows[k];
        if (r.hi < j0 || r.lo > j1) continue;
        const double ya = moves[k].from.y() - ym, yb = moves[k].to.y() - ym;
        order.push_back({(ya > 0) != (yb > 0) ? 0.0 : std::min(std::fabs(ya), std::fabs(yb)), k});
      }
      std::sort(order.begin(), order.end(), [](const Visit& a, const Visit& c) {
        return a.distance < c.distance || (a.distance == c.distance && a.move < c.move);
      });
      auto block_top = [&](int b) {
        double top = -kInf;
        const int ia = b * kPiece, ib = std::min(nx_, ia + kPiece);
        for (int j = j0; j <= j1; ++j) {
          const double* h = heights_.data() + index(0, j);
          for (int i = ia; i < ib; ++i) top = std::max(top, h[i]);
        }
        return top;
      };
      for (int b = 0; b < blocks; ++b) block_high[static_cast<std::size_t>(b)] = block_top(b);
      for (const Visit& v : order) {
        const std::size_t k = v.move;
        const RowRange& r = rows[k];
        const SweptEnvelope& env = envelopes_[first + k];
        const auto owner = static_cast<std::int32_t>(first + k);
        const int ja = std::max(j0, r.lo), jb = std::min(j1, r.hi);
        // The move leaves the band alone where its floor over these rows is
        // above every node under its shadow box (the margin covers rounding
        // in the bounds, a few ulps of the heights, far below it): the same
        // nodes the rows' and pieces' bounds below would leave.
        double band_high = -kInf;
        for (int b = r.blo; b <= r.bhi; ++b) band_high = std::max(band_high, block_high[static_cast<std::size_t>(b)]);
        if (env.strip_floor(y(ja), y(jb)) > band_high + kBoundMargin) continue;
        bool changed = false;
        for (int j = ja; j <= jb; ++j) {
          const double yj = y(j);
          double xl = 0, xh = 0;
          if (!env.row_span(yj, xl, xh)) continue;
          const int i0 = static_cast<int>(std::max(0.0, std::ceil((xl - x0_) / cell_)));
          const int i1 = static_cast<int>(std::min(double(nx_ - 1), std::floor((xh - x0_) / cell_)));
          if (i1 < i0) continue;
          const double xs = x(i0);
          double* h = heights_.data() + index(i0, j);
          std::int32_t* o = owners_.data() + index(i0, j);
          // The highest node of each piece, and of the row: a row whose
          // floor is above all of it is left at once (the same nodes the
          // pieces' bounds would leave, for one square root).
          const int pieces = (i1 - i0) / kPiece + 1;
          piece_high.resize(static_cast<std::size_t>(pieces));
          double row_high = -kInf;
          for (int p = 0; p < pieces; ++p) {
            const int c0 = p * kPiece, c1 = std::min(i1 - i0, c0 + kPiece - 1);
            double highest = -kInf;
            for (int i = c0; i <= c1; ++i) highest = std::max(highest, h[i]);
            piece_high[static_cast<std::size_t>(p)] = highest;
            row_high = std::max(row_high, highest);
          }
          // The margin covers rounding in the bounds (a few ulps of the
          // heights, far below it).
          if (env.strip_floor(yj, yj) > row_high + kBoundMargin) continue;
          for (int c0 = 0; c0 <= i1 - i0; c0 += kPiece) {
            const int c1 = std::min(i1 - i0, c0 + kPiece - 1);
            const double highest = piece_high[static_cast<std::size_t>(c0 / kPiece)];
            if (env.row_lower_bound(yj, xs, cell_, c0, c1) > highest + kBoundMargin) continue;
            env.row(yj, xs, cell_, c0, c1 - c0 + 1, buffer.data());
            bool lowered = false;
            for (int i = c0; i <= c1; ++i) {
              const double z = buffer[i - c0];
              if (z < h[i] || (z == h[i] && owner < o[i])) {
                lowered = lowered || z < h[i];
                h[i] = z;
                o[i] = owner;
              }
            }
            if (lowered) {
              for (int b = (i0 + c0) / kPiece; b <= (i0 + c1) / kPiece; ++b) touched[static_cast<std::size_t>(b)] = 1;
              changed = true;
            }
          }
        }
        if (changed)
          for (int b = r.blo; b <= r.bhi; ++b)
            if (touched[static_cast<std::size_t>(b)]) {
              touched[static_cast<std::size_t>(b)] = 0;
              block_high[static_cast<std::size_t>(b)] = block_top(b);
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

// Why a walk along the pass: the move that owns a node is the lowest there,
// but a move is lowest only over a strip about as long as itself. When moves
// are shorter than a cell (arcs cut into fine G1 chords: 4 um at 1e-7 mm sag
// on a 20 mm radius, against 0.1 mm nodes) the move lowest at (x, y) owns
// none of the four nodes around it, and the owners' envelopes evaluated
// there are higher by up to the path's slope times the gap (more on a flat
// end mill, whose lowest position jumps along the move), or miss (x, y)
// altogether: the error map then depended on how finely the path was cut,
// not on the path. The swept envelope of a pass is the minimum over its
// positions; starting from an owner, the walk follows the pass while the
// lowest position at (x, y) lies at the end of the current move (the lowest
// position is interior to a move only at a local minimum along the pass),
// and toward (x, y) while the move does not reach it. The result is the
// pass's local minimum nearest the owner's position, whatever the chord
// length (docs/architecture.md "Machining error between contact points").
double ZMap::lowest_along_pass(std::int32_t start, double x, double y, std::int32_t& lo, std::int32_t& hi) const {
  const auto count = static_cast<std::int32_t>(moves_.size());
  // Whether move b continues move a along the same pass.
  auto joined = [&](std::int32_t a, std::int32_t b) {
    return moves_[a].pass == moves_[b].pass && moves_[a].to == moves_[b].from;
  };
  auto neighbour = [&](std::int32_t m, int dir) -> std::int32_t {
    const std::int32_t n = m + dir;
    if (n < 0 || n >= count) return -1;
    return (dir > 0 ? joined(m, n) : joined(n, m)) ? n : -1;
  };
  // Horizontal distance from (x, y) to the move's projected segment: how
  // far the move is from reaching the point.
  auto distance = [&](std::int32_t m) {
    const Eigen::Vector2d a = moves_[m].from.head<2>(), d = moves_[m].to.head<2>() - a, p(x, y);
    const double len2 = d.squaredNorm();
    const double s = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (a + s * d - p).norm();
  };
  struct Probe {
    std::int32_t move;
    EnvelopePoint point;
    double distance;  // only when not reached
  };
  auto probe = [&](std::int32_t m) {
    Probe p{m, envelopes_[m].evaluate(x, y), 0};
    if (!std::isfinite(p.point.z)) p.distance = distance(m);
    return p;
  };
  auto better = [](const Probe& a, const Probe& b) {
    const bool ra = std::isfinite(a.point.z), rb = std::isfinite(b.point.z);
    if (ra != rb) return ra;
    return ra ? a.point.z < b.point.z : a.distance < b.distance;
  };
  // Directions in which the pass may go lower: toward the end of the move
  // where the lowest position sits, both ways while (x, y) is not reached.
  auto directions = [&](const Probe& p, int& first, int& second) {
    first = second = 0;
    if (!std::isfinite(p.point.z)) {
      first = -1, second = 1;
      return;
    }
    const double travel = (moves_[p.move].to - moves_[p.move].from).head<2>().norm();
    const double end = 4 * options_.envelope.along_tolerance;
    if (p.point.s * travel <= end) first = -1;
    if ((1 - p.point.s) * travel <= end) second = 1;
  };
  lo = hi = start;
  const Probe origin = probe(start);
  Probe best = origin;
  int first = 0, second = 0;
  directions(origin, first, second);
  for (int dir : {first, second}) {
    if (dir == 0) continue;
    Probe current = origin;
    for (std::int32_t n = neighbour(current.move, dir); n >= 0; n = neighbour(current.move, dir)) {
      const Probe next = probe(n);
      if (!better(next, current)) break;
      lo = std::min(lo, n), hi = std::max(hi, n);
      current = next;
      int back = 0, ahead = 0;
      directions(current, back, ahead);
      if ((dir < 0 ? back : ahead) == 0) break;  // the lowest position is inside this move
    }
    if (better(current, best)) best = current;
  }
  return best.point.z;
}

double ZMap::height_at(double x, double y) const {
  const int i = std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 2);
  const int j = std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 2);
  const std::int32_t candidates[4] = {owners_[index(i, j)], owners_[index(i + 1, j)], owners_[index(i, j + 1)],
                                      owners_[index(i + 1, j + 1)]};
  double best = kInf;
  // Moves a walk went down through: a walk from one of them would follow
  // the same descent to the same end, so it is not repeated.
  std::int32_t walked_lo[4], walked_hi[4];
  int walks = 0;
  for (int k = 0; k < 4; ++k) {
    const std::int32_t m = candidates[k];
    if (m < 0) continue;
    bool seen = false;
    for (int l = 0; l < walks; ++l) seen = seen || (m >= walked_lo[l] && m <= walked_hi[l]);
    if (seen) continue;
    best = std::min(best, lowest_along_pass(m, x, y, walked_lo[walks], walked_hi[walks]));
    ++walks;
  }
  return best;
}

bool ZMap::near_boundary(double x, double y) const {
  // Nodes within one cell of (x, y) in x and in y.
  const int i0 = std::max(0, static_cast<int>(std::ceil((x - cell_ - x0_) / cell_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((x + cell_ - x0_) / cell_)));
  const int j0 = std::max(0, static_cast<int>(std::ceil((y - cell_ - y0_) / cell_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((y + cell_ - y0_) / cell_)));
  if (i1 < i0 || j1 < j0) return true;  // off the grid: the z-map knows nothing there
  bool cut = false, uncut = false;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) (owners_[index(i, j)] < 0 ? uncut : cut) = true;
  return cut && uncut;
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
