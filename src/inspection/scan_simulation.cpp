#include "inspection/scan_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "inspection/surface_sampling.hpp"

namespace furrow {

namespace {

// More rays than this is a pitch far too fine for the part (or a mistake):
// refused rather than allocated.
constexpr double kMaxRays = 50e6;

void check_model(const ScannerModel& m) {
  auto fail = [](const std::string& what) { throw InputError("scan simulation: " + what); };
  // stableNorm: the plain norm of (1e308, 1e308, 0) overflows, and the
  // direction it normalises to would be zero.
  if (!m.view.allFinite() || !(m.view.stableNorm() > 0)) fail("the view direction must be a non-zero vector");
  if (!(m.stripe_pitch > 0) || !std::isfinite(m.stripe_pitch)) fail("the stripe pitch must be positive");
  if (!(m.point_pitch > 0) || !std::isfinite(m.point_pitch)) fail("the point pitch must be positive");
  if (!(m.max_incidence_deg > 0 && m.max_incidence_deg < 90))
    fail("the largest incidence must lie between 0 and 90 degrees");
  if (!(m.noise_sigma >= 0) || !std::isfinite(m.noise_sigma)) fail("the noise must be a non-negative number");
  if (!(m.spray_share >= 0 && m.spray_share < 1)) fail("the spray share must lie in [0, 1)");
  if (!(m.spray_min > 0 && m.spray_max >= m.spray_min && std::isfinite(m.spray_max)))
    fail("the spray range must be 0 < smallest <= largest");
  if (m.max_newton < 1 || !(m.newton_tolerance > 0)) fail("the Newton cap and tolerance must be positive");
  for (const SurfaceBump& b : m.bumps)
    if (!(b.radius > 0)) fail("a bump radius must be positive");
}

// The raster: ray (i, j) starts in the plane through the origin normal to
// the view, at x = x0 + i * dx along e1 and y = y0 + j * dy along e2 (a
// stripe is a row j), and runs along d.
struct Raster {
  Eigen::Vector3d d, e1, e2;
  double x0 = 0, y0 = 0, dx = 1, dy = 1;
  long nx = 0, ny = 0;
  Eigen::Vector3d origin(long i, long j) const { return (x0 + i * dx) * e1 + (y0 + j * dy) * e2; }
};

// What the nearest tessellation triangle says a ray meets first.
struct FirstHit {
  double depth = std::numeric_limits<double>::infinity();
  int face = -1;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

// A face's tessellation nodes: positions and whether the trim keeps them.
struct FaceNodes {
  int nu = 0, nv = 0;
  std::vector<double> u, v;
  std::vector<Eigen::Vector3d> p;
  std::vector<char> kept;
};

FaceNodes tessellate(const Face& face, double spacing) {
  FaceNodes n;
  const ParameterDomain& dom = face.domain();
  n.nu = std::clamp(static_cast<int>(std::ceil(iso_length(face, true) / spacing)), 2, 3000);
  n.nv = std::clamp(static_cast<int>(std::ceil(iso_length(face, false) / spacing)), 2, 3000);
  for (int i = 0; i <= n.nu; ++i) n.u.push_back(dom.u0 + dom.width_u() * i / n.nu);
  for (int j = 0; j <= n.nv; ++j) n.v.push_back(dom.v0 + dom.width_v() * j / n.nv);
  const std::size_t count = static_cast<std::size_t>(n.nu + 1) * (n.nv + 1);
  n.p.resize(count);
  n.kept.resize(count);
#pragma omp parallel for schedule(static)
  for (int j = 0; j <= n.nv; ++j)
    for (int i = 0; i <= n.nu; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * (n.nu + 1) + i;
      n.p[k] = face.surface().point(n.u[i], n.v[j]);
      n.kept[k] = face.contains(n.u[i], n.v[j]);
    }
  return n;
}

// Depth-buffers one triangle (projected corners a, b, c with depths and
// (u, v)) into `hits`.
void rasterize(const Raster& r, int face, const Eigen::Vector3d* p, const Eigen::Vector2d* uv,
               std::vector<FirstHit>& hits) {
  Eigen::Vector2d q[3];
  double z[3];
  for (int k = 0; k < 3; ++k) {
    q[k] = {r.e1.dot(p[k]), r.e2.dot(p[k])};
    z[k] = r.d.dot(p[k]);
  }
  const double area = (q[1] - q[0]).x() * (q[2] - q[0]).y() - (q[1] - q[0]).y() * (q[2] - q[0]).x();
  if (!(std::fabs(area) > 1e-18)) return;  // seen edge-on: its neighbours hold the surface
  const double xmin = std::min({q[0].x(), q[1].x(), q[2].x()}), xmax = std::max({q[0].x(), q[1].x(), q[2].x()});
  const double ymin = std::min({q[0].y(), q[1].y(), q[2].y()}), ymax = std::max({q[0].y(), q[1].y(), q[2].y()});
  const long i0 = std::max(0L, static_cast<long>(std::ceil((xmin - r.x0) / r.dx)));
  const long i1 = std::min(r.nx - 1, static_cast<long>(std::floor((xmax - r.x0) / r.dx)));
  const long j0 = std::max(0L, static_cast<long>(std::ceil((ymin - r.y0) / r.dy)));
  const long j1 = std::min(r.ny - 1, static_cast<long>(std::floor((ymax - r.y0) / r.dy)));
  // A shared edge belongs to both of its triangles (a small negative
  // tolerance), so no ray slips through the crack between them.
  const double slack = -1e-9;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) {
      const Eigen::Vector2d s(r.x0 + i * r.dx, r.y0 + j * r.dy);
      const double w1 = ((s - q[0]).x() * (q[2] - q[0]).y() - (s - q[0]).y() * (q[2] - q[0]).x()) / area;
      const double w2 = ((q[1] - q[0]).x() * (s - q[0]).y() - (q[1] - q[0]).y() * (s - q[0]).x()) / area;
      const double w0 = 1 - w1 - w2;
      if (w0 < slack || w1 < slack || w2 < slack) continue;
      const double depth = w0 * z[0] + w1 * z[1] + w2 * z[2];
      FirstHit& h = hits[static_cast<std::size_t>(j) * r.nx + i];
      if (depth < h.depth) h = {depth, face, w0 * uv[0] + w1 * uv[1] + w2 * uv[2]};
    }
}

enum class RayOutcome : unsigned char { missed, point, grazing, from_behind, not_solved };

struct RayResult {
  RayOutcome outcome = RayOutcome::missed;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  double cos_incidence = 0;
};

// The ray's point on the face, by Newton on S(u, v) - (o + t d) = 0 in
// (u, v, t) from the tessellation's guess, (u, v) kept in the domain.
RayResult solve_ray(const Face& face, const Eigen::Vector3d& o, const Eigen::Vector3d& d, Eigen::Vector2d uv,
                    const ScannerModel& m) {
  RayResult out;
  out.outcome = RayOutcome::not_solved;
  const ParameterDomain& dom = face.domain();
  double t = d.dot(face.surface().point(uv.x(), uv.y()) - o);
  bool converged = false;
  for (int it = 0; it < m.max_newton; ++it) {
    const SurfaceDerivatives s = face.surface().evaluate(uv.x(), uv.y(), 1);
    const Eigen::Vector3d residual = s.S - (o + t * d);
    if (residual.norm() < m.newton_tolerance) {
      converged = true;
      break;
    }
    Eigen::Matrix3d j;
    j << s.Su, s.Sv, -d;
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(j);
    if (!lu.isInvertible()) break;
    const Eigen::Vector3d step = lu.solve(-residual);
    uv.x() = std::clamp(uv.x() + step.x(), dom.u0, dom.u1);
    uv.y() = std::clamp(uv.y() + step.y(), dom.v0, dom.v1);
    t += step.z();
  }
  if (!converged || !face.contains(uv.x(), uv.y())) return out;
  const DifferentialGeometry g = face.geometry(uv.x(), uv.y());
  if (g.degenerate) return out;
  out.uv = uv;
  out.point = g.point;
  out.normal = g.normal;
  out.cos_incidence = -d.dot(g.normal);
  if (out.cos_incidence <= 0)
    out.outcome = RayOutcome::from_behind;
  else if (out.cos_incidence < std::cos(radians(m.max_incidence_deg)))
    out.outcome = RayOutcome::grazing;
  else
    out.outcome = RayOutcome::point;
  return out;
}

Raster make_raster(const Part& part, const ScannerModel& m, const std::vector<FaceNodes>& nodes) {
  Raster r;
  r.d = m.view / m.view.stableNorm();
  // e1 from the axis least aligned with the view, so the frame is fixed by
  // the view alone.
  Eigen::Index axis = 0;
  r.d.cwiseAbs().minCoeff(&axis);
  r.e1 = r.d.cross(Eigen::Vector3d::Unit(axis)).normalized();
  r.e2 = r.d.cross(r.e1);
  Eigen::AlignedBox2d box;
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    for (std::size_t k = 0; k < nodes[f].p.size(); ++k)
      if (nodes[f].kept[k]) box.extend(Eigen::Vector2d(r.e1.dot(nodes[f].p[k]), r.e2.dot(nodes[f].p[k])));
  if (box.isEmpty()) throw InputError("scan simulation: the part has no surface to scan");
  r.dx = m.point_pitch;
  r.dy = m.stripe_pitch;
  r.x0 = box.min().x();
  r.y0 = box.min().y();
  const double nx = std::floor(box.sizes().x() / r.dx) + 1, ny = std::floor(box.sizes().y() / r.dy) + 1;
  if (nx * ny > kMaxRays)
    throw InputError("scan simulation: a raster of " + std::to_string(static_cast<long long>(nx * ny)) +
                     " rays (more than 50 million): use a coarser pitch");
  r.nx = static_cast<long>(nx);
  r.ny = static_cast<long>(ny);
  return r;
}

}  // namespace

SimulatedScan simulate_scan(const Part& part, const ScannerModel& m) {
  check_model(m);
  // The tessellation only chooses the face a ray meets first; a node spacing
  // of twice the finer pitch keeps its chords' sag far below a pitch.
  const double spacing = 2 * std::min(m.stripe_pitch, m.point_pitch);
  // A pitch far too fine is refused before the fine tessellation, whose
  // cost grows with it: the nodes of a coarse one lie on the surface too,
  // so the raster over their extent has at most as many rays as the real
  // one; when even it is over the limit, make_raster refuses here.
  constexpr double kCoarseSpacing = 0.5;  // [mm]
  if (spacing < kCoarseSpacing) {
    std::vector<FaceNodes> coarse;
    for (const Face& face : part.faces) coarse.push_back(tessellate(face, kCoarseSpacing));
    bool any_kept = false;
    for (const FaceNodes& n : coarse) any_kept |= std::find(n.kept.begin(), n.kept.end(), 1) != n.kept.end();
    if (any_kept) make_raster(part, m, coarse);
  }
  std::vector<FaceNodes> nodes;
  for (const Face& face : part.faces) nodes.push_back(tessellate(face, spacing));
  const Raster r = make_raster(part, m, nodes);

  std::vector<FirstHit> hits(static_cast<std::size_t>(r.nx) * r.ny);
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const FaceNodes& n = nodes[f];
    for (int j = 0; j < n.nv; ++j)
      for (int i = 0; i < n.nu; ++i) {
        const std::size_t k00 = static_cast<std::size_t>(j) * (n.nu + 1) + i, k10 = k00 + 1,
                          k01 = k00 + n.nu + 1, k11 = k01 + 1;
        const Eigen::Vector2d uv00(n.u[i], n.v[j]), uv10(n.u[i + 1], n.v[j]), uv01(n.u[i], n.v[j + 1]),
            uv11(n.u[i + 1], n.v[j + 1]);
        // A triangle with any corner on the face occludes: dropping the
        // cells the trim cuts would open gaps along every trimmed edge that
        // rays slip through to the faces behind.
        if (n.kept[k00] || n.kept[k10] || n.kept[k11]) {
          const Eigen::Vector3d p[3] = {n.p[k00], n.p[k10], n.p[k11]};
          const Eigen::Vector2d uv[3] = {uv00, uv10, uv11};
          rasterize(r, static_cast<int>(f), p, uv, hits);
        }
        if (n.kept[k00] || n.kept[k11] || n.kept[k01]) {
          const Eigen::Vector3d p[3] = {n.p[k00], n.p[k11], n.p[k01]};
          const Eigen::Vector2d uv[3] = {uv00, uv11, uv01};
          rasterize(r, static_cast<int>(f), p, uv, hits);
        }
      }
  }

  std::vector<RayResult> rays(hits.size());
#pragma omp parallel for schedule(dynamic, 4096)
  for (long k = 0; k < static_cast<long>(hits.size()); ++k) {
    const FirstHit& h = hits[static_cast<std::size_t>(k)];
    if (h.face < 0) continue;
    rays[static_cast<std::size_t>(k)] =
        solve_ray(part.faces[static_cast<std::size_t>(h.face)], r.origin(k % r.nx, k / r.nx), r.d, h.uv, m);
  }

  // In raster order, on one thread: the random draws.
  SimulatedScan out;
  out.counts.rays = rays.size();
  std::mt19937 rng(m.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> along_sight;  // per point: the offset along the line of sight [mm]
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const RayResult& ray = rays[k];
    switch (ray.outcome) {
      case RayOutcome::missed: ++out.counts.missed; continue;
      case RayOutcome::grazing: ++out.counts.grazing; continue;
      case RayOutcome::from_behind: ++out.counts.from_behind; continue;
      case RayOutcome::not_solved: ++out.counts.not_solved; continue;
      case RayOutcome::point: break;
    }
    double h = 0;
    for (const SurfaceBump& b : m.bumps) h += b.offset_at(ray.point);
    out.face.push_back(static_cast<std::size_t>(hits[k].face));
    out.uv.push_back(ray.uv);
    out.nominal.push_back(ray.point);
    out.normals.push_back(ray.normal);
    out.intensity.push_back(static_cast<float>(ray.cos_incidence));
    out.true_deviation.push_back(h);
    out.points.push_back(ray.point + h * ray.normal);
    const double sigma = m.noise_grows_with_incidence
                             ? m.noise_sigma / (ray.cos_incidence * ray.cos_incidence)
                             : m.noise_sigma;
    along_sight.push_back(m.noise_sigma > 0 ? sigma * noise(rng) : 0.0);
  }
  const std::size_t count = out.points.size();
  out.spray.assign(count, false);
  // Spray: a partial Fisher-Yates draw of round(share * count) points.
  const std::size_t sprayed = static_cast<std::size_t>(std::llround(m.spray_share * static_cast<double>(count)));
  std::vector<std::size_t> order(count);
  for (std::size_t k = 0; k < count; ++k) order[k] = k;
  std::uniform_real_distribution<double> size(m.spray_min, m.spray_max);
  for (std::size_t s = 0; s < sprayed; ++s) {
    std::uniform_int_distribution<std::size_t> pick(s, count - 1);
    std::swap(order[s], order[pick(rng)]);
    const std::size_t k = order[s];
    out.spray[k] = true;
    along_sight[k] += (rng() & 1u ? 1.0 : -1.0) * size(rng);
  }
  out.counts.spray = sprayed;
  out.counts.points = count;

  const Eigen::Isometry3d to_scanner = m.part_to_scanner.part_to_cmm();
  for (std::size_t k = 0; k < count; ++k) {
    // The point moves along d; its distance from the surface along the
    // normal changes by d . n times that (to first order).
    out.points[k] += along_sight[k] * r.d;
    out.true_deviation[k] += along_sight[k] * r.d.dot(out.normals[k]);
    out.points[k] = to_scanner * out.points[k];
    out.normals[k] = to_scanner.linear() * out.normals[k];
  }
  return out;
}

}  // namespace furrow
