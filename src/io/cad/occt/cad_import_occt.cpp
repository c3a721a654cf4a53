// CAD import through OpenCASCADE (contract in cad_import.hpp), the body of
// the module furrow_cad.so (cad_module.hpp): the walk over the file's faces,
// one Furrow Face per OpenCASCADE face. The steps live in
// their own files: reading the file (cad_reader.hpp), the face's wires and
// parameter rectangle and its trim polygons (cad_face_trims.hpp), its
// surface as a NURBS (cad_surface.hpp). Their failures end here:
// FaceFailure and OpenCASCADE's exceptions (Standard_Failure, not
// std::exception) become InputError naming the file and the face, or a
// skipped face with options.skip_bad_faces.
#include "io/cad/cad_module.hpp"

#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Standard_Failure.hxx>
#include <TopAbs.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <cstddef>
#include <exception>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cad/cad_file_format.hpp"
#include "io/cad/cad_parameter_map.hpp"
#include "io/cad/occt/cad_face_trims.hpp"
#include "io/cad/occt/cad_occt_internal.hpp"
#include "io/cad/occt/cad_orientation.hpp"
#include "io/cad/occt/cad_reader.hpp"
#include "io/cad/occt/cad_surface.hpp"

namespace furrow {

namespace {

// OpenCASCADE's message, or the exception's type when it gives none.
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

struct ConvertedFace {
  Face face;
  CadFaceReport report;
};

// A face's surface without rectangular trims and its wires: taken before
// the faces are oriented, which needs to know which faces' loops enclose
// the other side of their edges (FaceWires::turned).
struct PreparedFace {
  Handle(Geom_Surface) basis;
  cad::FaceWires wires;
};

PreparedFace prepare_face(const TopoDS_Face& face, const cad::FileBoundary& file) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) throw cad::FaceFailure("it has no surface");
  PreparedFace prepared;
  prepared.basis = cad::strip_trim(surface);
  prepared.wires = cad::face_wires(face, prepared.basis, file);
  return prepared;
}

// One face, in the order the steps need each other: the wires give the
// parameter rectangle (prepare_face()), the surface is converted over that
// rectangle, the trims are carried into the conversion's parameters, and
// the normal's sense is compared last.
ConvertedFace convert_face(const TopoDS_Face& face, const std::string& name, const PreparedFace& prepared,
                           const cad::FaceSense& sense, const CadImportOptions& options) {
  const Handle(Geom_Surface)& basis = prepared.basis;
  CadFaceReport report;
  report.name = name;
  report.source_type = cad::source_type(basis);

  const cad::FaceWires& wires = prepared.wires;
  const ParameterDomain& bounds = wires.bounds;

  const cad::Conversion conversion = cad::convert_surface(basis, bounds, options);
  report.exact = conversion.exact;
  report.approximation_bound = conversion.bound;
  NurbsSurface nurbs = cad::to_nurbs(conversion.nurbs, "face " + quote_field(name));
  ParameterMap map;
  report.deviation = cad::carry_parameters(nurbs, basis, bounds, conversion.exact, options, map);

  cad::TrimLoops trims = cad::trim_loops(wires, nurbs, map, options);
  report.loops = static_cast<int>(trims.loops.size());
  for (const auto& loop : trims.loops) report.trim_vertices += static_cast<int>(loop.size());
  report.trim_deviation = trims.worst_sag;
  report.trim_tolerance_met = trims.tolerance_met;

  // Normals out of the material: OpenCASCADE's face orientation, and the
  // NURBS's own sense against the original surface's.
  const bool flipped = !cad::same_sense(nurbs, map, basis, bounds);
  // A loop rebuilt from model-space curves that encloses its region on the
  // other side than OpenCASCADE's face turns the face in a shell, whose
  // sense came from the way the face's edges run (cad_model_space_loop.hpp);
  // a face on its own keeps the file's surface normal.
  const bool turned = wires.turned && sense.from_neighbours;
  const bool reversed = (((face.Orientation() == TopAbs_REVERSED) != flipped) != sense.flip) != turned;
  report.orientation = sense.basis;
  report.flipped = sense.flip;

  Trim trim(std::move(trims.loops), "face " + quote_field(name) + " trim");
  // Recognised on the exact NURBS, so what the part file says is what the
  // computation uses (an approximated face is not claimed to be elementary).
  std::optional<AnalyticSurface> analytic;
  if (conversion.exact) analytic = recognise_analytic(nurbs);
  Face converted(name, std::move(nurbs), std::move(trim), reversed, report.source_type);
  converted.set_analytic(std::move(analytic));
  converted.set_orientation_established(sense.basis == CadFaceOrientation::solid ||
                                        sense.basis == CadFaceOrientation::closed_shell);
  return {std::move(converted), report};
}

}  // namespace

namespace cad {

CadImportResult import_with_occt(const std::string& path, const CadImportOptions& options) {
  const cad::Format format = cad::format_of(path);
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
    if (entity.rfind("entity ", 0) == 0) return entity;  // not a face (cad_reader.hpp, strict mode)
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

  // Each face's wires first (the orientation needs FaceWires::turned); a
  // face that fails here is reported below, in its turn.
  auto origin_of = [&file](const TopoDS_Face& face) {
    const auto it = file.origins.find(face.TShape().get());
    return it == file.origins.end() ? cad::FaceOrigin() : it->second;
  };
  std::vector<std::optional<PreparedFace>> prepared(static_cast<std::size_t>(faces.Extent()));
  std::vector<std::string> failures(prepared.size());
  std::vector<bool> turned(prepared.size(), false);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const std::size_t index = static_cast<std::size_t>(i - 1);
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    try {
      prepared[index] = prepare_face(face, origin_of(face).boundary);
      turned[index] = prepared[index]->wires.turned;
    } catch (const cad::FaceFailure& e) {
      failures[index] = e.what();
    } catch (const InputError& e) {
      failures[index] = e.what();
    } catch (const Standard_Failure& e) {
      failures[index] = "OpenCASCADE failed on it: " + occt_text(e);
    }
  }

  cad::OrientationOutcome senses;
  try {
    senses = cad::orient_faces(faces, solids, options, turned);
  } catch (const Standard_Failure& e) {
    throw InputError(path + ": OpenCASCADE failed while sewing and orienting the faces: " + occt_text(e));
  }
  result.sewn_shells = senses.sewn_shells;
  result.closed_shells = senses.closed_shells;

  std::set<std::string> used_names;
  const std::size_t total = static_cast<std::size_t>(faces.Extent());
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    const std::size_t index = static_cast<std::size_t>(i - 1);
    const cad::FaceOrigin origin = origin_of(face);
    std::string name = origin.name.empty() ? "face_" + std::to_string(index) : origin.name;
    if (used_names.count(name)) name += "_" + std::to_string(index);
    std::string failure = failures[index];
    if (failure.empty()) try {
      ConvertedFace converted = convert_face(face, name, *prepared[index], senses.faces[index], options);
      converted.report.entity = origin.entity;
      if (!solid_faces.Contains(face)) ++result.free_faces;
      used_names.insert(name);
      result.part.faces.push_back(std::move(converted.face));
      result.faces.push_back(std::move(converted.report));
    } catch (const cad::FaceFailure& e) {
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

}  // namespace cad

}  // namespace furrow

// The module's two exported functions (cad_module.hpp); everything else in
// it is hidden.
extern "C" __attribute__((visibility("default"))) const char* furrow_module_version() { return FURROW_VERSION; }

extern "C" __attribute__((visibility("default"))) int furrow_cad_import(const std::string* path,
                                                                      const furrow::CadImportOptions* options,
                                                                      furrow::CadImportResult* result,
                                                                      std::string* message) {
  using furrow::cad::ModuleOutcome;
  try {
    *result = furrow::cad::import_with_occt(*path, *options);
    return static_cast<int>(ModuleOutcome::ok);
  } catch (const furrow::InputError& e) {
    *message = e.what();
    return static_cast<int>(ModuleOutcome::input_error);
  } catch (const std::bad_alloc&) {
    return static_cast<int>(ModuleOutcome::out_of_memory);
  } catch (const std::exception& e) {
    *message = e.what();
    return static_cast<int>(ModuleOutcome::failure);
  } catch (const Standard_Failure& e) {
    *message = *path + ": OpenCASCADE failed: " + furrow::occt_text(e);
    return static_cast<int>(ModuleOutcome::input_error);
  } catch (...) {
    *message = *path + ": the CAD reader failed with an unknown exception";
    return static_cast<int>(ModuleOutcome::failure);
  }
}
