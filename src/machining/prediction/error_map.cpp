#include "machining/prediction/error_map.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/error.hpp"
#include "geometry/surface_grid.hpp"
#include "machining/prediction/uv_refine.hpp"

namespace furrow {

const char* to_string(ErrorCellStatus status) {
  switch (status) {
    case ErrorCellStatus::reached: return "reached";
    case ErrorCellStatus::not_reached: return "not_reached";
    case ErrorCellStatus::outside: return "outside";
    case ErrorCellStatus::not_machinable: return "not_machinable";
  }
  return "unknown";
}

NormalError zmap_error(const ZMap& zmap, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                       const NormalErrorOptions& options) {
  auto height = [&zmap](double x, double y) { return zmap.height_at(x, y); };
  // Steps of at most one cell of horizontal travel, so the search cannot
  // jump over uncut nodes between passes (normal_error.hpp "max_step").
  NormalErrorOptions o = with_height_bounds(options, zmap.lowest_tip(), zmap.shadow_box());
  const double nxy = std::hypot(normal.x(), normal.y());
  if (nxy > 0) {
    const double cell_step = zmap.cell() / nxy;
    o.max_step = o.max_step > 0 ? std::min(o.max_step, cell_step) : cell_step;
  }
  return normal_error(height, point, normal, o);
}

bool is_boundary_sample(const ZMap& zmap, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                        const NormalError& e) {
  if (zmap.near_boundary(point.x(), point.y())) return true;
  if (!e.reached) return e.end != 0;  // the normal left the cut area (0: nothing above the point)
  if (e.wall) return true;
  const Eigen::Vector3d meet = point + e.end * normal;
  return zmap.near_boundary(meet.x(), meet.y());
}

NormalError zmap_error(const ZMap& zmap, const Face& face, const Eigen::Vector2d& uv,
                       const NormalErrorOptions& options) {
  Eigen::Vector3d p, n;
  if (!face_normal(face, uv.x(), uv.y(), p, n) || !(n.z() >= 0)) return {};
  return zmap_error(zmap, p, n, options);
}

Eigen::Vector2d face_extent_lengths(const Face& face) {
  const ParameterDomain& d = face.domain();
  constexpr int kLines = 9, kSegments = 64;
  Eigen::Vector2d longest(0, 0);
  for (int l = 0; l < kLines; ++l) {
    const double s = double(l) / (kLines - 1);
    double along_u = 0, along_v = 0;
    Eigen::Vector3d pu = face.surface().point(d.u0, d.v0 + s * d.width_v());
    Eigen::Vector3d pv = face.surface().point(d.u0 + s * d.width_u(), d.v0);
    for (int k = 1; k <= kSegments; ++k) {
      const double t = double(k) / kSegments;
      const Eigen::Vector3d qu = face.surface().point(d.u0 + t * d.width_u(), d.v0 + s * d.width_v());
      const Eigen::Vector3d qv = face.surface().point(d.u0 + s * d.width_u(), d.v0 + t * d.width_v());
      along_u += (qu - pu).norm();
      along_v += (qv - pv).norm();
      pu = qu, pv = qv;
    }
    longest = longest.cwiseMax(Eigen::Vector2d(along_u, along_v));
  }
  return longest;
}

ErrorExtremum refine_error_extremum(const Part& part, const ZMap& zmap, std::size_t face,
                                    const Eigen::Vector2d& start, double du, double dv, double sign,
                                    const ErrorMapOptions& options) {
  const Face& f = part.faces[face];
  const ParameterDomain& dom = f.domain();
  auto cost = [&](const Eigen::Vector2d& uv) {
    if (!f.contains(uv.x(), uv.y())) return std::numeric_limits<double>::infinity();
    const NormalError e = zmap_error(zmap, f, uv, options.normal);
    return e.reached ? -sign * e.error : std::numeric_limits<double>::infinity();
  };
  ErrorExtremum result;
  Eigen::Vector2d uv = start;
  double best = cost(uv);
  if (!std::isfinite(best)) return result;
  UvRefineOptions refine;
  refine.rounds = options.refine_rounds;
  best = refine_uv_by_axes(cost, dom, Eigen::Vector2d(du, dv), best, uv, refine);
  result.found = true;
  result.error = -sign * best;
  result.at = surface_point(part, static_cast<int>(face), uv);
  return result;
}

namespace {

void summarise_cells(FaceErrorMap& m) {
  m.cells.assign(static_cast<std::size_t>(m.cells_u) * m.cells_v, ErrorCell{});
  for (int cj = 0; cj < m.cells_v; ++cj)
    for (int ci = 0; ci < m.cells_u; ++ci) {
      ErrorCell& c = m.cells[static_cast<std::size_t>(cj) * m.cells_u + ci];
      double sum = 0;
      bool machinable = false, inside = false;
      for (int j = cj * m.block_v; j < (cj + 1) * m.block_v; ++j)
        for (int i = ci * m.block_u; i < (ci + 1) * m.block_u; ++i) {
          const ErrorCellStatus s = m.status[m.index(i, j)];
          c.boundary += m.boundary[m.index(i, j)];
          inside = inside || s != ErrorCellStatus::outside;
          machinable = machinable || s == ErrorCellStatus::not_reached;
          if (s != ErrorCellStatus::reached) continue;
          const double e = m.error[m.index(i, j)];
          if (c.reached == 0 || e > c.max_undercut) c.max_undercut = e;
          if (c.reached == 0 || e < c.max_overcut) c.max_overcut = e;
          sum += e;
          ++c.reached;
        }
      if (c.reached > 0) {
        c.status = ErrorCellStatus::reached;
        c.mean = sum / c.reached;
      } else {
        c.status = !inside ? ErrorCellStatus::outside
                           : (machinable ? ErrorCellStatus::not_reached : ErrorCellStatus::not_machinable);
      }
    }
}

}  // namespace

ErrorMap compute_error_map(const Part& part, const ZMap& zmap, const ErrorMapOptions& options,
                           const std::function<void(std::size_t, std::size_t)>& progress) {
  const double spacing = options.sample_spacing > 0 ? options.sample_spacing : zmap.cell();
  if (!(options.cell_size > 0) || !std::isfinite(options.cell_size))
    throw InputError("error map: the cell size must be a positive number of millimetres");
  ErrorMap map;
  std::size_t total_rows = 0;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    FaceErrorMap m;
    m.face = f;
    m.domain = part.faces[f].domain();
    const Eigen::Vector2d len = face_extent_lengths(part.faces[f]);
    m.cells_u = std::max(1, static_cast<int>(std::ceil(len.x() / options.cell_size)));
    m.cells_v = std::max(1, static_cast<int>(std::ceil(len.y() / options.cell_size)));
    m.block_u = std::max(1, static_cast<int>(std::ceil(len.x() / m.cells_u / spacing)));
    m.block_v = std::max(1, static_cast<int>(std::ceil(len.y() / m.cells_v / spacing)));
    m.nu = m.cells_u * m.block_u;
    m.nv = m.cells_v * m.block_v;
    const double samples = double(m.nu) * m.nv;
    if (samples > double(options.max_samples)) {
      std::ostringstream s;
      s << "error map: face \"" << part.faces[f].name() << "\" would need " << samples << " samples at "
        << spacing << " mm, more than the limit of " << options.max_samples << " (use a coarser resolution)";
      throw InputError(s.str());
    }
    m.error.assign(static_cast<std::size_t>(samples), 0.0f);
    m.status.assign(static_cast<std::size_t>(samples), ErrorCellStatus::not_reached);
    m.boundary.assign(static_cast<std::size_t>(samples), 0);
    total_rows += m.nv;
    map.faces.push_back(std::move(m));
  }
  std::atomic<std::size_t> done{0};
  for (FaceErrorMap& m : map.faces) {
    const Face& face = part.faces[m.face];
    // Sample centres as one tensor grid (geometry/surface_grid.hpp): the basis
    // functions are computed once per grid column and row instead of at every
    // sample, with results bit-identical to face_normal's own evaluation.
    std::vector<double> us(m.nu), vs(m.nv);
    for (int i = 0; i < m.nu; ++i) us[i] = m.u(i);
    for (int j = 0; j < m.nv; ++j) vs[j] = m.v(j);
    const SurfaceGrid grid(face.surface(), std::move(us), std::move(vs), 1);
#pragma omp parallel
    {
      SurfaceGridScratch scratch;
      std::vector<SurfaceDerivatives> row(static_cast<std::size_t>(m.nu));
#pragma omp for schedule(dynamic, 4)
      for (int j = 0; j < m.nv; ++j) {
        grid.evaluate_row(j, row.data(), scratch);
        const double v = grid.v(j);
        for (int i = 0; i < m.nu; ++i) {
          const double u = grid.u(i);
          const std::size_t k = m.index(i, j);
          if (!face.contains(u, v)) {
            m.status[k] = ErrorCellStatus::outside;
            continue;
          }
          Eigen::Vector3d p, n;
          if (!face_normal(face, row[static_cast<std::size_t>(i)], p, n) || !(n.z() >= 0)) {
            m.status[k] = ErrorCellStatus::not_machinable;
            continue;
          }
          const NormalError e = zmap_error(zmap, p, n, options.normal);
          m.boundary[k] = is_boundary_sample(zmap, p, n, e) ? 1 : 0;
          if (!e.reached) continue;
          m.status[k] = ErrorCellStatus::reached;
          m.error[k] = static_cast<float>(e.error);
        }
        const std::size_t d = ++done;
        if (progress && omp_get_thread_num() == 0 && d % 64 == 0) progress(d, total_rows);
      }
    }
    summarise_cells(m);
  }
  if (progress) progress(total_rows, total_rows);

  // Extremes: the best sample (raster order breaks ties), refined.
  struct Best {
    bool found = false;
    double value = 0;
    std::size_t face = 0;
    int i = 0, j = 0;
  } hi, lo;
  for (const FaceErrorMap& m : map.faces)
    for (int j = 0; j < m.nv; ++j)
      for (int i = 0; i < m.nu; ++i) {
        const std::size_t k = m.index(i, j);
        ++map.samples;
        map.boundary += m.boundary[k];
        switch (m.status[k]) {
          case ErrorCellStatus::reached: ++map.reached; break;
          case ErrorCellStatus::not_reached: ++map.not_reached; break;
          case ErrorCellStatus::not_machinable: ++map.not_machinable; break;
          case ErrorCellStatus::outside: break;
        }
        if (m.status[k] != ErrorCellStatus::reached) continue;
        const double e = m.error[k];
        if (!hi.found || e > hi.value) hi = {true, e, m.face, i, j};
        if (!lo.found || e < lo.value) lo = {true, e, m.face, i, j};
      }
  auto refine = [&](const Best& b, double sign) {
    const FaceErrorMap& m = map.faces[b.face];
    const double du = m.domain.width_u() / m.nu, dv = m.domain.width_v() / m.nv;
    return refine_error_extremum(part, zmap, b.face, {m.u(b.i), m.v(b.j)}, du, dv, sign, options);
  };
  if (hi.found) map.max_undercut = refine(hi, +1);
  if (lo.found) map.max_overcut = refine(lo, -1);
  return map;
}

}  // namespace furrow
