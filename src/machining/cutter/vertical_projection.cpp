#include "machining/cutter/vertical_projection.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

bool face_normal(const Face& face, double u, double v, Eigen::Vector3d& point, Eigen::Vector3d& normal) {
  return face_normal(face, face.surface().evaluate(u, v, 1), point, normal);
}

bool face_normal(const Face& face, const SurfaceDerivatives& d, Eigen::Vector3d& point,
                 Eigen::Vector3d& normal) {
  point = d.S;
  const Eigen::Vector3d c = d.Su.cross(d.Sv);
  const double len = c.norm();
  const double scale = d.Su.norm() * d.Sv.norm();
  if (!(len > 1e-12 * scale) || !(len > 0)) return false;
  normal = (face.reversed() ? -c : c) / len;
  return true;
}

SurfacePoint surface_point(const Part& part, int face, const Eigen::Vector2d& uv) {
  SurfacePoint p;
  p.face = face;
  p.uv = uv;
  p.valid = face_normal(part.faces[face], uv.x(), uv.y(), p.point, p.normal);
  return p;
}

SurfacePoint project_vertically(const Part& part, int face_index, double x, double y,
                                const Eigen::Vector2d& seed, const VerticalProjectionOptions& options) {
  const Face& face = part.faces[face_index];
  const ParameterDomain& dom = face.domain();
  Eigen::Vector2d uv(std::clamp(seed.x(), dom.u0, dom.u1), std::clamp(seed.y(), dom.v0, dom.v1));
  SurfacePoint result;
  for (int it = 0; it < options.max_iterations; ++it) {
    const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 1);
    const Eigen::Vector2d r(d.S.x() - x, d.S.y() - y);
    if (r.norm() <= options.tolerance) {
      if (!face.contains(uv.x(), uv.y())) return result;
      return surface_point(part, face_index, uv);
    }
    Eigen::Matrix2d J;
    J << d.Su.x(), d.Sv.x(), d.Su.y(), d.Sv.y();
    const double det = J.determinant();
    if (!(std::fabs(det) > 1e-14 * d.Su.squaredNorm() * d.Sv.squaredNorm() + 1e-300)) return result;
    Eigen::Vector2d step = J.inverse() * r;
    // Damp steps that would leave the domain far behind (keeps the iteration
    // on the patch; a point truly outside ends pinned at the edge and fails).
    Eigen::Vector2d next = uv - step;
    next.x() = std::clamp(next.x(), dom.u0, dom.u1);
    next.y() = std::clamp(next.y(), dom.v0, dom.v1);
    if ((next - uv).norm() == 0) return result;  // pinned at the domain edge
    uv = next;
  }
  return result;
}

VerticalProjector::VerticalProjector(const Part& part, const VerticalProjectionOptions& options)
    : part_(&part), options_(options) {
  const int n = std::max(2, options.seed_grid);
  seeds_.resize(part.faces.size());
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const ParameterDomain& dom = part.faces[f].domain();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Eigen::Vector2d uv(dom.u0 + dom.width_u() * (i + 0.5) / n, dom.v0 + dom.width_v() * (j + 0.5) / n);
        const Eigen::Vector3d p = part.faces[f].surface().point(uv.x(), uv.y());
        seeds_[f].push_back({Eigen::Vector2d(p.x(), p.y()), uv});
      }
  }
}

SurfacePoint VerticalProjector::project(double x, double y, const SurfacePoint* hint) const {
  if (hint && hint->face >= 0) {
    const SurfacePoint p = project_vertically(*part_, hint->face, x, y, hint->uv, options_);
    if (p.valid) return p;
  }
  SurfacePoint best;
  const Eigen::Vector2d target(x, y);
  for (std::size_t f = 0; f < seeds_.size(); ++f) {
    // Newton from the two nearest seeds (the nearest alone can sit across a
    // fold of the projection near the face's edge).
    std::size_t first = 0, second = 0;
    double d1 = std::numeric_limits<double>::infinity(), d2 = d1;
    for (std::size_t k = 0; k < seeds_[f].size(); ++k) {
      const double d = (seeds_[f][k].xy - target).squaredNorm();
      if (d < d1) {
        second = first, d2 = d1;
        first = k, d1 = d;
      } else if (d < d2) {
        second = k, d2 = d;
      }
    }
    for (std::size_t k : {first, second}) {
      const SurfacePoint p = project_vertically(*part_, static_cast<int>(f), x, y, seeds_[f][k].uv, options_);
      if (p.valid) {
        if (!best.valid || p.point.z() > best.point.z()) best = p;
        break;
      }
    }
  }
  return best;
}

}  // namespace furrow
