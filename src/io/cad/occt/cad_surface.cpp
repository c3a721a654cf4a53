// A face's surface as a Furrow NURBS (contract in cad_surface.hpp).
#include "io/cad/occt/cad_surface.hpp"

#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <vector>

#include "io/cad/occt/cad_occt_internal.hpp"

namespace furrow::cad {

namespace {

// Grid on which every conversion is compared with the original surface.
constexpr int kCheckGrid = 13;

Conversion approximate(const Handle(Geom_Surface)& original, const ParameterDomain& b,
                       const CadImportOptions& options) {
  const Handle(Geom_Surface) piece = new Geom_RectangularTrimmedSurface(original, b.u0, b.u1, b.v0, b.v1);
  GeomConvert_ApproxSurface approx(piece, options.approximation_tolerance, GeomAbs_C2, GeomAbs_C2,
                                   options.approximation_max_degree, options.approximation_max_degree,
                                   options.approximation_max_segments, 1);
  if (!approx.HasResult())
    throw FaceFailure("its " + source_type(original) +
                      " surface has no exact NURBS form and could not be approximated");
  if (!(approx.MaxError() <= options.approximation_tolerance))
    throw FaceFailure("its " + source_type(original) + " surface could be approximated only within " +
                      number_text(approx.MaxError()) + " mm (tolerance " +
                      number_text(options.approximation_tolerance) + " mm)");
  return {approx.Surface(), false, approx.MaxError()};
}

}  // namespace

std::string source_type(const Handle(Geom_Surface)& s) {
  if (s->IsKind(STANDARD_TYPE(Geom_Plane))) return "plane";
  if (s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface))) return "cylinder";
  if (s->IsKind(STANDARD_TYPE(Geom_ConicalSurface))) return "cone";
  if (s->IsKind(STANDARD_TYPE(Geom_SphericalSurface))) return "sphere";
  if (s->IsKind(STANDARD_TYPE(Geom_ToroidalSurface))) return "torus";
  if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion))) return "extrusion";
  if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))) return "revolution";
  if (s->IsKind(STANDARD_TYPE(Geom_OffsetSurface))) return "offset";
  if (s->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) return "b-spline";
  if (s->IsKind(STANDARD_TYPE(Geom_BezierSurface))) return "bezier";
  return "other";
}

Handle(Geom_Surface) strip_trim(Handle(Geom_Surface) s) {
  for (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s); !t.IsNull();
       t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s))
    s = t->BasisSurface();
  return s;
}

std::string face_surface_type(const TopoDS_Face& face) {
  const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
  return s.IsNull() ? "no surface" : source_type(strip_trim(s));
}

NurbsSurface to_nurbs(Handle(Geom_BSplineSurface) bs, const std::string& field) {
  if (bs->IsUPeriodic() || bs->IsVPeriodic()) {
    bs = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
    if (bs->IsUPeriodic()) bs->SetUNotPeriodic();
    if (bs->IsVPeriodic()) bs->SetVNotPeriodic();
  }
  const int nu = bs->NbUPoles(), nv = bs->NbVPoles();
  TColStd_Array1OfReal ku(1, nu + bs->UDegree() + 1), kv(1, nv + bs->VDegree() + 1);
  bs->UKnotSequence(ku);
  bs->VKnotSequence(kv);
  std::vector<double> knots_u(ku.begin(), ku.end()), knots_v(kv.begin(), kv.end());
  std::vector<std::vector<Eigen::Vector3d>> net(nu, std::vector<Eigen::Vector3d>(nv));
  std::vector<std::vector<double>> weights;
  if (bs->IsURational() || bs->IsVRational()) weights.assign(nu, std::vector<double>(nv, 1.0));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      net[i][j] = to_eigen(bs->Pole(i + 1, j + 1));
      if (!weights.empty()) weights[i][j] = bs->Weight(i + 1, j + 1);
    }
  return NurbsSurface(bs->UDegree(), bs->VDegree(), std::move(knots_u), std::move(knots_v), net,
                      weights, field);
}


// Exact rational B-spline over the rectangle when OpenCASCADE has one (the
// offset of an elementary surface is converted through its equivalent
// elementary surface), an approximation otherwise.
Conversion convert_surface(const Handle(Geom_Surface)& original, const ParameterDomain& b,
                           const CadImportOptions& options) {
  Handle(Geom_Surface) exact_form = strip_trim(original);
  if (const auto offset = Handle(Geom_OffsetSurface)::DownCast(exact_form); !offset.IsNull())
    exact_form = offset->Surface();  // null when there is no elementary equivalent
  if (exact_form.IsNull() || exact_form->IsKind(STANDARD_TYPE(Geom_OffsetSurface)) ||
      source_type(exact_form) == "other")
    return approximate(original, b, options);
  try {
    if (const auto bs = Handle(Geom_BSplineSurface)::DownCast(exact_form); !bs.IsNull()) {
      auto piece = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
      piece->CheckAndSegment(b.u0, b.u1, b.v0, b.v1, 1e-9 * b.width_u(), 1e-9 * b.width_v());
      return {piece, true, 0};
    }
    const Handle(Geom_Surface) piece =
        new Geom_RectangularTrimmedSurface(exact_form, b.u0, b.u1, b.v0, b.v1);
    return {GeomConvert::SurfaceToBSplineSurface(piece), true, 0};
  } catch (const Standard_Failure&) {
    return approximate(original, b, options);
  }
}

double carry_parameters(const NurbsSurface& nurbs, const Handle(Geom_Surface)& original,
                        const ParameterDomain& bounds, bool exact, const CadImportOptions& options,
                        ParameterMap& map) {
  // The original's parametrisation is kept unless the conversion changed it.
  const ParameterMap::Evaluator evaluate = [original](double u, double v) {
    return to_eigen(original->Value(u, v));
  };
  const double allowed = exact ? options.exact_tolerance : options.approximation_tolerance;
  double deviation = max_deviation(nurbs, map, evaluate, bounds, kCheckGrid);
  if (deviation > allowed && exact) {
    ParameterMapOptions map_options;
    map_options.tolerance = options.exact_tolerance;
    map = ParameterMap(nurbs, evaluate, bounds, map_options);
    deviation = max_deviation(nurbs, map, evaluate, bounds, kCheckGrid);
  }
  if (!(deviation <= allowed))
    throw FaceFailure("its NURBS form deviates from the original " + source_type(original) +
                      " surface by " + number_text(deviation) + " mm (allowed " +
                      number_text(allowed) + " mm)");
  return deviation;
}

bool same_sense(const NurbsSurface& nurbs, ParameterMap& map, const Handle(Geom_Surface)& original,
                const ParameterDomain& bounds) {
  // Compare Su x Sv of the NURBS with OpenCASCADE's D1U x D1V at the check
  // point where the original is least degenerate.
  double best = -1;
  double sense = 1;
  for (int i = 0; i < kCheckGrid; ++i)
    for (int j = 0; j < kCheckGrid; ++j) {
      const double u = bounds.u0 + bounds.width_u() * (i + 0.5) / kCheckGrid;
      const double v = bounds.v0 + bounds.width_v() * (j + 0.5) / kCheckGrid;
      gp_Pnt p;
      gp_Vec du, dv;
      original->D1(u, v, p, du, dv);
      const Eigen::Vector3d n_occt = to_eigen(du.Crossed(dv));
      if (n_occt.norm() <= best) continue;
      const Eigen::Vector2d st = map(u, v);
      const SurfaceDerivatives e = nurbs.evaluate(st.x(), st.y(), 1);
      const Eigen::Vector3d n_ours = e.Su.cross(e.Sv);
      if (n_ours.norm() == 0) continue;
      best = n_occt.norm();
      sense = n_ours.dot(n_occt) >= 0 ? 1 : -1;
    }
  return sense > 0;
}

}  // namespace furrow::cad
