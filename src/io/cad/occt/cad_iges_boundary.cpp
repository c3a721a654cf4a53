// What an IGES file says about a face's outer boundary (contract in
// cad_iges_boundary.hpp).
#include "io/cad/occt/cad_iges_boundary.hpp"

#include <IGESData_IGESEntity.hxx>
#include <IGESGeom_BSplineCurve.hxx>
#include <IGESGeom_CircularArc.hxx>
#include <IGESGeom_CompositeCurve.hxx>
#include <IGESGeom_CopiousData.hxx>
#include <IGESGeom_CurveOnSurface.hxx>
#include <IGESGeom_Line.hxx>
#include <IGESGeom_SurfaceOfRevolution.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_XY.hxx>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "base/numbers.hpp"

namespace furrow::cad {

namespace {

// Point of an IGES rational B-spline (type 126) at t, x and y only (de Boor
// on the homogeneous poles; knots are numbered from -degree in OpenCASCADE).
gp_XY iges_bspline_point(const Handle(IGESGeom_BSplineCurve)& c, double t) {
  const int p = c->Degree(), n = c->UpperIndex();
  auto knot = [&](int i) { return c->Knot(i - p); };  // i = 0 .. n + p + 1
  int k = p;
  while (k < n && t >= knot(k + 1)) ++k;
  const bool polynomial = c->IsPolynomial();
  std::vector<Eigen::Vector3d> d(static_cast<std::size_t>(p + 1));
  for (int j = 0; j <= p; ++j) {
    const double w = polynomial ? 1.0 : c->Weight(k - p + j);
    const gp_Pnt q = c->Pole(k - p + j);
    d[static_cast<std::size_t>(j)] = {w * q.X(), w * q.Y(), w};
  }
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = k - p + j;
      const double span = knot(i + p - r + 1) - knot(i);
      const double alpha = span > 0 ? (t - knot(i)) / span : 0.0;
      d[static_cast<std::size_t>(j)] =
          (1 - alpha) * d[static_cast<std::size_t>(j - 1)] + alpha * d[static_cast<std::size_t>(j)];
    }
  const Eigen::Vector3d& h = d[static_cast<std::size_t>(p)];
  return {h.x() / h.z(), h.y() / h.z()};
}

// Points along an IGES parameter-space curve, in the surface's (u,v), for
// the curve types CAD systems write there (102 of 100/106/110/126). False
// for anything else, or a curve moved by a transformation matrix.
bool sample_parameter_curve(const Handle(IGESData_IGESEntity)& curve, std::vector<gp_XY>& points, int depth) {
  constexpr int kSamples = 32;
  if (curve.IsNull() || depth > 8 || curve->HasTransf()) return false;
  if (const auto composite = Handle(IGESGeom_CompositeCurve)::DownCast(curve); !composite.IsNull()) {
    for (int i = 1; i <= composite->NbCurves(); ++i)
      if (!sample_parameter_curve(composite->Curve(i), points, depth + 1)) return false;
    return composite->NbCurves() > 0;
  }
  if (const auto line = Handle(IGESGeom_Line)::DownCast(curve); !line.IsNull()) {
    points.push_back({line->StartPoint().X(), line->StartPoint().Y()});
    points.push_back({line->EndPoint().X(), line->EndPoint().Y()});
    return true;
  }
  if (const auto arc = Handle(IGESGeom_CircularArc)::DownCast(curve); !arc.IsNull()) {
    // Counterclockwise from the start to the end point (IGES type 100).
    const gp_XY c = arc->Center().XY(), a = arc->StartPoint().XY() - c, b = arc->EndPoint().XY() - c;
    const double a0 = std::atan2(a.Y(), a.X());
    double a1 = std::atan2(b.Y(), b.X());
    while (a1 <= a0) a1 += 2 * kPi;
    const double radius = a.Modulus();
    for (int k = 0; k <= kSamples; ++k) {
      const double angle = a0 + (a1 - a0) * k / kSamples;
      points.push_back(c + radius * gp_XY(std::cos(angle), std::sin(angle)));
    }
    return true;
  }
  if (const auto data = Handle(IGESGeom_CopiousData)::DownCast(curve); !data.IsNull()) {
    for (int i = 1; i <= data->NbPoints(); ++i) points.push_back({data->Point(i).X(), data->Point(i).Y()});
    return data->NbPoints() > 0;
  }
  if (const auto spline = Handle(IGESGeom_BSplineCurve)::DownCast(curve); !spline.IsNull()) {
    const double t0 = spline->UMin(), t1 = spline->UMax();
    for (int k = 0; k <= kSamples; ++k) points.push_back(iges_bspline_point(spline, t0 + (t1 - t0) * k / kSamples));
    return true;
  }
  return false;
}

}  // namespace

FileBoundary file_boundary(const Handle(IGESGeom_TrimmedSurface)& trimmed) {
  FileBoundary boundary;
  if (trimmed.IsNull() || !trimmed->HasOuterContour()) return boundary;
  const Handle(IGESGeom_CurveOnSurface) contour = trimmed->OuterContour();
  if (contour.IsNull()) return boundary;
  const Handle(IGESData_IGESEntity) surface = trimmed->Surface();
  const auto revolution = Handle(IGESGeom_SurfaceOfRevolution)::DownCast(surface);
  if (!revolution.IsNull()) boundary.surface_rotation = revolution->EndAngle() - revolution->StartAngle();
  boundary.model_space_only = contour->CurveUV().IsNull();
  std::vector<gp_XY> points;
  if (!sample_parameter_curve(contour->CurveUV(), points, 0) || points.size() < 3) return boundary;
  double twice_area = 0, u0 = points[0].X(), u1 = u0, v0 = points[0].Y(), v1 = v0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const gp_XY& a = points[k];
    const gp_XY& b = points[(k + 1) % points.size()];
    twice_area += a.X() * b.Y() - b.X() * a.Y();
    u0 = std::min(u0, a.X()), u1 = std::max(u1, a.X()), v0 = std::min(v0, a.Y()), v1 = std::max(v1, a.Y());
  }
  if (!(std::abs(twice_area) > 1e-9 * (u1 - u0) * (v1 - v0))) return boundary;
  boundary.sense = twice_area > 0 ? 1 : -1;
  if (!revolution.IsNull()) boundary.rotation_extent = v1 - v0;
  return boundary;
}

}  // namespace furrow::cad
