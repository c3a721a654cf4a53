#include "machining/toolpath/pass_curve.hpp"

#include <memory>

namespace furrow {

PassCurve iso_parametric_pass(const Part& part, int face, bool along_u, double level, double t0, double t1) {
  PassCurve c;
  c.t0 = t0;
  c.t1 = t1;
  auto uv = [along_u, level](double t) { return along_u ? Eigen::Vector2d(t, level) : Eigen::Vector2d(level, t); };
  c.at = [&part, face, uv](double t) { return surface_point(part, face, uv(t)); };
  c.between = [&part, face, uv](double a, double b) { return iso_parametric_curve(part, face, uv(a), uv(b)); };
  return c;
}

PassCurve iso_planar_pass(const VerticalProjector& projector, const Eigen::Vector2d& origin,
                          const Eigen::Vector2d& direction, double t0, double t1) {
  PassCurve c;
  c.t0 = t0;
  c.t1 = t1;
  auto last = std::make_shared<SurfacePoint>();
  c.at = [&projector, origin, direction, last](double t) {
    const Eigen::Vector2d xy = origin + t * direction;
    const SurfacePoint p = projector.project(xy.x(), xy.y(), last->valid ? last.get() : nullptr);
    if (p.valid) *last = p;
    return p;
  };
  c.between = [&projector, at = c.at](double a, double b) { return vertical_section_curve(projector, at(a), at(b)); };
  return c;
}

}  // namespace furrow
