#include "geometry/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/error.hpp"
#include "geometry/candidate_voxels.hpp"
#include "geometry/local_foot_point.hpp"
#include "geometry/seed_grid.hpp"

namespace furrow {

const char* to_string(FootLocation location) {
  switch (location) {
    case FootLocation::interior:
      return "interior";
    case FootLocation::domain_edge:
      return "domain_edge";
    case FootLocation::trim_edge:
      return "trim_edge";
  }
  return "?";
}

namespace {

struct Candidate {
  double squared_distance = std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d su = Eigen::Vector3d::Zero(), sv = Eigen::Vector3d::Zero();  // zero: unknown
  bool on_trim = false;
  bool converged = false;
  int iterations = 0;
  Eigen::Vector2d cell_lo = Eigen::Vector2d::Zero(), cell_hi = Eigen::Vector2d::Zero();
};

void check_options(const ClosestPointOptions& o) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("closest point options: " + what);
  };
  require(o.cells_per_span >= 1, "cells_per_span must be at least 1");
  require(o.min_cells >= 1, "min_cells must be at least 1");
  require(o.max_cells >= o.min_cells && o.max_cells >= o.cells_per_span,
          "max_cells must be at least min_cells and cells_per_span");
  require(o.max_newton_iterations >= 1, "max_newton_iterations must be at least 1");
  require(o.max_line_search_halvings >= 1, "max_line_search_halvings must be at least 1");
  require(o.step_tolerance > 0 && std::isfinite(o.step_tolerance),
          "step_tolerance must be positive");
  require(o.stall_tolerance >= o.step_tolerance && std::isfinite(o.stall_tolerance),
          "stall_tolerance must be at least step_tolerance");
  require(o.trim_samples_per_segment >= 1, "trim_samples_per_segment must be at least 1");
}

bool in_box(const Eigen::Vector2d& uv, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  return (uv.array() >= lo.array()).all() && (uv.array() <= hi.array()).all();
}

// Solves one cell: the box minimum, replaced by the minimum along the cell's
// trim segments when the box minimum is trimmed away.
void solve_cell(const Part& part, const SeedGrid& grid, const SeedCell& cell,
                const Eigen::Vector3d& q, const Eigen::Vector2d* seed,
                const ClosestPointOptions& options, Candidate& best) {
  const Face& face = part.faces[cell.face];
  Eigen::Vector2d start;
  if (seed) {
    start = *seed;
  } else if (best.face == cell.face && std::isfinite(best.squared_distance) &&
             in_box(best.uv, cell.lo, cell.hi)) {
    start = best.uv;  // continue from the best foot (typically on the shared edge)
  } else if (cell.sample_kept == 0x1f) {
    // q's projection on the tangent plane at the middle: Newton's first step
    // from there, for free.
    Eigen::Matrix<double, 3, 2> J;
    J << cell.middle_su, cell.middle_sv;
    const Eigen::Matrix2d JtJ = J.transpose() * J;
    start = cell.sample_uv[4];
    if (JtJ.determinant() > 1e-12 * JtJ.trace() * JtJ.trace())
      start += JtJ.inverse() * (J.transpose() * (q - cell.sample_point[4]));
  } else {
    double nearest = std::numeric_limits<double>::infinity();
    start = cell.sample_uv[4];
    for (int k = 0; k < 5; ++k) {
      if (!(cell.sample_kept >> k & 1u)) continue;
      const double d2 = (cell.sample_point[k] - q).squaredNorm();
      if (d2 < nearest) {
        nearest = d2;
        start = cell.sample_uv[k];
      }
    }
  }
  Candidate c;
  c.face = cell.face;
  c.cell_lo = cell.lo;
  c.cell_hi = cell.hi;
  const BezierPatch* patch = grid.patch(static_cast<std::size_t>(&cell - grid.cells().data()));
  const LocalFoot in_box_foot =
      patch ? foot_point_in_box(*patch, q, start, cell.lo, cell.hi, options)
            : foot_point_in_box(face.surface(), q, start, cell.lo, cell.hi, options);
  if (!cell.cut_by_trim || face.trim().contains(in_box_foot.uv)) {
    c.squared_distance = in_box_foot.squared_distance;
    c.uv = in_box_foot.uv;
    c.point = in_box_foot.point;
    c.su = in_box_foot.su;
    c.sv = in_box_foot.sv;
    c.converged = in_box_foot.converged;
    c.iterations = in_box_foot.iterations;
  } else {
    // Segments nearest sphere first; one whose sphere is no nearer than the
    // best foot (this cell's or the search's) cannot hold a better one.
    // Squared distances throughout: a sphere (c, r) is no nearer than the
    // distance D when |q - c|^2 >= (r + D)^2.
    const TrimSegment* segments = grid.trim_segments().data() + cell.first_segment;
    std::uint32_t first = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint32_t k = 0; k < cell.segment_count; ++k) {
      const double d2 = (q - segments[k].centre).squaredNorm(), r = segments[k].radius;
      if (d2 - r * r < nearest) nearest = d2 - r * r, first = k;  // a cheap order: any order is exact
    }
    for (std::uint32_t n = 0; n < cell.segment_count; ++n) {
      const std::uint32_t k = n == 0 ? first : (n <= first ? n - 1 : n);
      const TrimSegment& seg = segments[k];
      const double beat = std::min(c.squared_distance, best.squared_distance);
      if (std::isfinite(beat)) {
        const double reach = seg.radius + std::sqrt(beat);
        if ((q - seg.centre).squaredNorm() >= reach * reach) continue;
      }
      const LocalFoot f = foot_point_on_segment(face.surface(), q, seg.a, seg.b, options);
      if (f.squared_distance < c.squared_distance) {
        c.squared_distance = f.squared_distance;
        c.uv = f.uv;
        c.point = f.point;
        c.converged = f.converged;
        c.iterations = f.iterations;
        c.on_trim = true;
      }
    }
  }
  if (c.squared_distance < best.squared_distance) best = c;
}

// Unit normal at the foot: Su x Sv (from the solve when it gave them, else
// evaluated), flipped for a reversed face. At a degenerate point (pole,
// collapsed edge) the normal of a point nudged into the domain is the limit
// a user expects.
Eigen::Vector3d foot_normal(const Face& face, const Eigen::Vector2d& uv, Eigen::Vector3d su,
                            Eigen::Vector3d sv) {
  if (su.isZero() && sv.isZero()) {
    const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 1);
    su = d.Su;
    sv = d.Sv;
  }
  const Eigen::Vector3d n = su.cross(sv);
  if (n.norm() > 0 && n.norm() > kDegenerateRelativeTolerance * su.norm() * sv.norm())
    return face.reversed() ? Eigen::Vector3d(-n.normalized()) : Eigen::Vector3d(n.normalized());
  DifferentialGeometry g = face.geometry(uv.x(), uv.y());
  if (!g.degenerate) return g.normal;
  const ParameterDomain& dom = face.domain();
  const Eigen::Vector2d middle(0.5 * (dom.u0 + dom.u1), 0.5 * (dom.v0 + dom.v1));
  for (double step : {1e-9, 1e-7, 1e-5, 1e-3}) {
    const Eigen::Vector2d nudged = uv + step * (middle - uv);
    g = face.geometry(nudged.x(), nudged.y());
    if (!g.degenerate) return g.normal;
  }
  return g.normal;
}

}  // namespace

ClosestPointFinder::ClosestPointFinder(const Part& part, ClosestPointOptions options)
    : part_(&part), control_box_(part.control_box()), options_(options) {
  check_options(options_);
  grid_ = std::make_unique<SeedGrid>(part, options_);
  if (options_.candidate_voxels) voxels_ = std::make_unique<CandidateVoxels>(*grid_);
}

ClosestPointFinder::~ClosestPointFinder() = default;
ClosestPointFinder::ClosestPointFinder(ClosestPointFinder&&) noexcept = default;
ClosestPointFinder& ClosestPointFinder::operator=(ClosestPointFinder&&) noexcept = default;

std::size_t ClosestPointFinder::cell_count() const { return grid_->cells().size(); }

ClosestPoint ClosestPointFinder::project(const Eigen::Vector3d& q) const {
  return search(q, nullptr);
}

ClosestPoint ClosestPointFinder::project(const Eigen::Vector3d& q, const ClosestPoint& hint) const {
  return search(q, &hint);
}

std::vector<ClosestPoint> ClosestPointFinder::project_in_order(
    const std::vector<Eigen::Vector3d>& points) const {
  std::vector<ClosestPoint> feet;
  feet.reserve(points.size());
  for (const Eigen::Vector3d& q : points)
    feet.push_back(feet.empty() ? search(q, nullptr) : search(q, &feet.back()));
  return feet;
}

std::optional<ClosestPoint> ClosestPointFinder::project_to_other_faces(const Eigen::Vector3d& q,
                                                                      std::size_t face) const {
  const ClosestPoint foot = search(q, nullptr, face);
  if (foot.face == face || !std::isfinite(foot.distance)) return std::nullopt;
  return foot;
}

ClosestPoint ClosestPointFinder::search(const Eigen::Vector3d& q, const ClosestPoint* hint,
                                        std::size_t excluded) const {
  const SeedGrid& grid = *grid_;
  const auto& cells = grid.cells();
  const auto& bounds = grid.bounds();
  const auto& nodes = grid.nodes();
  Candidate best;
  int examined = 0;
  int hint_cell = -1;
  if (hint && hint->face < part_->faces.size()) {
    hint_cell = grid.cell_at(hint->face, hint->uv);
    if (hint_cell >= 0) {
      solve_cell(*part_, grid, cells[hint_cell], q, &hint->uv, options_, best);
      ++examined;
    }
  }

  // Two phases. First a depth-first walk of the box tree, nearer child
  // first, that only screens cells: a cell is a candidate when its lower
  // bound is below both the best foot so far and the nearest kept surface
  // sample of the cells screened (CellBounds::surface_point: an upper bound of the
  // answer, tight for a point far off the surface, where the lower bounds
  // of many cells are close to each other). Then the candidates are solved
  // in the order of their lower bounds until the next cannot beat the best
  // foot: the cell holding the foot usually comes first, so the others are
  // skipped. Squared distances throughout: no square roots on the way down.
  struct Pending {
    std::int32_t node;
    double squared_distance;
  };
  Pending stack[128];
  int top = 0;
  stack[top++] = {0, nodes[0].box.squaredExteriorDistance(q)};
  // Plain members, not std::pair: an array of pairs would be zeroed on
  // every query.
  struct Screened {
    double bound;  // squared
    std::uint32_t cell;
    bool operator<(const Screened& other) const { return bound < other.bound; }
  };
  constexpr int kMaxCandidates = 256;
  Screened candidates[kMaxCandidates];
  int count = 0;
  double upper = best.squared_distance;  // squared: min(best foot, nearest surface sample)
  auto solve_candidates = [&] {
    std::sort(candidates, candidates + count);
    for (int k = 0; k < count; ++k) {
      if (candidates[k].bound >= best.squared_distance) break;
      solve_cell(*part_, grid, cells[candidates[k].cell], q, nullptr, options_, best);
      ++examined;
    }
    count = 0;
    upper = std::min(upper, best.squared_distance);
  };
  auto screen = [&](std::uint32_t index) {
    if (static_cast<int>(index) == hint_cell || (excluded != kNoFace && cells[index].face == excluded)) return;
    const CellBounds& cell = bounds[index];
    upper = std::min(upper, (cell.surface_point - q).squaredNorm());
    const double bound = cell.squared_screen(q);
    if (!(bound < upper)) return;
    // A full list is solved at once (the walk goes on with its best).
    if (count == kMaxCandidates) solve_candidates();
    candidates[count++] = {bound, index};
  };
  // In the voxel lattice, the cube's list stands for the walk; a search
  // that excludes a face walks the tree (the lists do not know it).
  const CandidateCells near = voxels_ && excluded == kNoFace ? voxels_->cells_near(q) : CandidateCells{};
  if (near) {
    for (const std::uint32_t index : near) screen(index);
    top = 0;
  }
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.squared_distance >= upper) continue;
    const SeedNode& node = nodes[pending.node];
    if (node.left < 0) {
      for (std::uint32_t k = 0; k < node.count; ++k) screen(node.first + k);
      continue;
    }
    const double bl = nodes[node.left].box.squaredExteriorDistance(q);
    const double br = nodes[node.right].box.squaredExteriorDistance(q);
    const bool left_first = bl <= br;
    if (std::max(bl, br) < upper)
      stack[top++] = left_first ? Pending{node.right, br} : Pending{node.left, bl};
    if (std::min(bl, br) < upper)
      stack[top++] = left_first ? Pending{node.left, bl} : Pending{node.right, br};
  }
  solve_candidates();

  if (!std::isfinite(best.squared_distance)) {  // every cell was excluded
    ClosestPoint none;
    none.face = excluded;
    none.distance = std::numeric_limits<double>::infinity();
    return none;
  }
  const Face& face = part_->faces[best.face];
  const ParameterDomain& dom = face.domain();
  // Off the cell's edges, or on an edge that is the face's own domain edge
  // (the cell's bound there is the face's, so the cell's minimum is the
  // face's local minimum too: a point beyond the face's edge).
  const Eigen::Vector2d dom_lo(dom.u0, dom.v0), dom_hi(dom.u1, dom.v1);
  const bool inside_cell =
      ((best.uv.array() > best.cell_lo.array()) || (best.cell_lo.array() <= dom_lo.array())).all() &&
      ((best.uv.array() < best.cell_hi.array()) || (best.cell_hi.array() >= dom_hi.array())).all();
  if (!best.on_trim && !(inside_cell && best.converged)) {
    // The best cell minimum sits on an edge between cells; one solve over the
    // whole face from there confirms it is stationary for the face (or
    // improves it).
    const LocalFoot polish =
        foot_point_in_box(face.surface(), q, best.uv, {dom.u0, dom.v0}, {dom.u1, dom.v1}, options_);
    if (polish.squared_distance <= best.squared_distance && face.trim().contains(polish.uv)) {
      best.uv = polish.uv;
      best.point = polish.point;
      best.su = polish.su;
      best.sv = polish.sv;
      best.squared_distance = polish.squared_distance;
      best.converged = polish.converged;
      best.iterations += polish.iterations;
    }
  }

  ClosestPoint out;
  out.face = best.face;
  out.uv = best.uv;
  out.point = best.point;
  out.normal = foot_normal(face, best.uv, best.su, best.sv);
  out.distance = (q - best.point).norm();
  out.signed_distance = (q - best.point).dot(out.normal) < 0 ? -out.distance : out.distance;
  const bool on_domain_edge = best.uv.x() <= dom.u0 || best.uv.x() >= dom.u1 ||
                              best.uv.y() <= dom.v0 || best.uv.y() >= dom.v1;
  out.location = best.on_trim     ? FootLocation::trim_edge
                 : on_domain_edge ? FootLocation::domain_edge
                                  : FootLocation::interior;
  out.converged = best.converged;
  out.iterations = best.iterations;
  out.cells_examined = examined;
  return out;
}

}  // namespace furrow
