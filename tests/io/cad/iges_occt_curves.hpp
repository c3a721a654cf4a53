#pragma once
// Model-space curves for the tests' IGES writer (iges_writer.hpp) that are
// not conics: closed loops interpolated by OpenCASCADE, written as type 126
// rational B-splines. The curve runs through every given point; between
// them it is a periodic cubic, within ~1e-7 mm of the smooth curve the
// points sample for the loops the tests draw (a few mm across, 128 points).
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <gp_Pnt.hxx>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "iges_writer.hpp"

namespace furrow::test {

// The closed periodic cubic through `points` (in running order, the first
// not repeated at the end) as a type 126; returns its DE pointer.
inline int write_interpolated_loop(IgesBuilder& b, const std::vector<Eigen::Vector3d>& points) {
  Handle(TColgp_HArray1OfPnt) through = new TColgp_HArray1OfPnt(1, static_cast<int>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k)
    through->SetValue(static_cast<int>(k) + 1, gp_Pnt(points[k].x(), points[k].y(), points[k].z()));
  GeomAPI_Interpolate interpolate(through, Standard_True, 1e-9);
  interpolate.Perform();
  if (!interpolate.IsDone()) throw std::runtime_error("interpolation failed");
  const Handle(Geom_BSplineCurve) curve = Handle(Geom_BSplineCurve)::DownCast(interpolate.Curve()->Copy());
  curve->SetNotPeriodic();  // IGES 126 is clamped
  std::vector<double> knots;
  std::vector<int> multiplicities;
  for (int k = 1; k <= curve->NbKnots(); ++k) {
    knots.push_back(curve->Knot(k));
    multiplicities.push_back(curve->Multiplicity(k));
  }
  std::vector<Eigen::Vector3d> poles;
  std::vector<double> weights;
  for (int k = 1; k <= curve->NbPoles(); ++k) {
    const gp_Pnt q = curve->Pole(k);
    poles.emplace_back(q.X(), q.Y(), q.Z());
    weights.push_back(curve->Weight(k));
  }
  return b.bspline_flat(curve->Degree(), knots, multiplicities, poles, weights);
}

// A circle of radius `rho` [mm] drawn on a cylinder unrolled: the cylinder's
// point at (angle, height) is `point`, its radius `radius`; the loop is
// angle = angle_c + rho/radius cos t, height = height_c + rho sin t, which
// encloses exactly pi rho^2 on the cylinder (unrolling keeps areas).
// Counterclockwise in (angle, height) unless `reversed`. 128 points.
inline int write_unrolled_circle(IgesBuilder& b, const std::function<Eigen::Vector3d(double, double)>& point,
                                 double radius, double angle_c, double height_c, double rho, bool reversed) {
  constexpr int kPoints = 128;
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < kPoints; ++k) {
    const double t = (reversed ? -1.0 : 1.0) * 2 * M_PI * k / kPoints;
    points.push_back(point(angle_c + rho / radius * std::cos(t), height_c + rho * std::sin(t)));
  }
  return write_interpolated_loop(b, points);
}

}  // namespace furrow::test
