#pragma once
// A design-surface curve between two contact points, parametrised by
// lambda in [0, 1] (lambda = 0 and 1 are the contact points): the curve the
// per-step predictor evaluates the machining error on, and the one contact
// planning steps along.
//
// Two kinds, matching the two ways a finishing path follows a surface:
//   - iso-parametric: a straight line in (u, v) on one face (an iso-curve
//     when u or v is constant);
//   - vertical section: the surface under the straight horizontal line
//     between the two contact points (the section by the vertical plane
//     through them, which is the plane a 3-axis move lies in); may cross
//     from one face to another.
// A sample is invalid where the surface is degenerate or, for a section,
// where no face lies under the line.
#include <functional>

#include "machining/cutter/vertical_projection.hpp"

namespace furrow {

using SurfaceCurve = std::function<SurfacePoint(double lambda)>;

// The part must outlive the curve.
SurfaceCurve iso_parametric_curve(const Part& part, int face, const Eigen::Vector2d& uv0,
                                  const Eigen::Vector2d& uv1);

// Between two surface points (an invalid one gives a curve of invalid
// samples). Falls back to the iso-parametric line
// when the two points are (almost) vertically above each other on one face.
// The projector must outlive the curve.
SurfaceCurve vertical_section_curve(const VerticalProjector& projector, const SurfacePoint& from,
                                    const SurfacePoint& to);

}  // namespace furrow
