#include "machining/prediction/rapid_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/error.hpp"
#include "base/scalar_search.hpp"
#include "machining/cutter/vertical_projection.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/uv_refine.hpp"
#include "machining/prediction/swept_envelope.hpp"

namespace furrow {

const char* to_string(RapidGougeKind kind) { return kind == RapidGougeKind::part ? "part" : "stock"; }

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A face's samples: cell centres of an nu x nv grid over its parameter
// rectangle, grouped in blocks with the bounding box of their points.
struct FaceSamples {
  std::size_t face = 0;
  ParameterDomain domain;
  int nu = 0, nv = 0;
  double u(double i) const { return domain.u0 + (i + 0.5) * domain.width_u() / nu; }
  double v(double j) const { return domain.v0 + (j + 0.5) * domain.width_v() / nv; }
  struct Block {
    int i0, i1, j0, j1;  // sample range [i0, i1) x [j0, j1)
    Eigen::AlignedBox3d box;
  };
  std::vector<Block> blocks;
};

std::vector<FaceSamples> sample_faces(const Part& part, const RapidCheckOptions& options) {
  std::vector<FaceSamples> out;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    FaceSamples s;
    s.face = f;
    s.domain = face.domain();
    const Eigen::Vector2d len = face_extent_lengths(face);
    s.nu = std::max(2, static_cast<int>(std::ceil(len.x() / options.sample_spacing)));
    s.nv = std::max(2, static_cast<int>(std::ceil(len.y() / options.sample_spacing)));
    const double count = double(s.nu) * s.nv;
    if (count > double(options.max_samples)) {
      std::ostringstream m;
      m << "rapid check: face \"" << face.name() << "\" would need " << count << " samples at "
        << options.sample_spacing << " mm, more than the limit of " << options.max_samples
        << " (use a coarser resolution)";
      throw InputError(m.str());
    }
    const int b = options.block;
    for (int j0 = 0; j0 < s.nv; j0 += b)
      for (int i0 = 0; i0 < s.nu; i0 += b)
        s.blocks.push_back({i0, std::min(i0 + b, s.nu), j0, std::min(j0 + b, s.nv), Eigen::AlignedBox3d()});
#pragma omp parallel for schedule(dynamic, 4)
    for (int k = 0; k < static_cast<int>(s.blocks.size()); ++k) {
      FaceSamples::Block& block = s.blocks[static_cast<std::size_t>(k)];
      for (int j = block.j0; j < block.j1; ++j)
        for (int i = block.i0; i < block.i1; ++i) {
          Eigen::Vector3d p, n;
          if (!face.contains(s.u(i), s.v(j)) || !face_normal(face, s.u(i), s.v(j), p, n) || !(n.z() >= 0)) continue;
          block.box.extend(p);
        }
      // The surface between samples (and the refinement around them) may
      // reach a little beyond the samples themselves.
      if (!block.box.isEmpty()) {
        const double pad = 2 * options.sample_spacing;
        block.box.min().array() -= pad;
        block.box.max().array() += pad;
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

// Overcut depth of the swept envelope at a surface point (along its normal);
// 0 where the envelope does not reach below it, -inf where the point is not
// checkable (trimmed away, degenerate or facing down).
double depth_at(const Face& face, const SweptEnvelope& env, const Eigen::Vector2d& uv,
                const NormalErrorOptions& options) {
  if (!face.contains(uv.x(), uv.y())) return -kInf;
  Eigen::Vector3d p, n;
  if (!face_normal(face, uv.x(), uv.y(), p, n) || !(n.z() >= 0)) return -kInf;
  const double h = env.height_at(p.x(), p.y());
  if (!(h < p.z())) return 0;
  const NormalError e =
      normal_error([&env](double x, double y) { return env.height_at(x, y); }, p, n,
                   with_height_bounds(options, std::min(env.from().z(), env.to().z()), env.shadow_box()));
  return e.reached && e.error < 0 ? -e.error : 0;
}

// The deepest point of one rapid on the part; depth 0 when it stays clear.
RapidGouge part_check(const Part& part, const std::vector<FaceSamples>& faces, const SweptEnvelope& env,
                      double lowest_tip, const RapidCheckOptions& options, const NormalErrorOptions& normal) {
  RapidGouge best;
  const Eigen::AlignedBox2d shadow = env.shadow_box();
  double best_depth = 0;
  int best_face = -1;
  Eigen::Vector2d best_uv(0, 0);
  Eigen::Vector2d best_step(0, 0);
  for (const FaceSamples& s : faces) {
    const Face& face = part.faces[s.face];
    for (const FaceSamples::Block& block : s.blocks) {
      if (block.box.isEmpty()) continue;
      // A block outside the shadow, or whose top is not above the lowest
      // the envelope comes over it, cannot be touched (a plunge onto the
      // part reaches down only near its end point).
      if (block.box.max().z() <= lowest_tip) continue;
      if (block.box.max().x() < shadow.min().x() || block.box.min().x() > shadow.max().x() ||
          block.box.max().y() < shadow.min().y() || block.box.min().y() > shadow.max().y())
        continue;
      const Eigen::AlignedBox2d area(block.box.min().head<2>(), block.box.max().head<2>());
      if (block.box.max().z() <= env.lower_bound(area)) continue;
      for (int j = block.j0; j < block.j1; ++j)
        for (int i = block.i0; i < block.i1; ++i) {
          const Eigen::Vector2d uv(s.u(i), s.v(j));
          const double d = depth_at(face, env, uv, normal);
          if (d > best_depth) {  // strict: raster order breaks ties
            best_depth = d;
            best_face = static_cast<int>(s.face);
            best_uv = uv;
            best_step = Eigen::Vector2d(s.domain.width_u() / s.nu, s.domain.width_v() / s.nv);
          }
        }
    }
  }
  if (best_face < 0) return best;
  // Refine: golden-section along u, then v, within a sample step around
  // the best sample (the depth is smooth and unimodal that close).
  const Face& face = part.faces[static_cast<std::size_t>(best_face)];
  const ParameterDomain& dom = face.domain();
  Eigen::Vector2d uv = best_uv;
  auto cost = [&](const Eigen::Vector2d& q) {
    const double d = depth_at(face, env, q, normal);
    return std::isfinite(d) ? -d : kInf;
  };
  double value = cost(uv);
  UvRefineOptions refine;
  refine.rounds = options.refine_rounds;
  refine.relative_tolerance = 1e-6;
  refine.max_iterations = 80;
  refine.stall = 1e-12;
  value = refine_uv_by_axes(cost, dom, best_step, value, uv, refine);
  const SurfacePoint at = surface_point(part, best_face, uv);
  best.depth = -value;
  best.face = best_face;
  best.uv = uv;
  best.at = at.point;
  return best;
}

// Lowest tip of a rapid while the cutter's disc overlaps the stock in xy;
// depth 0 when it stays above the stock top or beside the stock.
RapidGouge stock_check(const RapidMove& rapid, double radius, const Eigen::AlignedBox3d& stock) {
  RapidGouge g;
  g.kind = RapidGougeKind::stock;
  const Eigen::Vector2d lo = stock.min().head<2>(), hi = stock.max().head<2>();
  auto tip = [&](double s) -> Eigen::Vector3d { return rapid.from + s * (rapid.to - rapid.from); };
  // Distance in xy from the tip to the stock's rectangle: convex in s.
  auto gap = [&](double s) {
    const Eigen::Vector2d p = tip(s).head<2>();
    return (p.cwiseMax(lo).cwiseMin(hi) - p).norm();
  };
  const ScalarSearchResult closest = minimize_unimodal(gap, 0.0, 1.0, {1e-12, 200});
  if (!(closest.value <= radius)) return g;
  auto over = [&](double s) { return gap(s) <= radius; };
  const double right = over(1.0) ? 1.0 : largest_satisfying(over, closest.x, 1.0, {1e-12, 200}).x;
  const double left =
      over(0.0) ? 0.0
                : closest.x - largest_satisfying([&](double t) { return over(closest.x - t); }, 0.0, closest.x,
                                                 {1e-12, 200})
                                  .x;
  // The tip height is linear in s: the lowest is at an end of the interval.
  const double s = tip(left).z() <= tip(right).z() ? left : right;
  g.at = tip(s);
  g.depth = std::max(0.0, stock.max().z() - g.at.z());
  return g;
}

}  // namespace

RapidCheck check_rapids(const Part& part, const Cutter& cutter, const std::vector<RapidMove>& rapids,
                        const RapidCheckOptions& options) {
  if (!(options.sample_spacing > 0) || !std::isfinite(options.sample_spacing))
    throw InputError("rapid check: the sample spacing must be a positive number of millimetres");
  if (!(options.threshold >= 0) || !std::isfinite(options.threshold))
    throw InputError("rapid check: the gouge threshold must not be negative");
  if (options.block < 1) throw InputError("rapid check: the block size must be at least 1");
  if (options.stock && (options.stock->isEmpty() || !options.stock->min().allFinite() ||
                        !options.stock->max().allFinite()))
    throw InputError("rapid check: the stock box must have finite min <= max on every axis");
  RapidCheck result;
  result.rapids = rapids.size();
  result.stock = options.stock.has_value();
  std::vector<std::size_t> known;
  for (std::size_t k = 0; k < rapids.size(); ++k) {
    if (rapids[k].known)
      known.push_back(k);
    else
      ++result.unchecked;
  }
  result.checked = known.size();
  if (known.empty()) return result;

  // The control nets' box contains every face: a rapid whose lowest tip is
  // above its top cannot touch the part (the cutter's lowest point is its
  // tip). Rapids at a clearance height, the usual case for posts that feed
  // the last approach with G1, then cost nothing, and when no rapid comes
  // lower the surface is not even sampled.
  const Eigen::AlignedBox3d box = part.control_box();
  auto may_touch = [&](const RapidMove& r) { return !box.isEmpty() && std::min(r.from.z(), r.to.z()) < box.max().z(); };
  bool any_low = false;
  for (std::size_t k : known) any_low = any_low || may_touch(rapids[k]);
  const std::vector<FaceSamples> faces = any_low ? sample_faces(part, options) : std::vector<FaceSamples>{};
  // A rapid may run deep through the part: the normal search must reach
  // across it.
  NormalErrorOptions normal = options.normal;
  normal.max_distance = std::max(normal.max_distance, box.isEmpty() ? 0.0 : box.diagonal().norm() + 2 * cutter.radius());

  std::vector<RapidGouge> found(known.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < static_cast<int>(known.size()); ++k) {
    const RapidMove& rapid = rapids[known[static_cast<std::size_t>(k)]];
    const SweptEnvelope env(cutter, rapid.from, rapid.to);
    RapidGouge g;
    if (may_touch(rapid)) g = part_check(part, faces, env, std::min(rapid.from.z(), rapid.to.z()), options, normal);
    if (!(g.depth > options.threshold) && options.stock) g = stock_check(rapid, cutter.radius(), *options.stock);
    g.rapid = known[static_cast<std::size_t>(k)];
    g.line = rapid.line;
    found[static_cast<std::size_t>(k)] = g;
  }
  for (const RapidGouge& g : found)
    if (g.depth > options.threshold) result.gouges.push_back(g);
  return result;
}

}  // namespace furrow
