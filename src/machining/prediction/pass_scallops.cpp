#include "machining/prediction/pass_scallops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/scalar_search.hpp"

namespace furrow {

namespace {

constexpr double kNone = -std::numeric_limits<double>::infinity();

// A point of a pass: on the segment from contact k to k + 1 at t in [0, 1]
// (t = 0: the contact itself).
struct PassPoint {
  SurfacePoint at;
  std::size_t k = 0;
  double t = 0;
  // The pass ends before the foot of the perpendicular from the section's
  // start: the section meets it obliquely, at its end.
  bool beyond_end = false;
};

// The point of pass `to` nearest `p` in xy: a contact, or a point of a
// segment between two valid contacts on one face (uv interpolated, then
// moved along the segment to the surface point nearest `p` in space, so
// that the section meets the pass square on a curved surface).
bool nearest_on_pass(const Part& part, const std::vector<PathContact>& to, const SurfacePoint& from,
                     PassPoint& out, double& distance) {
  const Eigen::Vector2d p = from.point.head<2>();
  distance = std::numeric_limits<double>::infinity();
  bool found = false;
  // Projection of p on the segment from contact k toward its neighbour j
  // (unclamped); NaN when there is no such segment.
  auto along = [&](std::size_t k, std::size_t j) {
    if (j >= to.size() || !to[j].valid || to[j].at.face != to[k].at.face) return std::nan("");
    const Eigen::Vector2d ab = to[j].at.point.head<2>() - to[k].at.point.head<2>();
    const double len2 = ab.squaredNorm();
    return len2 > 0 ? (p - to[k].at.point.head<2>()).dot(ab) / len2 : std::nan("");
  };
  for (std::size_t k = 0; k < to.size(); ++k) {
    if (!to[k].valid) continue;
    const double dk = (to[k].at.point.head<2>() - p).norm();
    if (dk < distance) {
      // A contact with a segment on one side only is an end of the pass.
      const double next = along(k, k + 1), previous = k > 0 ? along(k, k - 1) : std::nan("");
      const bool end = std::isnan(next) != std::isnan(previous);
      const double outward = std::isnan(next) ? previous : next;
      distance = dk, out = {to[k].at, k, 0.0, end && outward < -1e-9}, found = true;
    }
    const double t = along(k, k + 1);
    if (!(t > 0 && t < 1)) continue;
    const SurfacePoint& a = to[k].at;
    const SurfacePoint& b = to[k + 1].at;
    const double d = (a.point.head<2>() + t * (b.point.head<2>() - a.point.head<2>()) - p).norm();
    if (d < distance) {
      auto at = [&](double tt) { return surface_point(part, a.face, a.uv + tt * (b.uv - a.uv)); };
      const ScalarSearchResult r = minimize_unimodal(
          [&](double tt) {
            const SurfacePoint q = at(tt);
            return q.valid ? (q.point - from.point).squaredNorm() : std::numeric_limits<double>::infinity();
          },
          0.0, 1.0, {1e-10, 100});
      const double best = r.x > 0 && r.x < 1 && std::isfinite(r.value) ? r.x : t;
      out = {at(best), k, best, false};
      distance = d;
      found = true;
    }
  }
  return found;
}

// Where the cutter of `pass` stands at a point of it (the header): the
// path's tip at a contact, else the exact location moved by the contacts'
// interpolated offsets. False when the point cannot be reached from above.
bool tip_at(const Cutter& cutter, const std::vector<PathContact>& pass, const PassPoint& q,
            const CutterLocationOptions& options, Eigen::Vector3d& tip) {
  if (q.t == 0) {
    tip = pass[q.k].tip;
    return true;
  }
  const CutterLocation here = cutter_location(cutter, q.at.point, q.at.normal, options);
  const CutterLocation a = cutter_location(cutter, pass[q.k].at.point, pass[q.k].at.normal, options);
  const CutterLocation b = cutter_location(cutter, pass[q.k + 1].at.point, pass[q.k + 1].at.normal, options);
  if (!here.reachable || !a.reachable || !b.reachable) return false;
  tip = here.tip + (1 - q.t) * (pass[q.k].tip - a.tip) + q.t * (pass[q.k + 1].tip - b.tip);
  return true;
}

// Two cutters standing at tips a and b: the lower envelope of the two as a
// height function (+infinity where neither is above).
struct TwoCutters {
  const Cutter& cutter;
  Eigen::Vector3d a, b;
  double operator()(double x, double y) const {
    return std::min(a.z() + cutter.height_at(std::hypot(x - a.x(), y - a.y())),
                    b.z() + cutter.height_at(std::hypot(x - b.x(), y - b.y())));
  }
};

// The largest of error_at over lambda in [0, 1] (kNone where undefined):
// sampled with n + 1 points, the best refined by Brent's method between its
// neighbours. Adds it to `peak` when it is the largest so far.
template <class Error>
void raise_peak(const SurfaceCurve& curve, int n, double tolerance, const Error& error_at, ScallopPeak& peak) {
  int best_k = -1;
  double best = kNone;
  for (int k = 0; k <= n; ++k) {
    const double e = error_at(double(k) / n);
    if (e > best) best = e, best_k = k;
  }
  if (best_k < 0) return;
  const double lo = double(std::max(best_k - 1, 0)) / n, hi = double(std::min(best_k + 1, n)) / n;
  const ScalarSearchResult r = minimize_unimodal([&](double l) { return -error_at(l); }, lo, hi, {tolerance, 100});
  double lambda = double(best_k) / n;
  if (-r.value > best) best = -r.value, lambda = r.x;
  if (!peak.found || best > peak.height) {
    peak.found = true;
    peak.height = best;
    peak.at = curve(lambda);
  }
}

}  // namespace

PathContact exact_contact(const Cutter& cutter, const SurfacePoint& at, const CutterLocationOptions& options) {
  PathContact c;
  if (!at.valid) return c;
  const CutterLocation loc = cutter_location(cutter, at.point, at.normal, options);
  if (!loc.reachable) return c;
  c.valid = true;
  c.at = at;
  c.tip = loc.tip;
  return c;
}

std::vector<PassScallop> pass_pair_scallops(const VerticalProjector& projector, const ZMap& zmap,
                                            const Cutter& cutter,
                                            const std::vector<std::vector<PathContact>>& passes,
                                            const PassScallopOptions& options) {
  const Part& part = projector.part();
  const double spacing = options.sample_spacing > 0 ? options.sample_spacing : 0.5 * zmap.cell();
  const double reach = options.max_pass_distance > 0 ? options.max_pass_distance : cutter.diameter();
  std::vector<PassScallop> result;
  for (std::size_t a = 0; a + 1 < passes.size(); ++a) {
    PassScallop pair;
    pair.pass_a = static_cast<int>(a);
    pair.pass_b = static_cast<int>(a + 1);
    // Cross-section starts: contacts and mid-steps of pass a.
    std::vector<PassPoint> starts;
    const auto& pa = passes[a];
    for (std::size_t k = 0; k < pa.size(); ++k) {
      if (!pa[k].valid) continue;
      starts.push_back({pa[k].at, k, 0.0});
      if (k + 1 < pa.size() && pa[k + 1].valid && pa[k + 1].at.face == pa[k].at.face) {
        const SurfacePoint mid =
            surface_point(part, pa[k].at.face, 0.5 * (pa[k].at.uv + pa[k + 1].at.uv));
        if (mid.valid) starts.push_back({mid, k, 0.5});
      }
    }
    for (const PassPoint& s : starts) {
      PassPoint end;
      double distance = 0;
      if (!nearest_on_pass(part, passes[a + 1], s.at, end, distance) || distance > reach || !end.at.valid) continue;
      const SurfaceCurve curve = s.at.face == end.at.face
                                     ? iso_parametric_curve(part, s.at.face, s.at.uv, end.at.uv)
                                     : vertical_section_curve(projector, s.at, end.at);
      const double length = (end.at.point - s.at.point).norm();
      const int n = std::max(4, static_cast<int>(std::ceil(length / spacing)));
      const double tolerance = options.refine_tolerance / std::max(length, 1e-9);
      // The section's points where an error is defined: on the part, facing up.
      auto usable = [&](const SurfacePoint& p) {
        return p.valid && p.normal.z() >= 0 && part.faces[p.face].contains(p.uv.x(), p.uv.y());
      };
      raise_peak(curve, n, tolerance, [&](double lambda) {
        const SurfacePoint p = curve(lambda);
        if (!usable(p)) return kNone;
        const NormalError e = zmap_error(zmap, p.point, p.normal, options.normal);
        return e.reached ? e.error : kNone;
      }, pair.ridge);
      // The cusp belongs to the side step: a section that meets the next
      // pass beyond its end measures where the passes stop, not how far
      // apart they are.
      TwoCutters stamps{cutter, {}, {}};
      if (!end.beyond_end && tip_at(cutter, pa, s, options.location, stamps.a) &&
          tip_at(cutter, passes[a + 1], end, options.location, stamps.b)) {
        NormalErrorOptions normal = options.normal;
        // Bounds of the two cutters, so that a deep overcut is measured too.
        const Eigen::Vector2d r = Eigen::Vector2d::Constant(cutter.radius());
        Eigen::AlignedBox2d shadow(stamps.a.head<2>() - r, stamps.a.head<2>() + r);
        shadow.extend(Eigen::AlignedBox2d(stamps.b.head<2>() - r, stamps.b.head<2>() + r));
        normal = with_height_bounds(normal, std::min(stamps.a.z(), stamps.b.z()), shadow);
        raise_peak(curve, n, tolerance, [&](double lambda) {
          const SurfacePoint p = curve(lambda);
          if (!usable(p)) return kNone;
          const NormalError e = normal_error(stamps, p.point, p.normal, normal);
          return e.reached ? e.error : kNone;
        }, pair.cusp);
      }
      ++pair.cross_sections;
    }
    result.push_back(pair);
  }
  return result;
}

}  // namespace furrow
