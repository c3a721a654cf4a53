#pragma once
// Reading a STEP or IGES file with OpenCASCADE (docs/formats.md "CAD
// import"): the file's shape, in millimetres, and what the file says about
// its faces that the shape does not keep (names, entity labels, IGES
// boundary senses and, for boundaries given in model space only, the
// boundary's curves as translated before healing), plus the entities
// OpenCASCADE could not read or translate.
//
// An IGES trimmed surface with a model-space-only outer boundary that
// OpenCASCADE's healing split into several faces (a lune from pole to pole
// with a hole: the rest of the sphere and the hole's disc) is put back into
// one face in the shape (docs/formats.md "IGES boundaries"), whose outer
// boundary the import then rebuilds (cad_model_space_loop.hpp).
//
// Strict mode: what OpenCASCADE could not read or translate is listed in
// LoadedFile::untranslated, so that the caller can fail the import or, with
// skip_bad_faces, report it: for STEP every such entity, not only faces (a
// misspelt entity type is named as such), for IGES every root (trimmed or
// bounded surface, solid) without a shape.
//
// Failures: InputError naming the file for a file OpenCASCADE cannot read
// or that holds no data or shapes (the name and the signature are checked
// before, by cad_file_format.hpp).
// OpenCASCADE's Standard_Failure may escape read_file() (the caller reports
// it against the file). OpenCASCADE's messenger prints while reading; the
// caller silences it.
#include <TopoDS_Shape.hxx>
#include <TopoDS_TShape.hxx>

#include <string>
#include <unordered_map>
#include <vector>

#include "io/cad/occt/cad_iges_boundary.hpp"
#include "io/cad/cad_file_format.hpp"
#include "io/cad/cad_import.hpp"

namespace furrow::cad {

// Where a face of the shape comes from in the file.
struct FaceOrigin {
  std::string name;    // the face's name in the file, empty without a meaningful one
  std::string entity;  // "#437" (STEP), "D123" (IGES)
  FileBoundary boundary;
};

struct LoadedFile {
  TopoDS_Shape shape;                 // everything transferred, in millimetres
  std::string units = "mm";           // the file's length unit ("mm", "inch", ...)
  std::vector<std::string> products;  // STEP product names in file order
  // Keyed by the face's TShape, so any use of the face (either orientation,
  // any location) finds it.
  std::unordered_map<const TopoDS_TShape*, FaceOrigin> origins;
  // Faces without a shape, then (STEP) other unreadable entities, whose
  // CadSkippedFace::entity starts with "entity ".
  std::vector<CadSkippedFace> untranslated;
};

// Reads and transfers the whole file, converting it to millimetres (sets
// OpenCASCADE's global "xstep.cascade.unit" to MM to do so).
LoadedFile read_file(const std::string& path, Format format);

}  // namespace furrow::cad
