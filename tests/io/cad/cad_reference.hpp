#pragma once
// Reference CAD models built with OpenCASCADE inside the tests, written to
// STEP/IGES, and OpenCASCADE's own answers about them (areas, inside/outside,
// curvature) to check the importer against.
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevolution.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Writer.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Trsf.hxx>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace furrow::test {

inline gp_Pnt occ(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }
inline Eigen::Vector3d eig(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Eigen::Vector3d eig(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }

// OpenCASCADE's writers print statistics; the tests' output stays readable.
inline void silence_occt() { Message::DefaultMessenger()->ChangePrinters().Clear(); }

struct ReferenceModel {
  TopoDS_Shape shape;  // compound of the solids
  std::vector<TopoDS_Shape> solids;
};

// Geometry of the model (mm), also used by the tests' analytic oracles.
struct ReferenceGeometry {
  static constexpr double box_x = 80, box_y = 60, box_z = 20;
  static constexpr double boss_x = 20, boss_y = 30, boss_r = 8, boss_h = 15;
  static constexpr double dimple_x = 55, dimple_y = 30, dimple_z = 26, dimple_r = 10;
};

inline TopoDS_Compound compound_of(const std::vector<TopoDS_Shape>& shapes) {
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const auto& s : shapes) builder.Add(compound, s);
  return compound;
}

inline Handle(Geom_BSplineSurface) freeform_surface() {
  TColgp_Array2OfPnt pts(1, 5, 1, 4);
  for (int i = 1; i <= 5; ++i)
    for (int j = 1; j <= 4; ++j)
      pts(i, j) = gp_Pnt(250 + 10 * (i - 1), 10 * (j - 1), 20 + 3 * std::sin(i) * std::cos(0.7 * j));
  return GeomAPI_PointsToBSplineSurface(pts).Surface();
}

// A box with a cylindrical boss and a spherical dimple (planes with holes, a
// convex cylinder, a concave sphere), a ball, a ring (torus), a block with a
// free-form B-spline top (and extruded sides), a truncated cone and a vase
// revolved from a B-spline meridian: a compound of six solids.
inline ReferenceModel make_reference_model() {
  using G = ReferenceGeometry;
  TopoDS_Shape block = BRepPrimAPI_MakeBox(G::box_x, G::box_y, G::box_z).Shape();
  const TopoDS_Shape boss =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(G::boss_x, G::boss_y, G::box_z), gp::DZ()), G::boss_r, G::boss_h)
          .Shape();
  block = BRepAlgoAPI_Fuse(block, boss).Shape();
  const TopoDS_Shape dimple =
      BRepPrimAPI_MakeSphere(gp_Pnt(G::dimple_x, G::dimple_y, G::dimple_z), G::dimple_r).Shape();
  block = BRepAlgoAPI_Cut(block, dimple).Shape();

  ReferenceModel model;
  TopExp_Explorer solids(block, TopAbs_SOLID);
  model.solids.push_back(solids.Current());
  model.solids.push_back(BRepPrimAPI_MakeSphere(gp_Pnt(140, 30, 15), 15).Shape());
  model.solids.push_back(BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(200, 30, 10), gp::DZ()), 20, 6).Shape());
  const TopoDS_Face top = BRepBuilderAPI_MakeFace(freeform_surface(), 1e-7).Face();
  model.solids.push_back(BRepPrimAPI_MakePrism(top, gp_Vec(0, 0, -15)).Shape());
  model.solids.push_back(BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(140, 100, 0), gp::DZ()), 12, 5, 18).Shape());
  TColgp_Array1OfPnt meridian(1, 5);
  const double radius[5] = {8, 11, 9, 6.5, 9};
  for (int k = 1; k <= 5; ++k) meridian(k) = gp_Pnt(radius[k - 1], 0, 5.0 * (k - 1));
  const Handle(Geom_BSplineCurve) profile = GeomAPI_PointsToBSpline(meridian).Curve();
  // Revolved about the z axis, then placed by a location (the importer must
  // apply locations): a located solid as assemblies are.
  gp_Trsf place;
  place.SetTranslation(gp_Vec(200, 100, 0));
  model.solids.push_back(
      BRepPrimAPI_MakeRevolution(gp::XOY(), profile).Shape().Moved(TopLoc_Location(place)));

  model.shape = compound_of(model.solids);
  return model;
}

inline void write_step(const TopoDS_Shape& shape, const std::string& path, const char* unit = "MM") {
  silence_occt();
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.unit", unit);
  writer.Transfer(shape, STEPControl_AsIs);
  const IFSelect_ReturnStatus status = writer.Write(path.c_str());
  Interface_Static::SetCVal("write.step.unit", "MM");
  if (status != IFSelect_RetDone) throw std::runtime_error("cannot write " + path);
}

inline void write_iges(const TopoDS_Shape& shape, const std::string& path) {
  silence_occt();
  IGESControl_Writer writer("MM", 0);  // mode 0: trimmed surfaces, the common IGES flavour
  writer.AddShape(shape);
  writer.ComputeModel();
  if (!writer.Write(path.c_str())) throw std::runtime_error("cannot write " + path);
}

inline std::vector<TopoDS_Face> faces_of(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  std::vector<TopoDS_Face> faces;
  for (int i = 1; i <= map.Extent(); ++i) faces.push_back(TopoDS::Face(map(i)));
  return faces;
}

inline double occt_area(const TopoDS_Face& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props, 1e-10);
  return props.Mass();
}

// Number of the model's solids that contain p (strictly, TopAbs_IN). The
// classifiers are built once per solid (building one is the expensive part).
class SolidsClassifier {
 public:
  explicit SolidsClassifier(const ReferenceModel& model) {
    for (const auto& s : model.solids) {
      classifiers_.emplace_back(new BRepClass3d_SolidClassifier(s));
      boxes_.emplace_back();
      BRepBndLib::Add(s, boxes_.back());
    }
  }
  int containing(const Eigen::Vector3d& p) {
    int count = 0;
    for (std::size_t k = 0; k < classifiers_.size(); ++k) {
      if (boxes_[k].IsOut(occ(p))) continue;
      classifiers_[k]->Perform(occ(p), 1e-9);
      if (classifiers_[k]->State() == TopAbs_IN) ++count;
    }
    return count;
  }

 private:
  std::vector<std::unique_ptr<BRepClass3d_SolidClassifier>> classifiers_;
  std::vector<Bnd_Box> boxes_;
};

// OpenCASCADE's principal curvatures at the point of a face nearest to p,
// signed for the face's outward normal with Furrow's convention (positive
// when the surface bends toward the normal); k1 >= k2. `distance` is how far
// p is from the surface. The projector is built once per face.
struct OcctCurvature {
  double k1 = 0, k2 = 0, distance = 0;
  bool defined = false;
};
class FaceProbe {
 public:
  explicit FaceProbe(const TopoDS_Face& face)
      : surface_(BRep_Tool::Surface(face)), reversed_(face.Orientation() == TopAbs_REVERSED) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    // A margin around the face's rectangle, inside the surface's own bounds.
    double su0, su1, sv0, sv1;
    surface_->Bounds(su0, su1, sv0, sv1);
    const double mu = 0.05 * (u1 - u0), mv = 0.05 * (v1 - v0);
    projector_.Init(surface_, std::max(u0 - mu, su0), std::min(u1 + mu, su1), std::max(v0 - mv, sv0),
                    std::min(v1 + mv, sv1));
  }
  OcctCurvature at(const Eigen::Vector3d& p) {
    OcctCurvature c;
    projector_.Perform(occ(p));
    if (!projector_.IsDone() || projector_.NbPoints() == 0) return c;
    double u = 0, v = 0;
    projector_.LowerDistanceParameters(u, v);
    c.distance = projector_.LowerDistance();
    GeomLProp_SLProps props(surface_, u, v, 2, 1e-9);
    if (!props.IsCurvatureDefined()) return c;
    // GeomLProp's curvatures are w.r.t. D1U x D1V, with Furrow's sign rule.
    const double sign = reversed_ ? -1 : 1;
    c.k1 = sign * props.MaxCurvature();
    c.k2 = sign * props.MinCurvature();
    if (c.k1 < c.k2) std::swap(c.k1, c.k2);
    c.defined = true;
    return c;
  }

 private:
  Handle(Geom_Surface) surface_;
  bool reversed_;
  GeomAPI_ProjectPointOnSurf projector_;
};

}  // namespace furrow::test
