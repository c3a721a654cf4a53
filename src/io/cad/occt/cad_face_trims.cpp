// A face's trim loops in its surface's parameter plane (contract in
// cad_face_trims.hpp).
#include "io/cad/occt/cad_face_trims.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Bnd_Box2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "io/cad/occt/cad_model_space_loop.hpp"
#include "io/cad/occt/cad_occt_internal.hpp"
#include "io/cad/cad_trim_polygon.hpp"

namespace furrow::cad {

namespace {

// Exact (u,v) box of a wire's pcurves, unwrapping shifts included.
Bnd_Box2d wire_box(const WireUse& wire) {
  Bnd_Box2d box;
  for (const EdgeUse& e : wire.edges) {
    if (e.projected && !e.bridged) {
      const Eigen::Vector4d b = e.projected->box();
      box.Update(b[0] + e.shift.x(), b[1] + e.shift.y(), b[2] + e.shift.x(), b[3] + e.shift.y());
      continue;
    }
    if (e.bridged && wire.model_space) continue;
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

// The file's model-space curves of a face's outer boundary
// (FileBoundary::curves) in the order and direction `walked`, the face's
// outer wire as walked on the face, runs (by the tangents of the walked
// edges against the file curves they lie on). None when the curves do not
// form a chain, or a walked edge lies on none of them (the face's outer wire
// is not the file's outer boundary: OpenCASCADE's writer may give a hole as
// the outer boundary of a face on a cylinder); the caller then builds the
// loop from the walked edges.
std::vector<TopoDS_Edge> file_curves_as_walked(const TopoDS_Wire& curves, const std::vector<TopoDS_Edge>& walked) {
  std::vector<TopoDS_Edge> edges;
  if (curves.IsNull()) return edges;
  for (TopoDS_Iterator it(curves); it.More(); it.Next()) {
    if (it.Value().ShapeType() != TopAbs_EDGE) return {};
    const TopoDS_Edge& edge = TopoDS::Edge(it.Value());
    double c0 = 0, c1 = 0;
    if (!BRep_Tool::Degenerated(edge) && BRep_Tool::Curve(edge, c0, c1).IsNull()) return {};
    edges.push_back(edge);
  }
  if (edges.empty()) return {};
  // A chain, each curve starting where the one before ends (the loop closes).
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const TopoDS_Edge& a = edges[k];
    const TopoDS_Edge& b = edges[(k + 1) % edges.size()];
    const TopoDS_Vertex last = TopExp::LastVertex(a, true), first = TopExp::FirstVertex(b, true);
    if (last.IsNull() || first.IsNull()) return {};
    const gp_Pnt end = BRep_Tool::Pnt(last), start = BRep_Tool::Pnt(first);
    const double tolerance = std::max({BRep_Tool::Tolerance(a), BRep_Tool::Tolerance(b), 1e-4});
    if (end.Distance(start) > 10 * tolerance) return {};
  }
  // Every walked edge must lie on one of the file's curves (the face's
  // outer wire is the file's outer boundary), and they run along (+1) or
  // against (-1) each other there.
  int agree = 0;
  for (const TopoDS_Edge& w : walked) {
    double w0 = 0, w1 = 0;
    if (BRep_Tool::Degenerated(w)) continue;
    if (BRep_Tool::Curve(w, w0, w1).IsNull()) return {};
    const BRepAdaptor_Curve wc(w);
    gp_Pnt p;
    gp_Vec tangent;
    wc.D1(0.5 * (wc.FirstParameter() + wc.LastParameter()), p, tangent);
    if (w.Orientation() == TopAbs_REVERSED) tangent.Reverse();
    bool on_file = false;
    for (const TopoDS_Edge& e : edges) {
      if (BRep_Tool::Degenerated(e)) continue;
      double c0 = 0, c1 = 0;
      const Handle(Geom_Curve) curve = BRep_Tool::Curve(e, c0, c1);
      GeomAPI_ProjectPointOnCurve on(p, curve, std::min(c0, c1), std::max(c0, c1));
      const double tolerance = std::max({10 * BRep_Tool::Tolerance(e), 10 * BRep_Tool::Tolerance(w), 1e-4});
      if (on.NbPoints() == 0 || on.LowerDistance() > tolerance) continue;
      gp_Pnt q;
      gp_Vec along;
      curve->D1(on.LowerDistanceParameter(), q, along);
      if (e.Orientation() == TopAbs_REVERSED) along.Reverse();
      agree += along.Dot(tangent) > 0 ? 1 : -1;
      on_file = true;
      break;
    }
    if (!on_file) return {};
  }
  if (agree == 0) return {};
  if (agree < 0) {
    std::reverse(edges.begin(), edges.end());
    for (TopoDS_Edge& e : edges) e.Reverse();
  }
  return edges;
}

// The face's wires as chains of pcurves, unwrapped so that each chain is
// continuous in (u,v) even where it crosses a periodic surface's seam.
// `file` is what the file says about the outer boundary (cad_iges_boundary.hpp).
std::vector<WireUse> wire_chains(const TopoDS_Face& face, const Handle(Geom_Surface)& surface, const Periods& periods,
                                 const FileBoundary& file, bool& turned) {
  std::vector<WireUse> wires;
  // A boundary the file gives in model space only is rebuilt from its 3-D
  // curves on a periodic surface (cad_model_space_loop.hpp).
  const bool from_model_space = file.model_space_only && (periods.u || periods.v);
  Handle(ShapeAnalysis_Surface) projector;
  if (from_model_space) projector = new ShapeAnalysis_Surface(surface);
  int face_wire_count = 0;
  for (TopoDS_Iterator it(face); it.More(); it.Next()) {
    const TopAbs_Orientation o = it.Value().Orientation();
    face_wire_count += it.Value().ShapeType() == TopAbs_WIRE && o != TopAbs_INTERNAL && o != TopAbs_EXTERNAL;
  }
  // A face's wire as walked on it; whether a wire runs only along the
  // surface's seams and poles (the natural bound of the whole closed
  // surface, which OpenCASCADE's healing adds to a face on a torus or
  // sphere whose wires all look like holes to it).
  auto walked_edges = [&face](const TopoDS_Wire& wire) {
    std::vector<TopoDS_Edge> edges;
    for (BRepTools_WireExplorer we(wire, face); we.More(); we.Next()) edges.push_back(we.Current());
    return edges;
  };
  auto natural_bound = [&face](const TopoDS_Shape& wire) {
    for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
      if (!BRep_Tool::Degenerated(edge) && !BRep_Tool::IsClosed(edge, face)) return false;
    }
    return true;
  };
  // The outer wire: on a face whose split pieces the reader merged, the one
  // OpenCASCADE made of the file's outer boundary (the pieces' wires lie
  // apart, which OuterWire's box test cannot order).
  TopoDS_Wire outer = BRepTools::OuterWire(face);
  if (from_model_space && file.merged && !file.wire.IsNull())
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
      if (it.Value().ShapeType() != TopAbs_WIRE) continue;
      bool shares = false;
      for (TopExp_Explorer e(it.Value(), TopAbs_EDGE); e.More() && !shares; e.Next())
        for (TopExp_Explorer o(file.wire, TopAbs_EDGE); o.More() && !shares; o.Next())
          shares = e.Current().IsSame(o.Current()) && !BRep_Tool::Degenerated(TopoDS::Edge(o.Current()));
      if (shares) {
        outer = TopoDS::Wire(it.Value());
        break;
      }
    }
  // OuterWire's box test takes that natural bound, which spans whole
  // periods, for the outer wire: the outer wire is then the one that lies
  // on the file's outer boundary curves (a band around a torus's axis with
  // a hole on its seam came in as the whole torus and the band).
  if (from_model_space && !outer.IsNull() && natural_bound(outer))
    for (TopoDS_Iterator it(face); it.More(); it.Next())
      if (it.Value().ShapeType() == TopAbs_WIRE && !it.Value().IsSame(outer) &&
          !file_curves_as_walked(file.curves, walked_edges(TopoDS::Wire(it.Value()))).empty()) {
        outer = TopoDS::Wire(it.Value());
        break;
      }
  const bool outer_from_file = from_model_space && !outer.IsNull() &&
                               !file_curves_as_walked(file.curves, walked_edges(outer)).empty();
  // Where the outer loop is rebuilt from every one of the file's curves, a
  // further wire of the face is no hole when it lies on those curves (a
  // piece of the same boundary) or runs only along the surface's seams and
  // poles: the natural bound of the whole closed surface, which
  // OpenCASCADE's healing adds to a face on a torus or sphere whose wires
  // all look like holes to it. A torus band over the whole tube with a
  // hole on its seam, its loop running clockwise, came in as the hole:
  // the whole torus less the band's loop less the hole.
  auto piece_of_outer = [&](const TopoDS_Shape& wire) {
    return outer_from_file && !wire.IsSame(outer) &&
           (natural_bound(wire) || !file_curves_as_walked(file.curves, walked_edges(TopoDS::Wire(wire))).empty());
  };
  // A point of each of the face's other wires (its holes) in (u,v): the
  // rebuilt outer loop must hold them (cad_model_space_loop.hpp).
  std::vector<Eigen::Vector2d> holes;
  if (from_model_space)
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
      const TopAbs_Orientation o = it.Value().Orientation();
      if (it.Value().ShapeType() != TopAbs_WIRE || o == TopAbs_INTERNAL || o == TopAbs_EXTERNAL ||
          it.Value().IsSame(outer) || piece_of_outer(it.Value()))
        continue;
      for (TopExp_Explorer e(it.Value(), TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        double c0 = 0, c1 = 0;
        if (BRep_Tool::Degenerated(edge)) continue;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, c0, c1);
        if (curve.IsNull()) continue;
        const gp_Pnt2d q = projector->ValueOfUV(curve->Value(0.5 * (c0 + c1)), BRep_Tool::Tolerance(edge));
        holes.emplace_back(q.X(), q.Y());
        break;
      }
    }
  for (TopoDS_Iterator it(face); it.More(); it.Next()) {
    // Internal and external wires (imprinted lines, construction curves) do
    // not bound the face.
    const TopAbs_Orientation o = it.Value().Orientation();
    if (it.Value().ShapeType() != TopAbs_WIRE || o == TopAbs_INTERNAL || o == TopAbs_EXTERNAL) continue;
    const TopoDS_Wire& wire = TopoDS::Wire(it.Value());
    if (piece_of_outer(wire)) continue;
    int edges_in_wire = 0;
    for (TopoDS_Iterator e(wire); e.More(); e.Next()) ++edges_in_wire;
    WireUse use;
    use.outer = !outer.IsNull() && wire.IsSame(outer);
    std::vector<EdgeUse>& chain = use.edges;
    const bool rebuild = from_model_space && (use.outer || face_wire_count == 1);
    const Eigen::Vector2d period(periods.u ? periods.du : 0.0, periods.v ? periods.dv : 0.0);
    std::vector<TopoDS_Edge> walked;  // the wire's edges as walked on the face
    for (BRepTools_WireExplorer we(wire, face); we.More(); we.Next()) {
      const TopoDS_Edge& edge = we.Current();
      walked.push_back(edge);
      const bool reversed = edge.Orientation() == TopAbs_REVERSED;
      double first = 0, last = 0;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      EdgeUse use_of_edge;
      use_of_edge.pcurve = pcurve;
      use_of_edge.from = reversed ? last : first;
      use_of_edge.to = reversed ? first : last;
      use_of_edge.degenerate = BRep_Tool::Degenerated(edge) == Standard_True;
      use_of_edge.tolerance = BRep_Tool::Tolerance(edge);
      if (pcurve.IsNull() && !rebuild)
        throw FaceFailure("an edge has no curve in the surface's parameter plane (pcurve)");
      chain.push_back(std::move(use_of_edge));
    }
    // The wire rebuilt from the edges' 3-D curves, each cut where it passes
    // through a pole (cad_projected_curve.hpp pole_passages()): the file's
    // own curves where the reader has them (the face's healing may have
    // dropped some), else the face's; `chain` keeps the pcurves to fall back on.
    std::vector<EdgeUse> model_chain;
    bool model_curves = rebuild;  // every edge has what the rebuilt wire needs
    if (rebuild) {
      const std::vector<TopoDS_Edge> from_file = file_curves_as_walked(file.curves, walked);
      for (const TopoDS_Edge& edge : from_file.empty() ? walked : from_file) {
        const bool reversed = edge.Orientation() == TopAbs_REVERSED;
        if (BRep_Tool::Degenerated(edge)) {
          if (!from_file.empty()) continue;  // a pole: the curves' ends say where
          double first = 0, last = 0;
          EdgeUse pole;
          pole.pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
          pole.from = reversed ? last : first;
          pole.to = reversed ? first : last;
          pole.degenerate = true;
          pole.tolerance = BRep_Tool::Tolerance(edge);
          model_chain.push_back(std::move(pole));
          continue;
        }
        double c0 = 0, c1 = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, c0, c1);
        if (curve.IsNull()) {
          model_curves = false;
          break;
        }
        const double from = reversed ? c1 : c0, to = reversed ? c0 : c1;
        std::vector<double> cuts{from};
        for (const double t : pole_passages(curve, projector, from, to, period)) cuts.push_back(t);
        cuts.push_back(to);
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
          EdgeUse piece;
          piece.tolerance = BRep_Tool::Tolerance(edge);
          piece.from = cuts[k];
          piece.to = cuts[k + 1];
          piece.projected = std::make_shared<const ProjectedCurve>(curve, projector, piece.from, piece.to, period,
                                                                   k > 0, k + 2 < cuts.size());
          model_chain.push_back(std::move(piece));
        }
      }
    }
    if (chain.empty()) continue;
    if (static_cast<int>(chain.size()) < edges_in_wire)
      throw FaceFailure("a boundary wire is not a connected chain of edges");
    if (model_curves) {
      WireUse model;
      model.outer = use.outer;
      model.edges = std::move(model_chain);
      bool turn = false;
      if (model_space_loop(model, surface, periods, file, face.Orientation() == TopAbs_REVERSED, holes,
                           turn)) {
        turned = turn;
        model.model_space = true;
        wires.push_back(std::move(model));
        continue;
      }
    }
    for (const EdgeUse& e : chain)
      if (e.pcurve.IsNull()) throw FaceFailure("an edge has no curve in the surface's parameter plane (pcurve)");
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

}  // namespace

FaceWires face_wires(const TopoDS_Face& face, const Handle(Geom_Surface)& surface, const FileBoundary& file) {
  Periods periods;
  periods.u = surface->IsUPeriodic();
  periods.v = surface->IsVPeriodic();
  if (periods.u) periods.du = surface->UPeriod();
  if (periods.v) periods.dv = surface->VPeriod();
  bool turned = false;
  std::vector<WireUse> wires = wire_chains(face, surface, periods, file, turned);
  const ParameterDomain bounds = face_bounds(face, wires, surface, periods);
  add_seam_copies(wires, bounds, periods);
  return {std::move(wires), bounds, turned};
}

TrimLoops trim_loops(const FaceWires& face, const NurbsSurface& nurbs, ParameterMap& map,
                     const CadImportOptions& options) {
  const ParameterDomain& bounds = face.bounds;
  TrimPolygonOptions polygon_options;
  polygon_options.chord_tolerance = options.trim_chord_tolerance;
  polygon_options.uv_tolerance = options.trim_uv_tolerance;
  polygon_options.max_subdivisions = options.trim_max_subdivisions;
  TrimPolygonBuilder polygons(nurbs, polygon_options);
  std::vector<UvLoop> loops;
  for (const WireUse& wire : face.wires) {
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
  return {std::move(loops), polygons.worst_sag(), polygons.tolerance_met()};
}

}  // namespace furrow::cad
