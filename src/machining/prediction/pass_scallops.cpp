#include "machining/prediction/pass_scallops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/scalar_search.hpp"

namespace furrow {

namespace {

// The point of pass `to` nearest `p` in xy: on a segment between two valid
// contacts (uv interpolated on one face, else the nearer end).
bool nearest_on_pass(const std::vector<PathContact>& to, const Eigen::Vector2d& p, SurfacePoint& out,
                     double& distance) {
  distance = std::numeric_limits<double>::infinity();
  bool found = false;
  auto consider = [&](const SurfacePoint& s) {
    const double d = (s.point.head<2>() - p).norm();
    if (d < distance) distance = d, out = s, found = true;
  };
  for (std::size_t k = 0; k < to.size(); ++k) {
    if (!to[k].valid) continue;
    consider(to[k].at);
    if (k + 1 >= to.size() || !to[k + 1].valid) continue;
    const SurfacePoint& a = to[k].at;
    const SurfacePoint& b = to[k + 1].at;
    const Eigen::Vector2d ab = b.point.head<2>() - a.point.head<2>();
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0) || a.face != b.face) continue;
    const double t = std::clamp((p - a.point.head<2>()).dot(ab) / len2, 0.0, 1.0);
    if (t <= 0 || t >= 1) continue;
    const double d = (a.point.head<2>() + t * ab - p).norm();
    if (d < distance) {
      SurfacePoint s = a;
      s.uv = a.uv + t * (b.uv - a.uv);
      out = s;  // uv only: resolved on the surface by the caller
      out.valid = false;
      distance = d;
      found = true;
    }
  }
  return found;
}

}  // namespace

std::vector<PassScallop> pass_pair_scallops(const VerticalProjector& projector, const ZMap& zmap,
                                            double cutter_diameter,
                                            const std::vector<std::vector<PathContact>>& passes,
                                            const PassScallopOptions& options) {
  const Part& part = projector.part();
  const double spacing = options.sample_spacing > 0 ? options.sample_spacing : 0.5 * zmap.cell();
  const double reach = options.max_pass_distance > 0 ? options.max_pass_distance : cutter_diameter;
  std::vector<PassScallop> result;
  for (std::size_t a = 0; a + 1 < passes.size(); ++a) {
    PassScallop pair;
    pair.pass_a = static_cast<int>(a);
    pair.pass_b = static_cast<int>(a + 1);
    // Cross-section starts: contacts and mid-steps of pass a.
    std::vector<SurfacePoint> starts;
    const auto& pa = passes[a];
    for (std::size_t k = 0; k < pa.size(); ++k) {
      if (!pa[k].valid) continue;
      starts.push_back(pa[k].at);
      if (k + 1 < pa.size() && pa[k + 1].valid && pa[k + 1].at.face == pa[k].at.face) {
        const SurfacePoint mid =
            surface_point(part, pa[k].at.face, 0.5 * (pa[k].at.uv + pa[k + 1].at.uv));
        if (mid.valid) starts.push_back(mid);
      }
    }
    for (const SurfacePoint& s : starts) {
      SurfacePoint end;
      double distance = 0;
      if (!nearest_on_pass(passes[a + 1], s.point.head<2>(), end, distance) || distance > reach) continue;
      if (!end.valid) end = surface_point(part, end.face, end.uv);
      if (!end.valid) continue;
      const SurfaceCurve curve = s.face == end.face ? iso_parametric_curve(part, s.face, s.uv, end.uv)
                                                    : vertical_section_curve(projector, s, end);
      auto error_at = [&](double lambda) {
        const SurfacePoint p = curve(lambda);
        if (!p.valid || !(p.normal.z() >= 0) || !part.faces[p.face].contains(p.uv.x(), p.uv.y()))
          return -std::numeric_limits<double>::infinity();
        const NormalError e = zmap_error(zmap, p.point, p.normal, options.normal);
        return e.reached ? e.error : -std::numeric_limits<double>::infinity();
      };
      const double length = (end.point - s.point).norm();
      const int n = std::max(4, static_cast<int>(std::ceil(length / spacing)));
      int best_k = -1;
      double best = -std::numeric_limits<double>::infinity();
      for (int k = 0; k <= n; ++k) {
        const double e = error_at(double(k) / n);
        if (e > best) best = e, best_k = k;
      }
      if (best_k < 0) continue;
      const double lo = double(std::max(best_k - 1, 0)) / n, hi = double(std::min(best_k + 1, n)) / n;
      const ScalarSearchResult r = minimize_unimodal([&](double l) { return -error_at(l); }, lo, hi,
                                                     {options.refine_tolerance / std::max(length, 1e-9), 100});
      double lambda = double(best_k) / n;
      if (-r.value > best) best = -r.value, lambda = r.x;
      ++pair.cross_sections;
      if (!pair.found || best > pair.height) {
        pair.found = true;
        pair.height = best;
        pair.at = curve(lambda);
      }
    }
    result.push_back(pair);
  }
  return result;
}

}  // namespace furrow
