#pragma once
// A face's surface as a Furrow NURBS (docs/formats.md "CAD import").
//
// OpenCASCADE surfaces come in many kinds; Furrow has one, the rational
// B-spline patch. convert_surface() gives the exact rational B-spline of a
// surface over a parameter rectangle when OpenCASCADE has one (elementary,
// swept, B-spline, Bezier surfaces, offsets with an elementary equivalent)
// and an approximation within options.approximation_tolerance otherwise.
// The exact conversions of circles reparametrise them, so carry_parameters()
// finds the map from the original's (u,v) to the NURBS's (s,t)
// (cad_parameter_map.hpp) and checks the result against the original on a
// grid; same_sense() tells whether the NURBS's Su x Sv points the way the
// original's D1U x D1V does.
//
// Units: millimetres (OpenCASCADE has converted the file). "Original" is the
// face's surface with rectangular trims stripped (strip_trim()), in its own
// (u,v); `bounds` is the face's rectangle in it (cad_face_trims.hpp).
// Failures: FaceFailure (cad_occt_internal.hpp) saying why, for a surface
// that cannot be converted or checked; OpenCASCADE's Standard_Failure may
// escape too (import_with_occt() reports both against the face).
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <string>

#include "geometry/nurbs_surface.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_parameter_map.hpp"

namespace furrow::cad {

// The original surface's kind as CadFaceReport::source_type names it:
// plane, cylinder, cone, sphere, torus, extrusion, revolution, offset,
// b-spline, bezier, other.
std::string source_type(const Handle(Geom_Surface)& s);

// The surface under any rectangular trims (the trims are the face's wires'
// business, not the surface's).
Handle(Geom_Surface) strip_trim(Handle(Geom_Surface) s);

// source_type() of a face's surface, or "no surface"; for error messages.
std::string face_surface_type(const TopoDS_Face& face);

struct Conversion {
  Handle(Geom_BSplineSurface) nurbs;
  bool exact = true;
  double bound = 0;  // OpenCASCADE's error bound of an approximation
};

// Exact rational B-spline over the rectangle `b` of `original` when
// OpenCASCADE has one, an approximation otherwise. Throws FaceFailure when
// an approximation is needed and fails or misses the tolerance.
Conversion convert_surface(const Handle(Geom_Surface)& original, const ParameterDomain& b,
                           const CadImportOptions& options);

// OpenCASCADE's B-spline as a Furrow NurbsSurface (periodic ones opened up
// first); `field` names it in NurbsSurface's validation errors.
NurbsSurface to_nurbs(Handle(Geom_BSplineSurface) bs, const std::string& field);

// Sets `map` (identity on entry) from `original`'s (u,v) over `bounds` to
// `nurbs`' (s,t): the identity when that matches, else, for an exact
// conversion, a product map. Returns the largest deviation [mm] of
// N(map(u,v)) from S(u,v) on the check grid; throws FaceFailure when it is
// more than options.exact_tolerance (exact) or approximation_tolerance.
// `nurbs` must outlive `map`.
double carry_parameters(const NurbsSurface& nurbs, const Handle(Geom_Surface)& original,
                        const ParameterDomain& bounds, bool exact, const CadImportOptions& options,
                        ParameterMap& map);

// True when `nurbs`' Su x Sv agrees in sense with `original`'s D1U x D1V,
// compared at the check point of `bounds` where the original is least
// degenerate (so poles and apexes do not decide).
bool same_sense(const NurbsSurface& nurbs, ParameterMap& map, const Handle(Geom_Surface)& original,
                const ParameterDomain& bounds);

}  // namespace furrow::cad
