// CAD import through OpenCASCADE (contract in cad_import.hpp). The only file of
// furrow_core that includes OpenCASCADE headers; OpenCASCADE exceptions
// (Standard_Failure, not std::exception) are caught here and become
// InputError naming the file and the face.
#include "io/cad/cad_import.hpp"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Bnd_Box2d.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineSurface.hxx>
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
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESGeom_BSplineCurve.hxx>
#include <IGESGeom_CircularArc.hxx>
#include <IGESGeom_CompositeCurve.hxx>
#include <IGESGeom_CopiousData.hxx>
#include <IGESGeom_CurveOnSurface.hxx>
#include <IGESGeom_Line.hxx>
#include <IGESGeom_SurfaceOfRevolution.hxx>
#include <IGESGeom_TrimmedSurface.hxx>
#include <Interface_Check.hxx>
#include <Interface_ReportEntity.hxx>
#include <Interface_UndefinedContent.hxx>
#include <StepData_UndefinedEntity.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepBasic_Product.hxx>
#include <StepShape_FaceSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cad/cad_occt_internal.hpp"
#include "io/cad/cad_parameter_map.hpp"
#include "io/cad/cad_reader.hpp"
#include "io/cad/cad_surface.hpp"
#include "io/cad/cad_trim_polygon.hpp"

namespace furrow {

namespace {

using cad::FaceFailure;
using cad::number_text;
using cad::FileBoundary;

std::string occt_text(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  return (m && *m) ? std::string(m) : std::string(e.DynamicType()->Name());
}

// OpenCASCADE prints progress and statistics on standard output; a library
// must not. The printers are detached for the duration of an import.
class QuietMessenger {
 public:
  QuietMessenger() : saved_(Message::DefaultMessenger()->Printers()) {
    Message::DefaultMessenger()->ChangePrinters().Clear();
  }
  ~QuietMessenger() { Message::DefaultMessenger()->ChangePrinters() = saved_; }
  QuietMessenger(const QuietMessenger&) = delete;
  QuietMessenger& operator=(const QuietMessenger&) = delete;

 private:
  Message_SequenceOfPrinters saved_;
};

// ---------------------------------------------------------------- boundaries

// One use of an edge in a wire, in the order the wire runs.
struct EdgeUse {
  Handle(Geom2d_Curve) pcurve;
  double from = 0, to = 0;
  bool degenerate = false;
  double tolerance = 0;  // the edge's 3-D tolerance [mm]
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // whole periods added to unwrap a seam
  // A degenerate edge (a pole: one point in 3-D) rerouted along the pole
  // line between its neighbours' ends (route_like_file) instead of its pcurve.
  bool bridged = false;
  Eigen::Vector2d bridge_from = Eigen::Vector2d::Zero(), bridge_to = Eigen::Vector2d::Zero();
  Eigen::Vector2d uv(double t) const {
    if (bridged) return bridge_from + (to == from ? 0.0 : (t - from) / (to - from)) * (bridge_to - bridge_from);
    const gp_Pnt2d p = pcurve->Value(t);
    return Eigen::Vector2d(p.X(), p.Y()) + shift;
  }
};
struct WireUse {
  std::vector<EdgeUse> edges;
  bool outer = false;  // the face's outer boundary (BRepTools::OuterWire)
};

// Exact (u,v) box of a wire's pcurves, unwrapping shifts included.
Bnd_Box2d wire_box(const WireUse& wire) {
  Bnd_Box2d box;
  for (const EdgeUse& e : wire.edges) {
    if (e.bridged) {
      box.Update(std::min(e.bridge_from.x(), e.bridge_to.x()), std::min(e.bridge_from.y(), e.bridge_to.y()),
                 std::max(e.bridge_from.x(), e.bridge_to.x()), std::max(e.bridge_from.y(), e.bridge_to.y()));
      continue;
    }
    Bnd_Box2d edge_box;
    BndLib_Add2dCurve::AddOptimal(e.pcurve, std::min(e.from, e.to), std::max(e.from, e.to), 0.0,
                                  edge_box);
    double a, b, c, d;
    edge_box.Get(a, b, c, d);
    box.Update(a + e.shift.x(), b + e.shift.y(), c + e.shift.x(), d + e.shift.y());
  }
  return box;
}

Eigen::Vector2d box_centre(const Bnd_Box2d& box) {
  double a, b, c, d;
  box.Get(a, b, c, d);
  return {0.5 * (a + c), 0.5 * (b + d)};
}

struct Periods {
  bool u = false, v = false;
  double du = 0, dv = 0;
};

// Twice the signed area of a wire's (u,v) loop (positive: counterclockwise).
double twice_signed_area(const WireUse& wire) {
  constexpr int kSamples = 32;
  std::vector<Eigen::Vector2d> points;
  for (const EdgeUse& e : wire.edges)
    for (int k = 0; k < (e.degenerate ? 1 : kSamples); ++k)
      points.push_back(e.uv(e.from + (e.to - e.from) * k / (e.degenerate ? 1 : kSamples)));
  double sum = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d& a = points[k];
    const Eigen::Vector2d& b = points[(k + 1) % points.size()];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

// Makes a wire that runs from pole to pole enclose the region its file
// gives it (file_boundary(); `sense` is the sense of the file's loop as this
// wire is walked). Such a wire has (at least) two degenerate edges, points
// in 3-D that the parameter plane draws as stretches of the pole lines; the
// stretch of the loop between two of them may be moved by a period, which
// keeps every 3-D edge but swaps the region enclosed for the rest of the
// surface (a lune for the rest of the sphere). OpenCASCADE draws the pole
// edges of a clockwise IGES boundary so that the loop runs counterclockwise,
// around the rest of the sphere; the stretch is moved here so that the loop
// runs the way the file's does, the pole edges then going straight between
// their neighbours' ends. On a surface of revolution the moved loop must
// also span the file's range of rotation angles (the periodic parameter is
// that angle), so a loop OpenCASCADE merely reversed is never swapped for
// the rest. A wire whose sense agrees, or without two pole edges (which
// then cannot enclose the rest of the surface), is left as it is.
void route_like_file(WireUse& wire, const Periods& periods, int sense, double rotation_extent) {
  if (sense == 0 || periods.u == periods.v) return;  // no file sense; no or two periodic directions
  const double area = twice_signed_area(wire);
  if (area == 0 || (area > 0) == (sense > 0)) return;
  std::vector<std::size_t> poles;
  for (std::size_t k = 0; k < wire.edges.size(); ++k)
    if (wire.edges[k].degenerate) poles.push_back(k);
  const std::size_t n = wire.edges.size();
  const double period = periods.u ? periods.du : periods.dv;
  const int axis = periods.u ? 0 : 1;
  for (std::size_t i = 0; i < poles.size(); ++i)
    for (std::size_t j = i + 1; j < poles.size(); ++j)
      for (const double step : {period, -period}) {
        WireUse moved = wire;
        for (std::size_t k = poles[i] + 1; k < poles[j]; ++k) moved.edges[k].shift[axis] += step;
        for (const std::size_t pole : {poles[i], poles[j]}) {
          EdgeUse& e = moved.edges[pole];
          const EdgeUse& before = moved.edges[(pole + n - 1) % n];
          const EdgeUse& after = moved.edges[(pole + 1) % n];
          e.bridge_from = before.uv(before.to);
          e.bridge_to = after.uv(after.from);
          e.bridged = true;
        }
        double u0, v0, u1, v1;
        wire_box(moved).Get(u0, v0, u1, v1);
        const double extent = axis == 0 ? u1 - u0 : v1 - v0;
        const bool spans_file = rotation_extent < 0 || std::abs(extent - rotation_extent) <= 1e-3 * period;
        if ((twice_signed_area(moved) > 0) == (sense > 0) && extent <= period * (1 + 1e-9) && spans_file) {
          wire = std::move(moved);
          return;
        }
      }
}

// The face's wires as chains of pcurves, unwrapped so that each chain is
// continuous in (u,v) even where it crosses a periodic surface's seam.
// `file` is what the file says about the outer boundary (FaceOrigin).
std::vector<WireUse> face_wires(const TopoDS_Face& face, const Periods& periods, const FileBoundary& file) {
  std::vector<WireUse> wires;
  const TopoDS_Wire outer = BRepTools::OuterWire(face);
  for (TopoDS_Iterator it(face); it.More(); it.Next()) {
    // Internal and external wires (imprinted lines, construction curves) do
    // not bound the face.
    const TopAbs_Orientation o = it.Value().Orientation();
    if (it.Value().ShapeType() != TopAbs_WIRE || o == TopAbs_INTERNAL || o == TopAbs_EXTERNAL) continue;
    const TopoDS_Wire& wire = TopoDS::Wire(it.Value());
    int edges_in_wire = 0;
    for (TopoDS_Iterator e(wire); e.More(); e.Next()) ++edges_in_wire;
    WireUse use;
    use.outer = !outer.IsNull() && wire.IsSame(outer);
    std::vector<EdgeUse>& chain = use.edges;
    for (BRepTools_WireExplorer we(wire, face); we.More(); we.Next()) {
      const TopoDS_Edge& edge = we.Current();
      double first = 0, last = 0;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (pcurve.IsNull())
        throw FaceFailure("an edge has no curve in the surface's parameter plane (pcurve)");
      const bool reversed = edge.Orientation() == TopAbs_REVERSED;
      chain.push_back({pcurve, reversed ? last : first, reversed ? first : last,
                       BRep_Tool::Degenerated(edge) == Standard_True, BRep_Tool::Tolerance(edge),
                       Eigen::Vector2d::Zero()});
    }
    if (chain.empty()) continue;
    if (static_cast<int>(chain.size()) < edges_in_wire)
      throw FaceFailure("a boundary wire is not a connected chain of edges");
    Eigen::Vector2d end = chain.front().uv(chain.front().to);
    for (std::size_t k = 1; k < chain.size(); ++k) {
      const Eigen::Vector2d start = chain[k].uv(chain[k].from);
      if (periods.u) chain[k].shift.x() = std::round((end.x() - start.x()) / periods.du) * periods.du;
      if (periods.v) chain[k].shift.y() = std::round((end.y() - start.y()) / periods.dv) * periods.dv;
      end = chain[k].uv(chain[k].to);
    }
    const Eigen::Vector2d gap = end - chain.front().uv(chain.front().from);
    if ((periods.u && std::abs(gap.x()) > 0.5 * periods.du) ||
        (periods.v && std::abs(gap.y()) > 0.5 * periods.dv))
      throw FaceFailure("a boundary wire winds around the periodic surface without a seam edge "
                        "(heal the model, e.g. re-export it as a solid)");
    wires.push_back(std::move(use));
  }
  // The outer wire encloses the region the file's boundary does (walked on a
  // reversed face, the wire runs against the file's loop).
  if (file.sense != 0) {
    const int sense = face.Orientation() == TopAbs_REVERSED ? -file.sense : file.sense;
    for (WireUse& w : wires)
      if (w.outer || wires.size() == 1) route_like_file(w, periods, sense, file.rotation_extent);
  }
  // Inner wires may come a period away from the outer one (pcurves projected
  // into [0, 2 pi) each on their own): move each next to the outer wire.
  const auto reference = std::find_if(wires.begin(), wires.end(), [](const WireUse& w) { return w.outer; });
  if (reference != wires.end() && (periods.u || periods.v)) {
    const Eigen::Vector2d centre = box_centre(wire_box(*reference));
    for (WireUse& w : wires) {
      if (w.outer) continue;
      const Eigen::Vector2d offset = centre - box_centre(wire_box(w));
      Eigen::Vector2d shift = Eigen::Vector2d::Zero();
      if (periods.u) shift.x() = std::round(offset.x() / periods.du) * periods.du;
      if (periods.v) shift.y() = std::round(offset.y() / periods.dv) * periods.dv;
      for (EdgeUse& e : w.edges) e.shift += shift;
    }
  }
  return wires;
}

// A hole that crosses the seam of a face closed around a period lies partly
// beyond the face's rectangle; its copy one period over covers the rest.
// (The parts of both copies outside the rectangle are clamped onto its edge
// when sampled, so each copy cuts out exactly its share.)
void add_seam_copies(std::vector<WireUse>& wires, const ParameterDomain& b, const Periods& periods) {
  const std::size_t count = wires.size();
  for (std::size_t k = 0; k < count; ++k) {
    if (wires[k].outer) continue;
    double u0, v0, u1, v1;
    wire_box(wires[k]).Get(u0, v0, u1, v1);
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    const bool full_u = periods.u && b.width_u() >= periods.du * (1 - 1e-12);
    const bool full_v = periods.v && b.width_v() >= periods.dv * (1 - 1e-12);
    if (full_u && u1 > b.u1) shift.x() = -periods.du;
    if (full_u && u0 < b.u0) shift.x() = periods.du;
    if (full_v && v1 > b.v1) shift.y() = -periods.dv;
    if (full_v && v0 < b.v0) shift.y() = periods.dv;
    if (shift.isZero()) continue;
    WireUse copy = wires[k];
    for (EdgeUse& e : copy.edges) e.shift += shift;
    wires.push_back(std::move(copy));
  }
}

// A periodic range from pcurve boxes is off by rounding (e.g. [-4e-13, 2 pi]);
// OpenCASCADE's conversions of a full turn need it exact: ends within `eps`
// of a multiple of the period are moved onto it, and a range of a period (or
// up to `eps` more) is made exactly one period.
void snap_to_period(double& a, double& b, double period, double eps, const char* direction) {
  auto snap = [&](double& x) {
    const double multiple = std::round(x / period) * period;
    if (std::abs(x - multiple) <= eps) x = multiple;
  };
  snap(a);
  snap(b);
  if (b - a > period + eps)
    throw FaceFailure(std::string("its boundary spans more than one period in ") + direction);
  if (b - a > period - eps) b = a + period;
}

// How far a wire's pcurves may stray in a periodic parameter without
// meaning anything: rounding (1e-9 of the period), or the edges' own 3-D
// tolerance in parameter units. Why the latter: a wire that runs along the
// seam (a cap around a sphere's pole, an IGES file that gives only 3-D
// curves, whose pcurves OpenCASCADE projects) has pcurves up to the edge
// tolerance off the seam line, e.g. 1.3e-8 rad past 2 pi for 1e-7 mm on a
// 4.75 mm sphere; with rounding alone such a face was refused as spanning
// more than one period. The 3-D tolerance is turned into a parameter step
// by the largest speed of the surface along that parameter over the face,
// so the step is never larger than the tolerance on the surface.
double period_slack(const std::vector<WireUse>& wires, const Handle(Geom_Surface)& surface, double u0, double u1,
                    double v0, double v1, bool along_u, double period) {
  double tolerance = 0;
  for (const WireUse& w : wires)
    for (const EdgeUse& e : w.edges) tolerance = std::max(tolerance, e.tolerance);
  double speed = 0;
  constexpr int kSamples = 7;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      surface->D1(u0 + (u1 - u0) * i / (kSamples - 1), v0 + (v1 - v0) * j / (kSamples - 1), p, du, dv);
      speed = std::max(speed, (along_u ? du : dv).Magnitude());
    }
  const double rounding = 1e-9 * period;
  return speed > 0 ? std::max(rounding, std::min(tolerance / speed, 1e-6 * period)) : rounding;
}

// Parameter rectangle of the face: the exact box of its outer wire's
// pcurves, at most one period wide, inside the surface's own bounds.
ParameterDomain face_bounds(const TopoDS_Face& face, const std::vector<WireUse>& wires,
                            const Handle(Geom_Surface)& surface, const Periods& periods) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  if (wires.empty()) {
    BRepTools::UVBounds(face, u0, u1, v0, v1);
  } else {
    // The outer wire bounds the face (holes lie inside it); without one, all do.
    const bool has_outer = std::any_of(wires.begin(), wires.end(), [](const WireUse& w) { return w.outer; });
    Bnd_Box2d box;
    for (const WireUse& wire : wires)
      if (wire.outer || !has_outer) box.Add(wire_box(wire));
    box.Get(u0, v0, u1, v1);
  }
  double su0, su1, sv0, sv1;
  surface->Bounds(su0, su1, sv0, sv1);
  if (!periods.u) u0 = std::max(u0, su0), u1 = std::min(u1, su1);
  if (!periods.v) v0 = std::max(v0, sv0), v1 = std::min(v1, sv1);
  if (periods.u)
    snap_to_period(u0, u1, periods.du, period_slack(wires, surface, u0, u1, v0, v1, true, periods.du), "u");
  if (periods.v)
    snap_to_period(v0, v1, periods.dv, period_slack(wires, surface, u0, u1, v0, v1, false, periods.dv), "v");
  if (!(std::abs(u0) < 1e50 && std::abs(u1) < 1e50 && std::abs(v0) < 1e50 && std::abs(v1) < 1e50))
    throw FaceFailure("it is unbounded (an infinite surface without a boundary)");
  if (!(u1 > u0 && v1 > v0)) throw FaceFailure("its parameter rectangle is empty");
  return {u0, u1, v0, v1};
}

// ---------------------------------------------------------------- faces

struct ConvertedFace {
  Face face;
  CadFaceReport report;
};

ConvertedFace convert_face(const TopoDS_Face& face, const std::string& name, const FileBoundary& file,
                           const CadImportOptions& options) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) throw FaceFailure("it has no surface");
  const Handle(Geom_Surface) basis = cad::strip_trim(surface);
  CadFaceReport report;
  report.name = name;
  report.source_type = cad::source_type(basis);

  Periods periods;
  periods.u = basis->IsUPeriodic();
  periods.v = basis->IsVPeriodic();
  if (periods.u) periods.du = basis->UPeriod();
  if (periods.v) periods.dv = basis->VPeriod();
  std::vector<WireUse> wires = face_wires(face, periods, file);
  const ParameterDomain bounds = face_bounds(face, wires, basis, periods);
  add_seam_copies(wires, bounds, periods);

  const cad::Conversion conversion = cad::convert_surface(basis, bounds, options);
  report.exact = conversion.exact;
  report.approximation_bound = conversion.bound;
  NurbsSurface nurbs = cad::to_nurbs(conversion.nurbs, "face " + quote_field(name));
  ParameterMap map;
  report.deviation = cad::carry_parameters(nurbs, basis, bounds, conversion.exact, options, map);

  TrimPolygonOptions polygon_options;
  polygon_options.chord_tolerance = options.trim_chord_tolerance;
  polygon_options.uv_tolerance = options.trim_uv_tolerance;
  polygon_options.max_subdivisions = options.trim_max_subdivisions;
  TrimPolygonBuilder polygons(nurbs, polygon_options);
  std::vector<UvLoop> loops;
  for (const WireUse& wire : wires) {
    std::vector<BoundaryCurve> curves;
    for (const EdgeUse& e : wire.edges)
      curves.push_back({[&e, &map, &bounds](double t) {
                          const Eigen::Vector2d uv = e.uv(t);
                          return map(std::clamp(uv.x(), bounds.u0, bounds.u1),
                                     std::clamp(uv.y(), bounds.v0, bounds.v1));
                        },
                        e.from, e.to, e.degenerate});
    UvLoop loop = polygons.loop(curves);
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  if (map.failures() > 0)
    throw FaceFailure("its trim could not be carried into the NURBS parameters (" +
                      std::to_string(map.failures()) + " points did not converge, worst residual " +
                      number_text(map.worst_residual()) + " mm)");
  if (is_domain_rectangle(loops, nurbs.domain())) loops.clear();
  report.loops = static_cast<int>(loops.size());
  for (const auto& loop : loops) report.trim_vertices += static_cast<int>(loop.size());
  report.trim_deviation = polygons.worst_sag();
  report.trim_tolerance_met = polygons.tolerance_met();

  // Normals out of the material: OpenCASCADE's face orientation, and the
  // NURBS's own sense against the original surface's.
  const bool flipped = !cad::same_sense(nurbs, map, basis, bounds);
  const bool reversed = (face.Orientation() == TopAbs_REVERSED) != flipped;

  Trim trim(std::move(loops), "face " + quote_field(name) + " trim");
  return {Face(name, std::move(nurbs), std::move(trim), reversed, report.source_type), report};
}

}  // namespace

bool is_cad_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

CadImportResult import_cad(const std::string& path, const CadImportOptions& options) {
  const cad::Format format = cad::format_of(path);
  cad::check_signature(path, format);
  const QuietMessenger quiet;

  cad::LoadedFile file;
  try {
    file = cad::read_file(path, format);
  } catch (const Standard_Failure& e) {
    throw InputError(path + ": OpenCASCADE failed while reading the file: " + occt_text(e));
  }

  CadImportResult result;
  result.format = format == cad::Format::step ? "STEP" : "IGES";
  result.products = file.products;
  result.part.source_units = file.units;
  auto face_label = [](const std::string& name, const std::string& entity) {
    if (entity.rfind("entity ", 0) == 0) return entity;  // not a face (add_unreadable_entities)
    std::string label = "face";
    if (!name.empty()) label += " " + quote_field(name);
    if (!entity.empty()) label += " " + entity;
    return label;
  };
  for (const CadSkippedFace& bad : file.untranslated) {
    if (!options.skip_bad_faces)
      throw InputError(path + ": " + face_label(bad.name, bad.entity) +
                       " could not be translated: " + bad.reason);
    result.skipped.push_back(bad);
  }

  TopTools_IndexedMapOfShape faces, solids, solid_faces;
  TopExp::MapShapes(file.shape, TopAbs_FACE, faces);
  TopExp::MapShapes(file.shape, TopAbs_SOLID, solids);
  for (int s = 1; s <= solids.Extent(); ++s) TopExp::MapShapes(solids(s), TopAbs_FACE, solid_faces);
  result.solids = static_cast<std::size_t>(solids.Extent());
  if (faces.Extent() == 0) {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(file.shape, TopAbs_EDGE, edges);
    throw InputError(path + ": the file holds no surfaces (no faces" +
                     (edges.Extent() > 0 ? ", only " + std::to_string(edges.Extent()) + " curve(s)" : "") +
                     "): nothing to inspect");
  }

  std::set<std::string> used_names;
  const std::size_t total = static_cast<std::size_t>(faces.Extent());
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    const std::size_t index = static_cast<std::size_t>(i - 1);
    cad::FaceOrigin origin;
    if (auto it = file.origins.find(face.TShape().get()); it != file.origins.end()) origin = it->second;
    std::string name = origin.name.empty() ? "face_" + std::to_string(index) : origin.name;
    if (used_names.count(name)) name += "_" + std::to_string(index);
    std::string failure;
    try {
      ConvertedFace converted = convert_face(face, name, origin.boundary, options);
      converted.report.entity = origin.entity;
      if (!solid_faces.Contains(face)) ++result.free_faces;
      used_names.insert(name);
      result.part.faces.push_back(std::move(converted.face));
      result.faces.push_back(std::move(converted.report));
    } catch (const FaceFailure& e) {
      failure = e.what();
    } catch (const InputError& e) {
      failure = e.what();
    } catch (const Standard_Failure& e) {
      failure = "OpenCASCADE failed on it: " + occt_text(e);
    }
    if (!failure.empty()) {
      if (!options.skip_bad_faces)
        throw InputError(path + ": " + face_label(name, origin.entity) + " (" +
                         cad::face_surface_type(face) + "): " + failure);
      result.skipped.push_back({name, origin.entity, failure});
    }
    if (options.progress) options.progress(index + 1, total);
  }
  if (result.part.faces.empty())
    throw InputError(path + ": none of the file's " + std::to_string(total) +
                     " faces could be imported (first problem: " + result.skipped.front().reason + ")");
  return result;
}

}  // namespace furrow
