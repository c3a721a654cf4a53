#include "machining/compensation/path_offset.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "base/error.hpp"

namespace furrow {

namespace {

// The surface gradient of a scalar with parameter derivatives g = (g_u, g_v):
// the tangent vector (S_u, S_v) G^-1 g. Zero at a degenerate point.
Eigen::Vector3d surface_gradient(const Face& face, const Eigen::Vector2d& uv, const Eigen::Vector2d& g) {
  const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 1);
  Eigen::Matrix2d G;
  G << d.Su.dot(d.Su), d.Su.dot(d.Sv), d.Su.dot(d.Sv), d.Sv.dot(d.Sv);
  const double det = G.determinant();
  if (!(std::abs(det) > 1e-12 * G(0, 0) * G(1, 1))) return Eigen::Vector3d::Zero();
  const Eigen::Vector2d c = G.inverse() * g;
  return c.x() * d.Su + c.y() * d.Sv;
}

// The compensated surface's curvature at a point moved by d along the
// normal: each principal curvature k becomes k / (1 - d k) (header). False
// when 1 - d k <= 0: the offset surface folds over there (d beyond the
// concave radius), which no cutter can follow.
bool offset_geometry(const DifferentialGeometry& nominal, double d, DifferentialGeometry& moved) {
  moved = nominal;
  for (double* k : {&moved.k1, &moved.k2}) {
    const double scale = 1 - d * *k;
    if (!(scale > 0)) return false;
    *k /= scale;
  }
  moved.H = (moved.k1 + moved.k2) / 2, moved.K = moved.k1 * moved.k2;
  return true;
}

bool gouges_at(const Cutter& cutter, const DifferentialGeometry& nominal, double d, const GougeOptions& options) {
  DifferentialGeometry moved;
  return !offset_geometry(nominal, d, moved) || check_local_gouge(cutter, moved, options).gouges();
}

}  // namespace

PathOffset offset_path(const Part& part, const PathTools& tools, const PathGeometry& geometry,
                       const ErrorField& field, const PathOffsetOptions& o) {
  if (!(std::isfinite(o.gain) && o.gain > 0 && o.gain <= 2))
    throw InputError("compensation gain: must be in (0, 2], got " + std::to_string(o.gain));
  if (!(std::isfinite(o.max_offset) && o.max_offset > 0))
    throw InputError("compensation max_offset: must be positive, got " + std::to_string(o.max_offset));
  if (o.gouge_iterations < 0 || o.gouge_iterations > 200)
    throw InputError("compensation gouge_iterations: must be in [0, 200], got " + std::to_string(o.gouge_iterations));
  // Passes in parallel, each into its own record; merged in pass order
  // afterwards, so the lists and counts do not depend on the threads.
  const std::size_t passes = geometry.passes.size();
  std::vector<PathOffset> per_pass(passes);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::ptrdiff_t signed_p = 0; signed_p < std::ptrdiff_t(passes); ++signed_p) {
    const std::size_t p = std::size_t(signed_p);
    PathOffset& out = per_pass[p];
    out.tips.resize(1);
    out.offsets.resize(1);
    out.tilts.resize(1);
    const Cutter& cutter = tools.cutters[std::size_t(tools.of_pass[p])];
    for (std::size_t k = 0; k < geometry.passes[p].size(); ++k) {
      const PathPoint& pt = geometry.passes[p][k];
      out.tips[0].push_back(pt.tip);
      out.offsets[0].push_back(0.0);
      out.tilts[0].push_back(Eigen::Vector3d::Zero());
      if (!pt.contact.valid) {
        ++out.no_contact;
        continue;
      }
      if (pt.in_air) {
        ++out.in_air;
        continue;
      }
      const SurfacePoint& at = pt.contact.at;
      const std::size_t f = std::size_t(at.face);
      if (f >= field.faces.size() || !field.faces[f]) continue;
      const FieldValue e = field.faces[f]->at(at.uv.x(), at.uv.y());
      OffsetPoint record{p, k, pt.line, -o.gain * e.value, 0.0};
      record.applied = std::clamp(record.requested, -o.max_offset, o.max_offset);
      bool clipped = record.applied != record.requested;
      if (clipped) out.clipped.push_back(record);
      if (record.applied == 0) continue;  // nothing to move (outside the field)
      if (o.check_gouge) {
        GougeOptions gouge = o.gouge;
        gouge.location = o.location;
        const DifferentialGeometry nominal = part.faces[f].geometry(at.uv.x(), at.uv.y());
        if (!nominal.degenerate && !check_local_gouge(cutter, nominal, gouge).gouges() &&
            gouges_at(cutter, nominal, record.applied, gouge)) {
          double safe = 0, unsafe = record.applied;  // bisection keeps safe clear, unsafe gouging
          for (int i = 0; i < o.gouge_iterations; ++i) {
            const double mid = 0.5 * (safe + unsafe);
            (gouges_at(cutter, nominal, mid, gouge) ? unsafe : safe) = mid;
          }
          OffsetPoint cut_back = record;
          cut_back.applied = safe;
          out.gouge_clipped.push_back(cut_back);
          record.applied = safe;
          clipped = true;
        }
      }
      // The compensated surface's normal (header): tilted against the
      // offset's slope, unless clipped (the offset is flat there).
      Eigen::Vector3d normal = at.normal;
      if (!clipped) normal -= surface_gradient(part.faces[f], at.uv, -o.gain * e.gradient);
      const CutterLocation before = cutter_location(cutter, at.point, at.normal, o.location);
      const CutterLocation after =
          cutter_location(cutter, at.point + record.applied * at.normal, normal, o.location);
      if (!before.reachable || !after.reachable) {
        out.unreachable.push_back(record);
        continue;
      }
      out.tips[0][k] = pt.tip + (after.tip - before.tip);
      out.offsets[0][k] = record.applied;
      out.tilts[0][k] = normal - at.normal;
      out.largest_offset = std::max(out.largest_offset, std::abs(record.applied));
      ++out.moved;
    }
  }
  PathOffset out;
  for (PathOffset& one : per_pass) {
    out.tips.push_back(std::move(one.tips[0]));
    out.offsets.push_back(std::move(one.offsets[0]));
    out.tilts.push_back(std::move(one.tilts[0]));
    out.clipped.insert(out.clipped.end(), one.clipped.begin(), one.clipped.end());
    out.gouge_clipped.insert(out.gouge_clipped.end(), one.gouge_clipped.begin(), one.gouge_clipped.end());
    out.unreachable.insert(out.unreachable.end(), one.unreachable.begin(), one.unreachable.end());
    out.moved += one.moved, out.no_contact += one.no_contact, out.in_air += one.in_air;
    out.largest_offset = std::max(out.largest_offset, one.largest_offset);
  }
  return out;
}

void reduce_offset(PathOffset& offset, const Cutter& cutter, const PathGeometry& geometry, std::size_t pass,
                   std::size_t point, double factor, const CutterLocationOptions& location) {
  const PathPoint& pt = geometry.passes.at(pass).at(point);
  double& d = offset.offsets.at(pass).at(point);
  Eigen::Vector3d& tilt = offset.tilts.at(pass).at(point);
  d *= factor;
  tilt *= factor;
  const SurfacePoint& at = pt.contact.at;
  const CutterLocation before = cutter_location(cutter, at.point, at.normal, location);
  const CutterLocation after = cutter_location(cutter, at.point + d * at.normal, at.normal + tilt, location);
  if (before.reachable && after.reachable) {
    offset.tips[pass][point] = pt.tip + (after.tip - before.tip);
  } else {  // not for a point offset_path moved; kept safe all the same
    offset.tips[pass][point] = pt.tip;
    d = 0;
    tilt.setZero();
  }
  offset.largest_offset = 0;
  for (const auto& one : offset.offsets)
    for (double o : one) offset.largest_offset = std::max(offset.largest_offset, std::abs(o));
}

}  // namespace furrow
