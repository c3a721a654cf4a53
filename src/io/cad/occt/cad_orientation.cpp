// Outward orientation of imported faces (contract in cad_orientation.hpp).
#include "io/cad/occt/cad_orientation.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Precision.hxx>
#include <Geom_Surface.hxx>
#include <ShapeFix_Shell.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include "io/cad/occt/cad_occt_internal.hpp"

namespace furrow::cad {

namespace {

// The face's outward normal (its orientation applied) at surface parameters
// (u, v), or nullopt where the surface has none (a pole).
std::optional<gp_Vec> oriented_normal(const TopoDS_Face& face, const Handle(Geom_Surface)& surface, double u,
                                      double v) {
  GeomLProp_SLProps props(surface, u, v, 1, 1e-9);
  if (!props.IsNormalDefined()) return std::nullopt;
  gp_Vec n(props.Normal());
  if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
  return n;
}

// A point of the face with a defined normal: the centre of its parameter
// box, else a few points around it (the centre may be a pole).
struct FacePoint {
  gp_Pnt point;
  gp_Vec normal;
};
std::optional<FacePoint> sample_point(const TopoDS_Face& face) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) return std::nullopt;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  for (const double a : {0.5, 0.3, 0.7})
    for (const double b : {0.5, 0.3, 0.7}) {
      const double u = u0 + a * (u1 - u0), v = v0 + b * (v1 - v0);
      if (const auto n = oriented_normal(face, surface, u, v)) return FacePoint{surface->Value(u, v), *n};
    }
  return std::nullopt;
}

// Whether `other` (the same surface, possibly another orientation or a
// rebuilt face) points the same way as `original` does at its sample point.
bool same_sense(const TopoDS_Face& original, const TopoDS_Face& other) {
  // Sewing usually keeps the face's surface: then the orientations decide.
  TopLoc_Location lo, lt;
  const Handle(Geom_Surface)& so = BRep_Tool::Surface(original, lo);
  const Handle(Geom_Surface)& st = BRep_Tool::Surface(other, lt);
  if (!so.IsNull() && so == st && lo.IsEqual(lt)) return original.Orientation() == other.Orientation();
  const std::optional<FacePoint> p = sample_point(original);
  if (!p) return true;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(other);
  if (surface.IsNull()) return true;
  GeomAPI_ProjectPointOnSurf projection(p->point, surface);
  if (projection.NbPoints() == 0) return true;
  double u, v;
  projection.LowerDistanceParameters(u, v);
  const std::optional<gp_Vec> n = oriented_normal(other, surface, u, v);
  return !n || n->Dot(p->normal) >= 0;
}

double area_of(const TopoDS_Shape& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  return props.Mass();
}

// Integral of the rule's "outward" component of the normal over the face,
// sampled on a grid of its parameter box (points inside the face only).
double outward_weight(const TopoDS_Face& face, const OutwardRule& rule) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) return 0;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  constexpr int kGrid = 8;
  const double du = (u1 - u0) / kGrid, dv = (v1 - v0) / kGrid;
  double weight = 0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const double u = u0 + (i + 0.5) * du, v = v0 + (j + 0.5) * dv;
      BRepClass_FaceClassifier inside(face, gp_Pnt2d(u, v), 1e-9);
      if (inside.State() != TopAbs_IN) continue;
      GeomLProp_SLProps props(surface, u, v, 1, 1e-9);
      if (!props.IsNormalDefined()) continue;
      const double element = props.D1U().Crossed(props.D1V()).Magnitude() * du * dv;
      gp_Vec n(props.Normal());
      if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
      double along = 0;
      switch (rule.kind) {
        case OutwardRule::Kind::plus_z: along = n.Z(); break;
        case OutwardRule::Kind::minus_z: along = -n.Z(); break;
        case OutwardRule::Kind::away_from_point: {
          const gp_Vec away(gp_Pnt(rule.point.x(), rule.point.y(), rule.point.z()), props.Value());
          if (away.Magnitude() > 0) along = n.Dot(away) / away.Magnitude();
          break;
        }
        case OutwardRule::Kind::none: break;
      }
      weight += along * element;
    }
  return weight;
}

// A face that closes on itself (a full sphere or torus): every edge is
// degenerate (a pole), a seam used twice by the face, or lies on another edge
// of the same face within `tolerance` — the two copies of a seam that IGES
// writes as separate boundary curves.
bool closes_on_itself(const TopoDS_Face& face, double tolerance) {
  struct Span {
    gp_Pnt a, m, b;
  };
  std::vector<Span> spans;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    if (BRep_Tool::IsClosed(edge, face)) continue;
    const BRepAdaptor_Curve c(edge);
    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
    spans.push_back({c.Value(t0), c.Value(0.5 * (t0 + t1)), c.Value(t1)});
  }
  for (std::size_t i = 0; i < spans.size(); ++i) {
    bool paired = false;
    for (std::size_t j = 0; j < spans.size() && !paired; ++j) {
      if (i == j || spans[i].m.Distance(spans[j].m) > tolerance) continue;
      paired = (spans[i].a.Distance(spans[j].a) <= tolerance && spans[i].b.Distance(spans[j].b) <= tolerance) ||
               (spans[i].a.Distance(spans[j].b) <= tolerance && spans[i].b.Distance(spans[j].a) <= tolerance);
    }
    if (!paired) return false;
  }
  return true;
}

// Whether an iso-line of `surface` shrinks to a point (a pole), on 9
// samples within 1e-7 mm: the line u = `at` (v from `from` to `to`) when
// `along_v`, else the line v = `at` (u from `from` to `to`).
bool collapsed_iso(const Handle(Geom_Surface)& surface, bool along_v, double at, double from, double to) {
  const gp_Pnt first = along_v ? surface->Value(at, from) : surface->Value(from, at);
  for (int k = 1; k <= 8; ++k) {
    const double t = from + (to - from) * k / 8;
    if (first.Distance(along_v ? surface->Value(at, t) : surface->Value(t, at)) > 1e-7) return false;
  }
  return true;
}

// The volume the whole surface of `face` encloses, counted with the face's
// orientation as BRepGProp counts a closed shell's (positive when the normal
// points out of it), or nullopt when the surface does not close on itself
// (in each parameter it must be closed or end at poles: a sphere, a torus;
// not a cylinder or a patch).
std::optional<double> whole_surface_volume(const TopoDS_Face& face) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) return std::nullopt;
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  if (!(std::abs(u0) < 1e50 && std::abs(u1) < 1e50 && std::abs(v0) < 1e50 && std::abs(v1) < 1e50))
    return std::nullopt;
  const bool closed_u = surface->IsUClosed() || (collapsed_iso(surface, true, u0, v0, v1) &&
                                                 collapsed_iso(surface, true, u1, v0, v1));
  const bool closed_v = surface->IsVClosed() || (collapsed_iso(surface, false, v0, u0, u1) &&
                                                 collapsed_iso(surface, false, v1, u0, u1));
  if (!closed_u || !closed_v) return std::nullopt;
  BRepBuilderAPI_MakeFace whole(surface, Precision::Confusion());
  if (!whole.IsDone()) return std::nullopt;
  GProp_GProps props;
  BRepGProp::VolumeProperties(whole.Face().Oriented(face.Orientation()), props);
  return props.Mass();
}

// One group of loose faces: a sewn shell (or a face that sewed to nothing).
struct Group {
  TopoDS_Shape shape;
  bool closed = false;
  std::vector<int> members;              // indices into the face map (0-based)
  std::vector<TopoDS_Face> oriented;     // each member as the group orients it
};

}  // namespace

OrientationOutcome orient_faces(const TopTools_IndexedMapOfShape& faces, const TopTools_IndexedMapOfShape& solids,
                                const CadImportOptions& options, const std::vector<bool>& turned) {
  OrientationOutcome out;
  out.faces.resize(static_cast<std::size_t>(faces.Extent()));

  // Faces of solids: the solid decides; an inside-out solid is turned.
  TopTools_IndexedMapOfShape solid_faces;
  for (int s = 1; s <= solids.Extent(); ++s) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(solids(s), props);
    const bool inside_out = props.Mass() < 0;
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(solids(s), TopAbs_FACE, own);
    for (int k = 1; k <= own.Extent(); ++k) {
      solid_faces.Add(own(k));
      if (const int index = faces.FindIndex(own(k)); index > 0)
        out.faces[static_cast<std::size_t>(index - 1)] = {inside_out, CadFaceOrientation::solid, true};
    }
  }
  std::vector<int> loose;
  for (int i = 1; i <= faces.Extent(); ++i)
    if (!solid_faces.Contains(faces(i))) loose.push_back(i);
  if (loose.empty()) return out;

  // Sew the loose faces and orient each shell consistently.
  std::vector<Group> groups;
  std::unordered_map<const TopoDS_TShape*, std::pair<std::size_t, TopoDS_Face>> in_group;
  BRepBuilderAPI_Sewing sewing(options.sewing_tolerance > 0 ? options.sewing_tolerance : 1e-7);
  if (options.sewing_tolerance > 0) {
    for (const int i : loose) sewing.Add(faces(i));
    sewing.Perform();
    for (TopExp_Explorer shells(sewing.SewedShape(), TopAbs_SHELL); shells.More(); shells.Next()) {
      ShapeFix_Shell fix(TopoDS::Shell(shells.Current()));
      fix.Perform();
      for (TopExp_Explorer fixed(fix.Shape(), TopAbs_SHELL); fixed.More(); fixed.Next()) {
        Group g;
        g.shape = fixed.Current();
        g.closed = BRep_Tool::IsClosed(g.shape);
        for (TopExp_Explorer f(g.shape, TopAbs_FACE); f.More(); f.Next())
          in_group[f.Current().TShape().get()] = {groups.size(), TopoDS::Face(f.Current())};
        groups.push_back(std::move(g));
      }
    }
  }
  for (const int i : loose) {
    const TopoDS_Shape& original = faces(i);
    const TopoDS_Shape sewn =
        options.sewing_tolerance > 0 && sewing.IsModified(original) ? sewing.Modified(original) : original;
    auto it = in_group.find(sewn.TShape().get());
    if (it == in_group.end()) {  // sewed to nothing: a group of its own
      Group g;
      g.shape = original;
      g.closed = closes_on_itself(TopoDS::Face(original), std::max(options.sewing_tolerance, 1e-7));
      g.members.push_back(i - 1);
      g.oriented.push_back(TopoDS::Face(original));
      groups.push_back(std::move(g));
      continue;
    }
    Group& g = groups[it->second.first];
    g.members.push_back(i - 1);
    g.oriented.push_back(it->second.second);
  }

  for (Group& g : groups) {
    if (g.members.empty()) continue;
    if (!g.closed && g.members.size() == 1)
      g.closed = closes_on_itself(g.oriented[0], std::max(options.sewing_tolerance, 1e-7));
    if (g.members.size() > 1) ++out.sewn_shells;
    // Per member: does the group's orientation agree with the file's?
    std::vector<bool> agrees(g.members.size());
    double agreeing_area = 0;
    for (std::size_t k = 0; k < g.members.size(); ++k) {
      const TopoDS_Face& original = TopoDS::Face(faces(g.members[k] + 1));
      agrees[k] = same_sense(original, g.oriented[k]);
      // The size of the face: OpenCASCADE integrates over the face's own
      // pcurves, which for a boundary the file gives in model space only
      // may run the wrong way round a hole across the seam and make the
      // integral negative (a lone ring with such a hole was turned round).
      agreeing_area += (agrees[k] ? 1 : -1) * std::abs(area_of(original));
    }
    bool turn = false;  // turn the whole group round
    CadFaceOrientation basis = CadFaceOrientation::file;
    if (g.closed) {
      ++out.closed_shells;
      GProp_GProps props;
      BRepGProp::VolumeProperties(g.shape, props);
      double volume = props.Mass();
      // A turned face keeps the rest of its closed surface instead of
      // OpenCASCADE's region, on the other side of the same edges, and is
      // turned round to run its edges as its neighbours do: its share of
      // the volume is the whole surface's less OpenCASCADE's region's,
      // counted the other way, i.e. the shell's volume less the whole
      // surface's (counted with the face as the shell orients it).
      for (std::size_t k = 0; k < g.members.size(); ++k) {
        const std::size_t index = static_cast<std::size_t>(g.members[k]);
        if (index >= turned.size() || !turned[index]) continue;
        if (const std::optional<double> whole = whole_surface_volume(g.oriented[k])) volume -= *whole;
      }
      turn = volume < 0;
      basis = CadFaceOrientation::closed_shell;
    } else if (options.outward.kind != OutwardRule::Kind::none) {
      double weight = 0;
      for (const TopoDS_Face& f : g.oriented) weight += outward_weight(f, options.outward);
      turn = weight < 0;
      basis = CadFaceOrientation::rule;
    } else {
      turn = agreeing_area < 0;  // keep the file's sense of most of the area
    }
    for (std::size_t k = 0; k < g.members.size(); ++k)
      out.faces[static_cast<std::size_t>(g.members[k])] = {agrees[k] == turn, basis, g.members.size() > 1};
  }
  return out;
}

}  // namespace furrow::cad
