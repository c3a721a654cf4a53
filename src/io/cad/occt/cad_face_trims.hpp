#pragma once
// A face's trim loops in its surface's parameter plane (docs/formats.md "CAD
// import").
//
// face_wires() takes the face's boundary wires as chains of pcurves in the
// original surface's (u,v) and prepares them for one NURBS patch:
// - on a periodic surface each chain is unwrapped so that it is continuous
//   across the seam, inner wires are moved next to the outer one, and a hole
//   that crosses the seam of a face closed around a period is cut out on both
//   sides (a copy one period over);
// - a wire that runs from pole to pole is made to enclose the region the IGES
//   file's own boundary does (cad_iges_boundary.hpp): OpenCASCADE may route
//   its pole edges around the other side of the surface;
// - the outer wire of an IGES boundary given in model space only is built
//   from its 3-D curves instead of OpenCASCADE's projected pcurves
//   (cad_model_space_loop.hpp): the file's own curves as translated
//   (FileBoundary::curves), when the face's outer wire lies on them, so a
//   curve the face's healing dropped still counts, else the wire's edges;
//   FaceWires::turned says when its region lies on the other side of the
//   wire than OpenCASCADE's face has it;
//   the face's other wires are its holes, less any that OpenCASCADE's
//   healing made of the same boundary or added as the natural bound of the
//   whole closed surface (seam and pole edges only), which the rebuilt
//   loop makes redundant and which would take its region away again;
// - the face's rectangle is the exact box of its outer wire, at most one
//   period wide, snapped onto whole periods within rounding or the edges' own
//   tolerance.
// trim_loops() then samples the wires into balanced polygons in the NURBS's
// (s,t) (cad_trim_polygon.hpp), through the map from (u,v) to (s,t)
// (cad_surface.hpp carry_parameters()); points outside the rectangle are
// clamped onto its edge.
//
// Units: parameters as the surface has them (radians for angles); edge
// tolerances and trim sags in millimetres. Precondition: `surface` is the
// face's own surface (BRep_Tool::Surface, not null) without rectangular trims
// (cad_surface.hpp strip_trim()). Failures: FaceFailure
// (cad_occt_internal.hpp) for an edge without a pcurve, a wire that is not a
// connected chain or winds around the surface without a seam edge, a
// boundary spanning more than one period, an unbounded or empty rectangle,
// and trim points the map could not carry over; OpenCASCADE's
// Standard_Failure may escape too.
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt2d.hxx>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "geometry/nurbs_surface.hpp"
#include "geometry/trim.hpp"
#include "io/cad/occt/cad_iges_boundary.hpp"
#include "io/cad/occt/cad_projected_curve.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_parameter_map.hpp"

namespace furrow::cad {

// Which parameters of the surface are periodic, and their periods.
struct Periods {
  bool u = false, v = false;
  double du = 0, dv = 0;
};

// One use of an edge in a wire, in the order the wire runs.
struct EdgeUse {
  Handle(Geom2d_Curve) pcurve;
  double from = 0, to = 0;
  bool degenerate = false;
  double tolerance = 0;  // the edge's 3-D tolerance [mm]
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // whole periods added to unwrap a seam
  // A degenerate edge (a pole: one point in 3-D) rerouted along the pole
  // line between its neighbours' ends (see face_wires()) instead of its pcurve.
  bool bridged = false;
  Eigen::Vector2d bridge_from = Eigen::Vector2d::Zero(), bridge_to = Eigen::Vector2d::Zero();
  // Instead of the pcurve: the (u,v) of the edge's 3-D curve, for a
  // boundary the file gives in model space only (cad_model_space_loop.hpp).
  std::shared_ptr<const ProjectedCurve> projected;
  Eigen::Vector2d uv(double t) const {
    if (bridged) return bridge_from + (to == from ? 0.0 : (t - from) / (to - from)) * (bridge_to - bridge_from);
    if (projected) return projected->uv(t) + shift;
    const gp_Pnt2d p = pcurve->Value(t);
    return Eigen::Vector2d(p.X(), p.Y()) + shift;
  }
};

// One boundary wire of the face, edges in running order.
struct WireUse {
  std::vector<EdgeUse> edges;
  bool outer = false;  // the face's outer boundary (BRepTools::OuterWire)
  // Built from model-space curves (cad_model_space_loop.hpp): its pole
  // bridges lie between its curves' ends and add nothing to its box.
  bool model_space = false;
};

struct FaceWires {
  std::vector<WireUse> wires;  // unwrapped, seam copies of holes included
  ParameterDomain bounds;      // the face's (u,v) rectangle
  // The outer loop, built from model-space curves, encloses its region on
  // the other side than OpenCASCADE's face has it: the face's normal must
  // be turned for its boundary to run as its neighbours' do
  // (cad_model_space_loop.hpp).
  bool turned = false;
};

// The face's boundary wires on `surface` (the face's surface without
// rectangular trims) and its parameter rectangle; `file` is what the file
// says about the outer boundary (FileBoundary{} when it says nothing).
FaceWires face_wires(const TopoDS_Face& face, const Handle(Geom_Surface)& surface, const FileBoundary& file);

struct TrimLoops {
  std::vector<UvLoop> loops;  // in `nurbs`' (s,t); empty: untrimmed (the whole rectangle)
  double worst_sag = 0;       // largest chord sag before balancing [mm]
  bool tolerance_met = true;  // false when options.trim_max_subdivisions stopped the refinement
};

// The polygons of `face`'s wires in `nurbs`' (s,t), to the trim tolerances
// of `options`; `map` carries (u,v) over (cad_surface.hpp carry_parameters()).
TrimLoops trim_loops(const FaceWires& face, const NurbsSurface& nurbs, ParameterMap& map,
                     const CadImportOptions& options);

}  // namespace furrow::cad
