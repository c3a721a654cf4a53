// Reading a STEP or IGES file with OpenCASCADE (contract in cad_reader.hpp).
#include "io/cad/occt/cad_reader.hpp"

#include <BRepTools_ReShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESGeom_CurveOnSurface.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESGeom_TrimmedSurface.hxx>
#include <Interface_Check.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_ReportEntity.hxx>
#include <Interface_Static.hxx>
#include <Interface_UndefinedContent.hxx>
#include <STEPControl_Reader.hxx>
#include <StepBasic_Product.hxx>
#include <StepData_UndefinedEntity.hxx>
#include <StepShape_FaceSurface.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow::cad {

namespace {

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

// The file's length unit as Part::source_units names it (OpenCASCADE's
// spelling varies with the format and the writer).
std::string unit_name(const std::string& occt_unit) {
  const std::string u = to_lower(trim(occt_unit));
  if (u == "mm" || u == "millimetre" || u == "millimeter") return "mm";
  if (u == "in" || u == "inch") return "inch";
  return u.empty() ? "mm" : u;
}

// A face without a name in the file, or a system's placeholder for none.
bool meaningful_name(const std::string& name) { return !name.empty() && name != "NONE"; }

// The wire OpenCASCADE made of an IGES entity, null when it made none.
TopoDS_Wire wire_of(const Handle(Transfer_TransientProcess)& process, const Handle(Standard_Transient)& entity) {
  if (entity.IsNull()) return {};
  const TopoDS_Shape shape = TransferBRep::ShapeResult(process, entity);
  return !shape.IsNull() && shape.ShapeType() == TopAbs_WIRE ? TopoDS::Wire(shape) : TopoDS_Wire();
}

// What OpenCASCADE made of a trimmed surface's model-space-only outer
// boundary (FileBoundary::curves and ::wire): the 142's curve C is a
// composite (type 102) whose translation keeps every curve; a single curve
// is not bound to a shape of its own, and then the 142's healed wire serves.
void add_outer_wires(const Handle(Transfer_TransientProcess)& process,
                     const Handle(IGESGeom_TrimmedSurface)& trimmed, FileBoundary& boundary) {
  if (trimmed.IsNull() || !boundary.model_space_only || !trimmed->HasOuterContour()) return;
  const Handle(IGESGeom_CurveOnSurface) contour = trimmed->OuterContour();
  if (contour.IsNull()) return;
  boundary.wire = wire_of(process, contour);
  boundary.curves = wire_of(process, contour->Curve3D());
  if (boundary.curves.IsNull()) boundary.curves = boundary.wire;
}

// OpenCASCADE's healing splits a face whose wires it finds outside its
// outer one into several faces (ShapeFix_Face's split of a face with
// several outer wires): a lune from pole to pole with a hole, whose pole
// edges it routed around the rest of the sphere, came in as the rest of the
// sphere and the hole's disc. For an IGES boundary given in model space
// only the importer builds the outer loop itself (cad_model_space_loop.hpp),
// so the pieces are put back into one face on their common surface: the
// piece holding the outer boundary's wire first (its orientation is the
// face's), the other pieces' wires its holes, turned round (each ran around
// its own piece). `outer_piece` is set to the piece holding the outer wire,
// as `result` holds it. Returns a null face when the pieces do not share one
// surface or none holds the outer wire.
TopoDS_Face merge_pieces(const TopoDS_Shape& result, const TopoDS_Wire& outer, TopoDS_Face& outer_piece) {
  std::vector<TopoDS_Face> pieces;
  for (TopExp_Explorer f(result, TopAbs_FACE); f.More(); f.Next()) pieces.push_back(TopoDS::Face(f.Current()));
  if (pieces.size() < 2 || outer.IsNull()) return {};
  auto holds_outer = [&](const TopoDS_Face& face) {
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
      for (TopExp_Explorer o(outer, TopAbs_EDGE); o.More(); o.Next())
        if (e.Current().IsSame(o.Current()) && !BRep_Tool::Degenerated(TopoDS::Edge(o.Current()))) return true;
    return false;
  };
  const auto first = std::find_if(pieces.begin(), pieces.end(), holds_outer);
  if (first == pieces.end()) return {};
  std::rotate(pieces.begin(), first, first + 1);
  outer_piece = pieces.front();
  TopLoc_Location location;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(pieces.front(), location);
  for (const TopoDS_Face& piece : pieces) {
    TopLoc_Location other;
    if (BRep_Tool::Surface(piece, other) != surface || !other.IsEqual(location)) return {};
  }
  BRep_Builder builder;
  TopoDS_Face merged;
  builder.MakeFace(merged, surface, location, BRep_Tool::Tolerance(pieces.front()));
  for (std::size_t k = 0; k < pieces.size(); ++k)
    for (TopoDS_Iterator w(pieces[k].Oriented(TopAbs_FORWARD)); w.More(); w.Next())
      builder.Add(merged, k == 0 ? w.Value() : w.Value().Reversed());
  merged.Orientation(outer_piece.Orientation());
  return merged;
}

}  // namespace

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

  // Faces OpenCASCADE split that are put back together (merge_pieces()).
  const Handle(BRepTools_ReShape) merges = new BRepTools_ReShape;
  bool merged_any = false;
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
    TopoDS_Shape result = TransferBRep::ShapeResult(process, entity);
    const auto trimmed = Handle(IGESGeom_TrimmedSurface)::DownCast(entity);
    FileBoundary boundary = file_boundary(trimmed);
    add_outer_wires(process, trimmed, boundary);
    if (!result.IsNull() && result.ShapeType() != TopAbs_FACE && boundary.model_space_only) {
      TopoDS_Face outer_piece;
      if (const TopoDS_Face merged = merge_pieces(result, boundary.wire, outer_piece); !merged.IsNull()) {
        for (TopExp_Explorer f(result, TopAbs_FACE); f.More(); f.Next())
          if (f.Current().IsSame(outer_piece))
            merges->Replace(f.Current(), merged);
          else
            merges->Remove(f.Current());
        result = merged;
        boundary.merged = true;
        merged_any = true;
      }
    }
    if (!result.IsNull() && result.ShapeType() == TopAbs_FACE) {
      file.origins.emplace(result.TShape().get(), FaceOrigin{name, entity_label(model, entity), boundary});
    } else if (result.IsNull() && format == Format::step && attempted(model, process, entity)) {
      file.untranslated.push_back({name, entity_label(model, entity),
                                   entity_problems(model, process, entity)});
    }
  }
  if (merged_any) file.shape = merges->Apply(file.shape);
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

}  // namespace furrow::cad
