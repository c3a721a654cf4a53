#pragma once
// Recognising the elementary surface a NURBS patch exactly is: a plane,
// cylinder, cone, sphere or torus, with its parameters (docs/formats.md
// "Analytic surfaces").
//
// Why: CAD files often carry a cylinder or a torus as a B-spline or a surface
// of revolution; a metrologist wants the radius and axis in the report, and
// the planner and the report can name a bore a bore. The recognised surface
// is metadata only: every computation keeps using the exact NURBS.
//
// How: points and normals sampled on a grid over the patch's parameter
// rectangle. A plane has one normal. Every other candidate is a surface of
// revolution, whose normal lines all meet its axis; the axis is the line
// whose Plücker coordinates are the null vector of that condition (a 6 x 6
// eigenproblem), or, for a cylinder, the common perpendicular of the normals.
// In the axis frame each point has a radius r and a height h, and the
// meridian decides: r constant (cylinder), r linear in h (cone), a circle
// centred on the axis (sphere) or off it (torus). A candidate is accepted
// only when every sample of a second, finer grid lies within `tolerance` of
// it (a true distance, not an algebraic residual), so a perturbed patch is
// not recognised.
//
// Conventions: millimetres and radians; `axis` is a unit vector with its
// largest component positive (so the same surface gives the same numbers
// whatever its parameterisation); a plane's axis is its normal, in the same
// convention.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

struct AnalyticSurface {
  enum class Type { plane, cylinder, cone, sphere, torus };
  Type type = Type::plane;
  // plane: a point of it (nearest the patch's sample centroid); cylinder:
  // the axis point nearest that centroid; cone: apex; sphere, torus: centre.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radius = 0;        // cylinder, sphere; torus: major radius
  double minor_radius = 0;  // torus (tube)
  double half_angle = 0;    // cone, radians in (0, pi/2)
  double deviation = 0;     // largest distance of the check samples [mm]
};

const char* to_string(AnalyticSurface::Type type);
// Inverse of to_string; nullopt for another name.
std::optional<AnalyticSurface::Type> analytic_type_from_string(const std::string& name);

// Grid sizes of the fit and of the check, per direction.
constexpr int kAnalyticFitGrid = 12;
constexpr int kAnalyticCheckGrid = 23;
// Default acceptance: rounding of an exact conversion, far below anything
// measurable; a fitted B-spline approximation is not "exactly" a cylinder.
constexpr double kAnalyticTolerance = 1e-7;  // mm

// Unset when no candidate is within `tolerance` (or the patch has too many
// degenerate samples to tell).
std::optional<AnalyticSurface> recognise_analytic(const NurbsSurface& surface, double tolerance = kAnalyticTolerance);

// One line for people: "cylinder, radius 12.5 mm, axis (0, 0, 1) through
// (10, 20, 0)" (lengths in mm with up to 9 significant digits).
std::string describe(const AnalyticSurface& s);

// Distance of p from the analytic surface [mm] (the full surface, unbounded).
double analytic_distance(const AnalyticSurface& s, const Eigen::Vector3d& p);

}  // namespace furrow
