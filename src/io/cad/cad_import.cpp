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
#include "io/cad/cad_surface.hpp"
#include "io/cad/cad_trim_polygon.hpp"

namespace furrow {

namespace {

using cad::FaceFailure;
using cad::number_text;

enum class Format { step, iges };

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

Format format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".step" || ext == ".stp") return Format::step;
  if (ext == ".iges" || ext == ".igs") return Format::iges;
  throw InputError(path + ": not a CAD file name (expected .step, .stp, .iges or .igs)");
}

// Cheap signature check so that a wrong file gets a plain answer instead of
// whatever OpenCASCADE's parser makes of it.
void check_signature(const std::string& path, Format format) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (trim(head).empty()) throw InputError(path + ": the file is empty");
  if (format == Format::step) {
    std::size_t start = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 BOM
    start = head.find_first_not_of(" \t\r\n", start);
    if (start == std::string::npos || head.compare(start, 12, "ISO-10303-21") != 0)
      throw InputError(path + ": not a STEP file (a STEP file starts with \"ISO-10303-21;\")");
  } else {
    const std::string first_line = head.substr(0, head.find('\n'));
    if (first_line.size() < 73 || (first_line[72] != 'S' && first_line[72] != 'C'))
      throw InputError(path + ": not an IGES file (an IGES file starts with 80-column records, "
                              "the first with 'S' in column 73)");
  }
}

// ---------------------------------------------------------------- reading

// What the file itself says about a face's outer boundary in its own
// parameter plane (IGES trimmed surfaces; see file_boundary()).
struct FileBoundary {
  int sense = 0;                // +1 counterclockwise, -1 clockwise, 0 not given
  double rotation_extent = -1;  // range of the rotation angle v [rad] on a type 120, -1 if not one
};

struct FaceOrigin {
  std::string name, entity;
  FileBoundary boundary;
};

struct LoadedFile {
  TopoDS_Shape shape;
  std::string units = "mm";
  std::vector<std::string> products;
  std::unordered_map<const TopoDS_TShape*, FaceOrigin> origins;
  std::vector<CadSkippedFace> untranslated;  // face entities without a shape
};

std::string hstring(const Handle(TCollection_HAsciiString)& s) {
  return s.IsNull() ? std::string() : trim(s->ToCString());
}

std::string entity_label(const Handle(Interface_InterfaceModel)& model,
                         const Handle(Standard_Transient)& entity) {
  const std::string label = hstring(model->StringLabel(entity));
  return label.empty() ? "#" + std::to_string(model->Number(entity)) : label;
}

// Why OpenCASCADE could not read or translate an entity, from its checks.
std::string entity_problems(const Handle(Interface_InterfaceModel)& model,
                            const Handle(Transfer_TransientProcess)& process,
                            const Handle(Standard_Transient)& entity) {
  std::vector<std::string> messages;
  auto collect = [&](const Handle(Interface_Check)& check) {
    if (check.IsNull()) return;
    for (int k = 1; k <= check->NbFails(); ++k) messages.push_back(trim(check->CFail(k)));
    for (int k = 1; k <= check->NbWarnings(); ++k) messages.push_back(trim(check->CWarning(k)));
  };
  const int number = model->Number(entity);
  if (number > 0) {
    collect(model->Check(number, true));
    collect(model->Check(number, false));
  }
  collect(process->Check(entity));
  std::string text;
  for (const auto& m : messages) text += (text.empty() ? "" : "; ") + m;
  return text.empty() ? "OpenCASCADE could not translate it" : text;
}

// Whether OpenCASCADE tried to translate the entity (or could not even read
// it). A face no transferred shape refers to is neither, and is not an error.
bool attempted(const Handle(Interface_InterfaceModel)& model,
               const Handle(Transfer_TransientProcess)& process,
               const Handle(Standard_Transient)& entity) {
  const int number = model->Number(entity);
  const Handle(Interface_Check)& syntax = model->Check(number, true);
  return process->IsBound(entity) || (!syntax.IsNull() && syntax->HasFailed());
}

// Unknown entities (a misspelt or unsupported type) that a readable entity
// refers to, found in the raw parameters OpenCASCADE kept for it.
void collect_unknown(const Handle(Interface_InterfaceModel)& model, const Handle(StepData_UndefinedEntity)& raw,
                     std::vector<Handle(Standard_Transient)>& found, int depth) {
  if (raw.IsNull() || depth > 8) return;
  const Handle(Interface_UndefinedContent) content = raw->UndefinedContent();
  for (int k = 1; !content.IsNull() && k <= content->NbParams(); ++k) {
    if (!content->IsParamEntity(k)) continue;
    const Handle(Standard_Transient) e = content->ParamEntity(k);
    const auto sub = Handle(StepData_UndefinedEntity)::DownCast(e);
    if (sub.IsNull()) continue;
    if (sub->IsSub() || model->Number(e) == 0)
      collect_unknown(model, sub, found, depth + 1);  // a list in the parameters
    else if (std::find(found.begin(), found.end(), e) == found.end())
      found.push_back(e);
  }
}

// Strict import (docs/formats.md "CAD import"): every entity OpenCASCADE
// could not read is an error, not only faces. An entity with a failed syntax
// check (not a face: those are reported by the caller with their names) is
// reported through the unknown entities it refers to, when there are any, so
// the message names the misspelt one ("#17 (ADVANCED_FACX)"), else itself.
void add_unreadable_entities(const Handle(Interface_InterfaceModel)& model,
                             std::vector<CadSkippedFace>& untranslated) {
  std::set<std::string> reported;
  for (const CadSkippedFace& f : untranslated) reported.insert(f.entity);
  auto failed = [&](int i) {
    const Handle(Interface_Check)& syntax = model->Check(i, true);
    return model->IsErrorEntity(i) || (!syntax.IsNull() && syntax->HasFailed());
  };
  auto unknown_in = [&](int i) {
    std::vector<Handle(Standard_Transient)> unknown;
    if (model->IsRedefinedContent(i) && !model->ReportEntity(i).IsNull())
      collect_unknown(model, Handle(StepData_UndefinedEntity)::DownCast(model->ReportEntity(i)->Content()),
                      unknown, 0);
    return unknown;
  };
  // What a failed face refers to is reported with the face (by the caller).
  for (int i = 1; i <= model->NbEntities(); ++i)
    if (failed(i) && !Handle(StepShape_FaceSurface)::DownCast(model->Value(i)).IsNull())
      for (const Handle(Standard_Transient)& e : unknown_in(i)) reported.insert(entity_label(model, e));
  for (int i = 1; i <= model->NbEntities(); ++i) {
    if (!failed(i)) continue;
    const Handle(Interface_Check)& syntax = model->Check(i, true);
    const Handle(Standard_Transient) entity = model->Value(i);
    if (!Handle(StepShape_FaceSurface)::DownCast(entity).IsNull()) continue;
    std::string why;
    for (int k = 1; !syntax.IsNull() && k <= syntax->NbFails(); ++k)
      why += (why.empty() ? "" : "; ") + trim(syntax->CFail(k));
    if (why.empty()) why = "OpenCASCADE could not read it";
    const std::string label = entity_label(model, entity);
    const std::vector<Handle(Standard_Transient)> unknown = unknown_in(i);
    if (unknown.empty()) {
      if (reported.insert(label).second)
        untranslated.push_back({"", "entity " + label, "could not be read (" + why + ")"});
      continue;
    }
    for (const Handle(Standard_Transient)& e : unknown) {
      const auto raw = Handle(StepData_UndefinedEntity)::DownCast(e);
      const std::string unknown_label = entity_label(model, e);
      if (!reported.insert(unknown_label).second) continue;
      untranslated.push_back({"", "entity " + unknown_label + " (" + quote_field(raw->StepType()) + ")",
                              "not an entity type OpenCASCADE knows, referred to by " + label + " (" + why +
                                  ")"});
    }
  }
}

// ---------------------------------------------------------------- IGES boundary sense

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
    while (a1 <= a0) a1 += 2 * M_PI;
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

// Which way the outer boundary of an IGES trimmed surface (type 144) runs in
// the file's own parameter plane, and, on a surface of revolution (type
// 120, whose v is the rotation angle: IGES 5.3), over what range of angles.
// The sense is 0 when the file does not tell (no parameter-space curve,
// curve types not read by sample_parameter_curve, a degenerate loop).
//
// Why it matters: the surface's (u,v) rectangle in the file is not periodic,
// so a closed boundary curve there encloses one region whichever way it
// runs, and writers do not all run outer boundaries the same way. After
// OpenCASCADE's translation the same boundary lies on a periodic surface,
// where a boundary that runs from pole to pole (a lune of a sphere written
// as a surface of revolution) encloses the face on one side and the rest of
// the sphere on the other; only the way the boundary runs tells which.
// OpenCASCADE keeps the IGES surface normal (for type 120 its angle is the
// file's terminate angle minus v, its other parameter the file's u), so its
// parameter map keeps the sense of every loop; but (7.6) it routes the pole
// edges of a clockwise boundary around the other side of the sphere, and
// such a face came in as the rest of the sphere: a quarter sphere of
// 70.88 mm^2 as 212.65 mm^2 (docs/formats.md "CAD import", "IGES
// boundaries"). route_like_file() routes them back.
FileBoundary file_boundary(const Handle(IGESGeom_TrimmedSurface)& trimmed) {
  FileBoundary boundary;
  if (trimmed.IsNull() || !trimmed->HasOuterContour()) return boundary;
  const Handle(IGESGeom_CurveOnSurface) contour = trimmed->OuterContour();
  if (contour.IsNull()) return boundary;
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
  const Handle(IGESData_IGESEntity) surface = trimmed->Surface();
  if (!surface.IsNull() && surface->IsKind(STANDARD_TYPE(IGESGeom_SurfaceOfRevolution)))
    boundary.rotation_extent = v1 - v0;
  return boundary;
}

std::string unit_name(const std::string& occt_unit) {
  const std::string u = to_lower(trim(occt_unit));
  if (u == "mm" || u == "millimetre" || u == "millimeter") return "mm";
  if (u == "in" || u == "inch") return "inch";
  return u.empty() ? "mm" : u;
}

// A face without a name in the file, or a system's placeholder for none.
bool meaningful_name(const std::string& name) { return !name.empty() && name != "NONE"; }

LoadedFile read_file(const std::string& path, Format format) {
  std::unique_ptr<XSControl_Reader> reader;
  if (format == Format::step)
    reader = std::make_unique<STEPControl_Reader>();
  else
    reader = std::make_unique<IGESControl_Reader>();
  // Furrow works in millimetres: have OpenCASCADE convert every file to mm.
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");

  const char* kind = format == Format::step ? "STEP" : "IGES";
  const IFSelect_ReturnStatus status = reader->ReadFile(path.c_str());
  if (status == IFSelect_RetVoid)
    throw InputError(path + ": the " + std::string(kind) + " file holds no data");
  if (status != IFSelect_RetDone)
    throw InputError(path + ": not a readable " + std::string(kind) +
                     " file (OpenCASCADE could not parse it)");
  const Handle(Interface_InterfaceModel) model = reader->WS()->Model();
  if (model.IsNull() || model->NbEntities() == 0)
    throw InputError(path + ": the " + std::string(kind) + " file holds no entities");
  if (reader->NbRootsForTransfer() == 0)
    throw InputError(path + ": the file holds no shape to import (no solid, shell or surface)");
  reader->TransferRoots();

  LoadedFile file;
  file.shape = reader->OneShape();
  const Handle(Transfer_TransientProcess) process = reader->WS()->TransferReader()->TransientProcess();
  if (format == Format::step) {
    TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
    static_cast<STEPControl_Reader&>(*reader).FileUnits(lengths, angles, solid_angles);
    if (lengths.Length() >= 1) file.units = unit_name(lengths.Value(1).ToCString());
  } else {
    const Handle(IGESData_IGESModel) iges = Handle(IGESData_IGESModel)::DownCast(model);
    if (!iges.IsNull()) file.units = unit_name(hstring(iges->GlobalSection().UnitName()));
  }

  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) entity = model->Value(i);
    std::string name;
    if (format == Format::step) {
      if (const auto product = Handle(StepBasic_Product)::DownCast(entity); !product.IsNull()) {
        file.products.push_back(hstring(product->Name()));
        continue;
      }
      // Faces with geometry (ADVANCED_FACE, FACE_SURFACE); an ORIENTED_FACE
      // only points at one of those.
      const auto face = Handle(StepShape_FaceSurface)::DownCast(entity);
      if (face.IsNull()) continue;
      name = hstring(face->Name());
    } else {
      const auto iges = Handle(IGESData_IGESEntity)::DownCast(entity);
      if (iges.IsNull()) continue;
      if (iges->HasName()) name = hstring(iges->NameValue());
    }
    if (!meaningful_name(name)) name.clear();
    const TopoDS_Shape result = TransferBRep::ShapeResult(process, entity);
    if (!result.IsNull() && result.ShapeType() == TopAbs_FACE) {
      file.origins.emplace(result.TShape().get(),
                           FaceOrigin{name, entity_label(model, entity),
                                      file_boundary(Handle(IGESGeom_TrimmedSurface)::DownCast(entity))});
    } else if (result.IsNull() && format == Format::step && attempted(model, process, entity)) {
      file.untranslated.push_back({name, entity_label(model, entity),
                                   entity_problems(model, process, entity)});
    }
  }
  if (format == Format::step) add_unreadable_entities(model, file.untranslated);
  if (format == Format::iges) {
    // IGES faces are roots (trimmed/bounded surfaces, MSBO solids): a root
    // without a result is a face or solid OpenCASCADE could not translate.
    for (int r = 1; r <= reader->NbRootsForTransfer(); ++r) {
      const Handle(Standard_Transient) root = reader->RootForTransfer(r);
      if (!TransferBRep::ShapeResult(process, root).IsNull()) continue;
      const auto iges = Handle(IGESData_IGESEntity)::DownCast(root);
      std::string label = entity_label(model, root);
      if (!iges.IsNull())
        label += " (IGES type " + std::to_string(iges->TypeNumber()) + " form " +
                 std::to_string(iges->FormNumber()) + ")";
      file.untranslated.push_back({iges.IsNull() || !iges->HasName() ? "" : hstring(iges->NameValue()),
                                   label, entity_problems(model, process, root)});
    }
  }
  return file;
}

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
  const Format format = format_of(path);
  check_signature(path, format);
  const QuietMessenger quiet;

  LoadedFile file;
  try {
    file = read_file(path, format);
  } catch (const Standard_Failure& e) {
    throw InputError(path + ": OpenCASCADE failed while reading the file: " + occt_text(e));
  }

  CadImportResult result;
  result.format = format == Format::step ? "STEP" : "IGES";
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
    FaceOrigin origin;
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
