#pragma once
// Local differential geometry of a surface point: normal, fundamental forms,
// Gaussian and mean curvature, principal curvatures and directions.
//
// Sign convention (docs/architecture.md): the normal n points out of the material, into
// the air. Normal curvature k_n(t) = II(t)/I(t) with L = Suu.n, M = Suv.n,
// N = Svv.n, so a dome seen from the air has negative curvatures (convex =>
// H < 0). k1 >= k2; K = k1 k2; H = (k1 + k2) / 2.
//
// Degenerate points (|Su x Sv| negligible against the parametrisation's own
// scale, e.g. a collapsed edge or a pole) are flagged `degenerate` with all
// curvature fields zero; callers must check the flag. At umbilics (k1 == k2)
// the principal directions are still an orthonormal tangent frame.
#include <Eigen/Core>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

struct DifferentialGeometry {
  bool degenerate = true;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, out of the material
  double E = 0, F = 0, G = 0;                        // first fundamental form
  double L = 0, M = 0, N = 0;                        // second fundamental form (w.r.t. normal)
  double K = 0, H = 0;                               // Gaussian, mean curvature [1/mm^2, 1/mm]
  double k1 = 0, k2 = 0;                             // principal curvatures, k1 >= k2 [1/mm]
  Eigen::Vector3d d1 = Eigen::Vector3d::UnitX();     // unit 3-D principal direction of k1
  Eigen::Vector3d d2 = Eigen::Vector3d::UnitY();     // of k2; (d1, d2, normal) is right-handed
  double area_element = 0;                           // |Su x Sv| [mm^2 per unit du dv]

  // Normal curvature in the tangent direction t (any length, 3-D; the part of
  // t along the normal is ignored). Euler: k1 cos^2 a + k2 sin^2 a. Returns 0
  // at degenerate points or for a zero tangent.
  double normal_curvature(const Eigen::Vector3d& t) const;
};

// Threshold on |Su x Sv| below which a point counts as degenerate, relative to
// |Su| |Sv| or to the surface's typical derivative scale (whichever is larger):
// both a collapsed edge (Su -> 0) and parallel tangents are caught.
constexpr double kDegenerateRelativeTolerance = 1e-10;

// `reversed` flips the normal (docs/architecture.md: a face's normal is Su x Sv
// normalised, flipped when the face is reversed). `derivative_scale` is the
// typical |Su||Sv| of the surface (see typical_derivative_scale).
DifferentialGeometry differential_geometry(const SurfaceDerivatives& d, bool reversed,
                                           double derivative_scale);

// Typical |Su| |Sv| of a surface: control-box diagonal squared over the
// parameter area. Used to recognise vanishing derivatives scale-independently.
double typical_derivative_scale(const NurbsSurface& surface);

// Convenience: evaluate and analyse in one call.
DifferentialGeometry differential_geometry(const NurbsSurface& surface, double u, double v,
                                           bool reversed);

}  // namespace furrow
