#pragma once
// Which rigid motions a set of surface points constrains
// (docs/registration.md "Weakly constrained directions").
//
// A best fit measures only the distance along each point's normal. A rigid
// motion p = (w, t) (rotation vector about the part origin [rad],
// translation [mm]) moves a point x by w x x + t, of which only
// n . (w x x + t) shows in the residual. Over the points:
//   H = sum (J_i p)^2       the information: normal displacement squared,
//   G = sum |w x x_i + t|^2 the size of the motion: all displacement squared.
// The generalised eigenvalues of H v = lambda G v are the share (0..1) of a
// motion's displacement that the residuals see. They need no scale between
// rotations and translations and do not depend on where the origin is: a
// rotation is as large as the displacement it causes at the points. On a
// plane, sliding in the plane and turning about its normal have lambda = 0;
// on a cylinder, sliding along and turning about its axis; on a sphere, the
// three rotations about its centre.
//
// A direction is *weak* when its lambda is below `weak_ratio` times the
// largest. Registration holds weak directions at their start (registration.hpp)
// so that noise and edge effects cannot slide the part off the measured
// surface through them; the report names them in words.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace furrow {

using MotionBasis = Eigen::Matrix<double, 6, Eigen::Dynamic>;

// Below this share of the largest (ratio) a motion is not seen at all: an
// exact symmetry of the measured surface, whose computed information is
// round-off.
constexpr double kUnseenRatio = 1e-8;

struct WeakDirection {
  // The motion per 1 mm RMS displacement of the points: rx ry rz [rad]
  // (about the part origin), tx ty tz [mm].
  Eigen::Matrix<double, 6, 1> parameters = Eigen::Matrix<double, 6, 1>::Zero();
  bool translation = false;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // translation direction or rotation axis (unit)
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();  // rotation: the axis point nearest the points' centroid
  double pitch = 0;      // rotation: advance along the axis [mm per rad]
  double lever = 0;      // rotation: RMS distance of the points from the axis [mm]
  double ratio = 0;      // lambda / largest lambda
  double information = 0;  // sum of squared normal displacements of this motion [mm^2]
  // Weak for these points only: a dense sample of the measured faces
  // constrains it (more or better spread points would fix it).
  bool from_points = false;
  // Not fitted: held where the coarse start put it (set by registration.hpp).
  bool held = false;

  // "translation along (0.71, 0.71, 0.00)" or "rotation about the axis
  // through (x, y, z) mm along (a, b, c)".
  std::string describe() const;
  // 1-sigma of the motion for a residual standard deviation `sigma` [mm]:
  // the points' RMS displacement [mm]. Infinity when nothing constrains it:
  // no information, or a share below kUnseenRatio (round-off of an exact
  // symmetry, whose "sigma" would be a meaningless 1e13 mm).
  double sigma_mm(double sigma) const;
};

struct Observability {
  std::vector<WeakDirection> weak;  // weakest first
  MotionBasis constrained;          // the other directions (columns, origin parameters)
  std::vector<double> ratios;       // every lambda / largest, ascending
  double weak_ratio = 0;
  MotionBasis allowed;              // the motions analysed
};

// The motions allowed by `allowed` (6 x m columns of origin parameters,
// e.g. the unit vectors of the free degrees of freedom) analysed over the
// points `x` with outward normals `n` (same size). Fewer than one point, or
// points that no allowed motion moves, leave every direction weak.
// weak_ratio must lie in (0, 1).
Observability analyse_observability(const std::vector<Eigen::Vector3d>& x,
                                    const std::vector<Eigen::Vector3d>& n, const MotionBasis& allowed,
                                    double weak_ratio);

// Tells apart, among the weak directions of `points` (analysed over
// `point_x`, `point_n`), those that the surface itself leaves free from
// those that only the points do: a surface sample (`surface_x`,
// `surface_n`: a grid over the measured faces) constrains a motion of the
// weak subspace when its lambda over the sample is at least weak_ratio times
// the sample's largest. The weak directions are re-chosen so that the ones
// the surface fixes are separate, and those get `from_points`.
void mark_weak_by_points(Observability& points, const std::vector<Eigen::Vector3d>& point_x,
                         const std::vector<Eigen::Vector3d>& point_n, const std::vector<Eigen::Vector3d>& surface_x,
                         const std::vector<Eigen::Vector3d>& surface_n);

// The unit vectors of the free parameters (locked ones left out).
MotionBasis free_parameter_basis(const std::array<bool, 6>& free);

}  // namespace furrow
