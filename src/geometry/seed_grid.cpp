#include "geometry/seed_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

constexpr int kSub = 8;  // sub-samples per cell and direction: (kSub + 1)^2 points

// Clips segment a-b to the box [lo, hi] (Liang-Barsky); false when it misses.
bool clip_segment(Eigen::Vector2d& a, Eigen::Vector2d& b, const Eigen::Vector2d& lo,
                  const Eigen::Vector2d& hi) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = b - a;
  for (int k = 0; k < 2; ++k) {
    const double p[2] = {-d(k), d(k)};
    const double q[2] = {a(k) - lo(k), hi(k) - a(k)};
    for (int s = 0; s < 2; ++s) {
      if (p[s] == 0) {
        if (q[s] < 0) return false;
        continue;
      }
      const double t = q[s] / p[s];
      if (p[s] < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Eigen::Vector2d a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

// Axis-aligned box of a cell's oriented box.
Eigen::AlignedBox3d cell_box(const CellBounds& c) {
  const Eigen::Vector3d reach = c.axes.transpose().cwiseAbs() * c.half_extent;
  return Eigen::AlignedBox3d(c.centre - reach, c.centre + reach);
}

// Orthonormal rows (tangent along Su, second tangent, normal) at a point;
// any frame where the tangents degenerate (the box is then just less tight).
Eigen::Matrix3d tangent_frame(const SurfaceDerivatives& d) {
  Eigen::Vector3d n = d.Su.cross(d.Sv);
  Eigen::Vector3d t1 = d.Su;
  if (!(n.norm() > 1e-300) || !(t1.norm() > 1e-300)) return Eigen::Matrix3d::Identity();
  n.normalize();
  t1.normalize();
  Eigen::Matrix3d axes;
  axes.row(0) = t1;
  axes.row(1) = n.cross(t1);
  axes.row(2) = n;
  return axes;
}

}  // namespace

namespace {

// The cone test of CellBounds::may_hold_foot on q in the box's frame.
bool in_cone_reach(const Eigen::Vector3d& local, const Eigen::Vector3d& half_extent, double cone_tan) {
  if (!(cone_tan >= 0)) return true;
  // A foot p in the box has q - p within the cone's angle alpha of +-axis
  // (the box's third axis), so q's sideways distance from the box is at
  // most tan(alpha) times the largest height of q over a point of the box.
  const double dx = std::max(std::abs(local.x()) - half_extent.x(), 0.0);
  const double dy = std::max(std::abs(local.y()) - half_extent.y(), 0.0);
  const double height = std::abs(local.z()) + half_extent.z();
  const double reach = cone_tan * height * (1 + 1e-12) + 1e-12 * (1 + height);
  return dx * dx + dy * dy <= reach * reach;  // squared: no root on the search's path
}

}  // namespace

bool CellBounds::may_hold_foot(const Eigen::Vector3d& q) const {
  return in_cone_reach(axes * (q - centre), half_extent, cone_tan);
}

bool CellBounds::may_hold_foot_near(const Eigen::Vector3d& c, double radius) const {
  // Growing the box by `radius` lowers q's sideways distance and raises its
  // height by at least as much as moving q by `radius` could.
  return in_cone_reach(axes * (c - centre), half_extent.array() + radius, cone_tan);
}

double CellBounds::squared_screen(const Eigen::Vector3d& q) const {
  const Eigen::Vector3d local = axes * (q - centre);
  if (!in_cone_reach(local, half_extent, cone_tan)) return std::numeric_limits<double>::infinity();
  return (local.cwiseAbs() - half_extent).cwiseMax(0.0).squaredNorm();
}

std::vector<double> seed_breaks(const std::vector<double>& knots, double lo, double hi,
                                const ClosestPointOptions& options) {
  std::vector<double> distinct{lo};
  for (double k : knots)
    if (k > distinct.back() && k < hi) distinct.push_back(k);
  distinct.push_back(hi);
  const int spans = static_cast<int>(distinct.size()) - 1;
  std::vector<double> breaks;
  if (spans * options.cells_per_span > options.max_cells) {
    for (int k = 0; k <= options.max_cells; ++k)
      breaks.push_back(lo + (hi - lo) * k / options.max_cells);
    breaks.back() = hi;
    return breaks;
  }
  int per_span = std::max(options.cells_per_span, (options.min_cells + spans - 1) / spans);
  per_span = std::max(options.cells_per_span, std::min(per_span, options.max_cells / spans));
  for (int s = 0; s < spans; ++s)
    for (int k = 0; k < per_span; ++k)
      breaks.push_back(distinct[s] + (distinct[s + 1] - distinct[s]) * k / per_span);
  breaks.push_back(hi);
  return breaks;
}

SeedGrid::SeedGrid(const Part& part, const ClosestPointOptions& options) {
  for (std::size_t f = 0; f < part.faces.size(); ++f) add_face(part, f, options);
  if (cells_.empty())
    throw InputError("closest point: the part has no surface left after trimming");
  std::vector<std::uint32_t> order(cells_.size());
  std::iota(order.begin(), order.end(), 0u);
  nodes_.reserve(2 * cells_.size());
  build_tree(order, 0, static_cast<std::uint32_t>(order.size()));
  // Store cells in tree order so that a leaf's cells are contiguous.
  std::vector<SeedCell> sorted(cells_.size());
  std::vector<CellBounds> sorted_bounds(cells_.size());
  std::vector<std::int32_t> new_index(cells_.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted[k] = cells_[order[k]];
    sorted_bounds[k] = bounds_[order[k]];
    new_index[order[k]] = static_cast<std::int32_t>(k);
  }
  cells_ = std::move(sorted);
  bounds_ = std::move(sorted_bounds);
  for (FaceCells& fc : faces_)
    for (std::int32_t& i : fc.index)
      if (i >= 0) i = new_index[i];
  patches_.reserve(cells_.size());
  for (const SeedCell& cell : cells_)
    patches_.push_back(BezierPatch::within_span(part.faces[cell.face].surface(), cell.lo, cell.hi));
}

void SeedGrid::add_face(const Part& part, std::size_t face_index,
                        const ClosestPointOptions& options) {
  const Face& face = part.faces[face_index];
  const NurbsSurface& s = face.surface();
  const ParameterDomain& dom = face.domain();
  FaceCells fc;
  fc.breaks_u = seed_breaks(s.knots_u(), dom.u0, dom.u1, options);
  fc.breaks_v = seed_breaks(s.knots_v(), dom.v0, dom.v1, options);
  const int nu = static_cast<int>(fc.breaks_u.size()) - 1;
  const int nv = static_cast<int>(fc.breaks_v.size()) - 1;
  fc.index.assign(static_cast<std::size_t>(nu) * nv, -1);
  const Trim& trim = face.trim();

  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      SeedCell cell;
      CellBounds bounds;
      cell.face = static_cast<std::uint32_t>(face_index);
      cell.lo = {fc.breaks_u[i], fc.breaks_v[j]};
      cell.hi = {fc.breaks_u[i + 1], fc.breaks_v[j + 1]};
      const Eigen::Vector2d mid = 0.5 * (cell.lo + cell.hi);
      if (!trim.empty()) {
        const double half_diagonal = 0.5 * (cell.hi - cell.lo).norm();
        bool cut = trim.distance_to_boundary(mid) <= half_diagonal;
        if (cut) {
          cell.first_segment = static_cast<std::uint32_t>(segments_.size());
          for (const UvLoop& loop : trim.loops())
            for (std::size_t k = 0; k < loop.size(); ++k) {
              Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
              if (clip_segment(a, b, cell.lo, cell.hi)) segments_.push_back({a, b, Eigen::Vector3d::Zero(), 0});
            }
          cell.segment_count = static_cast<std::uint32_t>(segments_.size()) - cell.first_segment;
          cut = cell.segment_count > 0;
        }
        if (!cut && !trim.contains(mid)) continue;  // wholly trimmed away
        cell.cut_by_trim = cut;
      }

      // Sub-samples: the oriented box and the five seed samples.
      Eigen::Vector3d pts[kSub + 1][kSub + 1], normals[kSub + 1][kSub + 1];
      double max_uu = 0, max_uv = 0, max_vv = 0;
      double max_nu = 0, max_nv = 0;  // bounds on |dn/du|, |dn/dv|
      bool regular = true;
      Eigen::AlignedBox3d box;
      const Eigen::Vector2d h = (cell.hi - cell.lo) / kSub;
      // The cell's Bezier form, where it has one, evaluates the sub-samples
      // without knot searches (bezier_patch.hpp).
      const std::optional<BezierPatch> piece = BezierPatch::within_span(s, cell.lo, cell.hi);
      auto sub_sample = [&](int a, int b) {  // the far sides exactly at hi
        return Eigen::Vector2d(a == kSub ? cell.hi.x() : cell.lo.x() + a * h.x(),
                               b == kSub ? cell.hi.y() : cell.lo.y() + b * h.y());
      };
      for (int a = 0; a <= kSub; ++a)
        for (int b = 0; b <= kSub; ++b) {
          const Eigen::Vector2d uv = sub_sample(a, b);
          const SurfaceDerivatives d = piece ? piece->evaluate(uv.x(), uv.y(), 2) : s.evaluate(uv.x(), uv.y(), 2);
          pts[a][b] = d.S;
          box.extend(d.S);
          max_uu = std::max(max_uu, d.Suu.squaredNorm());  // squared here, rooted below
          max_uv = std::max(max_uv, d.Suv.squaredNorm());
          max_vv = std::max(max_vv, d.Svv.squaredNorm());
          const Eigen::Vector3d n = d.Su.cross(d.Sv);
          const double area = n.norm();
          regular = regular && area > kDegenerateRelativeTolerance * d.Su.norm() * d.Sv.norm();
          normals[a][b] = regular ? Eigen::Vector3d(n / area) : Eigen::Vector3d::Zero();
          if (regular) {
            max_nu = std::max(max_nu, (d.Suu.cross(d.Sv).norm() + d.Su.cross(d.Suv).norm()) / area);
            max_nv = std::max(max_nv, (d.Suv.cross(d.Sv).norm() + d.Su.cross(d.Svv).norm()) / area);
          }
        }
      max_uu = std::sqrt(max_uu);
      max_uv = std::sqrt(max_uv);
      max_vv = std::sqrt(max_vv);
      bounds.centre = box.center();
      const SurfaceDerivatives middle = s.evaluate(mid.x(), mid.y(), 1);
      cell.middle_su = middle.Su;
      cell.middle_sv = middle.Sv;
      bounds.axes = tangent_frame(middle);
      Eigen::Vector3d extent = Eigen::Vector3d::Zero();
      for (auto& row : pts)
        for (auto& p : row) extent = extent.cwiseMax((bounds.axes * (p - bounds.centre)).cwiseAbs());
      const double bulge =
          2.0 * (h.x() * h.x() * max_uu + 2 * h.x() * h.y() * max_uv + h.y() * h.y() * max_vv) / 8;
      const double slack = bulge + 1e-12 * (1 + bounds.centre.norm());
      for (std::uint32_t k = 0; k < cell.segment_count; ++k) {
        TrimSegment& seg = segments_[cell.first_segment + k];
        const Eigen::Vector3d pa = s.point(seg.a.x(), seg.a.y()), pb = s.point(seg.b.x(), seg.b.y());
        const Eigen::Vector2d d = (seg.b - seg.a).cwiseAbs();
        const double bow = 2.0 * (d.x() * d.x() * max_uu + 2 * d.x() * d.y() * max_uv + d.y() * d.y() * max_vv) / 8;
        seg.centre = 0.5 * (pa + pb);
        seg.radius = 0.5 * (pb - pa).norm() + bow + 1e-12 * (1 + seg.centre.norm());
      }
      bounds.half_extent = extent.array() + slack;
      const bool on_domain_edge = i == 0 || j == 0 || i == nu - 1 || j == nv - 1;
      if (regular && !on_domain_edge && !cell.cut_by_trim) {
        // The box's third axis is the middle normal: the cone's axis.
        const Eigen::Vector3d axis = bounds.axes.row(2).transpose();
        double narrowest_cosine = 1;
        for (auto& row : normals)
          for (auto& n : row) narrowest_cosine = std::min(narrowest_cosine, n.dot(axis));
        const double widest = std::acos(std::clamp(narrowest_cosine, -1.0, 1.0));
        // Every point of the cell is within half a sub-step in u and in v
        // of a sub-sample: its normal turns from that sample's by at most
        // (hu / 2) sup |dn/du| + (hv / 2) sup |dn/dv|, the sups taken as
        // twice the sampled maxima.
        const double angle = widest + h.x() * max_nu + h.y() * max_nv;
        if (std::isfinite(angle) && angle < radians(80.0)) bounds.cone_tan = std::tan(angle);
      }
      const int corner[5][2] = {{0, 0}, {kSub, 0}, {0, kSub}, {kSub, kSub}, {kSub / 2, kSub / 2}};
      cell.sample_kept = 0;
      for (int k = 0; k < 5; ++k) {
        cell.sample_uv[k] = sub_sample(corner[k][0], corner[k][1]);
        cell.sample_point[k] = pts[corner[k][0]][corner[k][1]];
        if (!cell.cut_by_trim || trim.contains(cell.sample_uv[k])) cell.sample_kept |= 1u << k;
      }
      for (int k : {4, 0, 1, 2, 3})  // the middle first: nearest to most of the cell
        if (cell.sample_kept >> k & 1u) {
          bounds.surface_point = cell.sample_point[k];
          break;
        }
      fc.index[static_cast<std::size_t>(i) * nv + j] = static_cast<std::int32_t>(cells_.size());
      cells_.push_back(cell);
      bounds_.push_back(bounds);
    }
  }
  faces_.push_back(std::move(fc));
}

std::int32_t SeedGrid::build_tree(std::vector<std::uint32_t>& order, std::uint32_t first,
                                  std::uint32_t count) {
  const auto node = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  const auto begin = order.begin() + first, end = begin + count;
  if (count <= 4) {
    SeedNode leaf;
    leaf.first = first;
    leaf.count = count;
    for (auto it = begin; it != end; ++it) leaf.box.extend(cell_box(bounds_[*it]));
    nodes_[node] = leaf;
    return node;
  }
  Eigen::AlignedBox3d box;
  for (auto it = begin; it != end; ++it) box.extend(bounds_[*it].centre);
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const auto middle = begin + count / 2;
  std::nth_element(begin, middle, end, [&](std::uint32_t a, std::uint32_t b) {
    return bounds_[a].centre(axis) < bounds_[b].centre(axis);
  });
  const std::int32_t left = build_tree(order, first, count / 2);
  const std::int32_t right = build_tree(order, first + count / 2, count - count / 2);
  SeedNode inner;
  inner.left = left;
  inner.right = right;
  inner.box = nodes_[left].box.merged(nodes_[right].box);
  nodes_[node] = inner;
  return node;
}

int SeedGrid::cell_at(std::size_t face, const Eigen::Vector2d& uv) const {
  if (face >= faces_.size()) return -1;
  const FaceCells& fc = faces_[face];
  auto locate = [](const std::vector<double>& breaks, double t) {
    const auto it = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, t);
    return static_cast<int>(it - breaks.begin()) - 1;
  };
  const int i = locate(fc.breaks_u, uv.x());
  const int j = locate(fc.breaks_v, uv.y());
  const int nv = static_cast<int>(fc.breaks_v.size()) - 1;
  return fc.index[static_cast<std::size_t>(i) * nv + j];
}

}  // namespace furrow
