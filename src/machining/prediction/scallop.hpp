#pragma once
// Scallop height between two adjacent passes of a ball end mill, and its
// inverse, the side step for a target scallop (docs/architecture.md "Machining error between contact points").
//
// The cross-section across the passes is a circle of radius rho = 1/|k| (k is
// the part's normal curvature across the path, docs/architecture.md sign: convex < 0,
// concave > 0, 0 flat); the two contact points are an arc w apart, phi =
// w / (2 rho). With ball radius r:
//   convex:  a = rho + r, d = a cos phi - sqrt(r^2 - a^2 sin^2 phi), h = d - rho
//   concave: a = rho - r, d = a cos phi + sqrt(r^2 - a^2 sin^2 phi), h = rho - d
//   flat:    h = r - sqrt(r^2 - (w/2)^2)
// These are exact for a circular cross-section; the usual small-h estimate
// w ~ sqrt(8 h r rho / (rho +- r)) is given separately for comparison only.
// Heights are material left above the design surface [mm], >= 0.
#include <optional>

namespace furrow {

struct ScallopOptions {
  double tolerance = 1e-12;  // on the side step, relative to the ball radius
  int max_iterations = 200;  // bisection steps (each halves the bracket)
};

// Height of the cusp for side step w (arc length on the surface). nullopt when
// the geometry has no cusp: a concave radius <= r (the ball does not fit: it
// gouges), or a step so wide that the two balls no longer overlap (w >= 2r on
// a flat part; the analogues on curved parts). Preconditions: r > 0, w >= 0.
std::optional<double> ball_scallop_height(double ball_radius, double curvature_across, double side_step);

struct SideStepResult {
  double side_step = 0;  // arc length [mm]
  bool converged = false;
  int iterations = 0;
  bool feasible = false;  // false: no positive step reaches the target (see above)
};

// Largest side step whose scallop does not exceed `height` (> 0), by
// bisection on the exact formula (h is increasing in w).
SideStepResult ball_side_step_for_scallop(double ball_radius, double curvature_across, double height,
                                          const ScallopOptions& options = {});

// The small-h estimate sqrt(8 h r rho / (rho + r)) (convex) or
// sqrt(8 h r rho / (rho - r)) (concave), sqrt(8 h r) when flat; for
// comparison with the exact inverse only.
double ball_side_step_estimate(double ball_radius, double curvature_across, double height);

}  // namespace furrow
