#include "machining/prediction/surface_curve.hpp"

#include <cmath>

namespace furrow {

SurfaceCurve iso_parametric_curve(const Part& part, int face, const Eigen::Vector2d& uv0,
                                  const Eigen::Vector2d& uv1) {
  return [&part, face, uv0, uv1](double lambda) {
    return surface_point(part, face, uv0 + lambda * (uv1 - uv0));
  };
}

SurfaceCurve vertical_section_curve(const VerticalProjector& projector, const SurfacePoint& from,
                                    const SurfacePoint& to) {
  if (!from.valid || !to.valid) return [](double) { return SurfacePoint{}; };
  const Eigen::Vector2d a = from.point.head<2>(), b = to.point.head<2>();
  if ((b - a).norm() < 1e-9 && from.face == to.face)
    return iso_parametric_curve(projector.part(), from.face, from.uv, to.uv);
  return [&projector, from, to, a, b](double lambda) {
    if (lambda <= 0) return from;
    if (lambda >= 1) return to;
    const Eigen::Vector2d xy = a + lambda * (b - a);
    SurfacePoint hint = lambda < 0.5 ? from : to;
    if (from.face == to.face) hint.uv = from.uv + lambda * (to.uv - from.uv);
    return projector.project(xy.x(), xy.y(), &hint);
  };
}

}  // namespace furrow
