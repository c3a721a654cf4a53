#pragma once
// One finishing pass as a curve on the part, parametrised by t in [t0, t1]:
// what contact planning steps along.
//   - iso-parametric: v (or u) fixed on one face, t = u (or v);
//   - iso-planar: the section by a vertical plane, t = the horizontal
//     distance along the plane's direction from its origin (the surface
//     point under each position found by vertical projection, so the
//     section may run over several faces).
// `between(a, b)` is the design curve between the points at a and b (the
// per-step predictor's curve: the iso-curve piece, or the vertical section
// between the two points, which is the same plane).
// An iso-planar curve remembers its last surface point as the next
// projection's seed: one curve must not be shared between threads.
#include <functional>

#include "machining/prediction/surface_curve.hpp"

namespace furrow {

struct PassCurve {
  double t0 = 0, t1 = 1;
  std::function<SurfacePoint(double)> at;
  std::function<SurfaceCurve(double, double)> between;
};

// along_u: v = level, t = u in [t0, t1]; otherwise u = level, t = v.
PassCurve iso_parametric_pass(const Part& part, int face, bool along_u, double level, double t0, double t1);

// Points origin + t direction (xy; direction unit) for t in [t0, t1].
PassCurve iso_planar_pass(const VerticalProjector& projector, const Eigen::Vector2d& origin,
                          const Eigen::Vector2d& direction, double t0, double t1);

}  // namespace furrow
