#pragma once
// Which way each face of a CAD file points: out of the material, decided by
// topology where the file allows it (docs/formats.md "Orientation").
//
// - Faces of a closed solid: the solid's own orientation, checked by its
//   signed volume (a solid whose volume comes out negative is inside out and
//   all its faces are turned).
// - Faces bounding no solid (IGES surface models, loose STEP faces): sewn
//   with OpenCASCADE within `sewing_tolerance`, their shells oriented
//   consistently (neighbours traverse a shared edge in opposite senses);
//   a shell that closes is made a solid and oriented by its volume.
// - An open shell has no inside: the user's rule decides it (+z: the
//   area-weighted mean normal points up; point: normals point away from a
//   point inside the material); without a rule the shell keeps the sense
//   most of its area had in the file and its faces are reported undecided.
//
// The faces themselves are not replaced: sewing only tells which faces are
// neighbours; the import converts the file's own faces and applies `flip`.
// OpenCASCADE types stay in src/io/cad/ (cad_import.hpp).
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <vector>

#include "io/cad/cad_import.hpp"

namespace furrow::cad {

struct FaceSense {
  bool flip = false;  // turn the file's orientation round
  CadFaceOrientation basis = CadFaceOrientation::file;
  // The sense came from the face's neighbours (a solid, a sewn shell of two
  // or more faces), through the way its edges run, not from the face alone.
  bool from_neighbours = false;
};

struct OrientationOutcome {
  std::vector<FaceSense> faces;  // parallel to the face map given
  int sewn_shells = 0;           // shells of two or more free faces after sewing
  int closed_shells = 0;         // of which closed (made solids)
};

// `faces` is the file's face map (TopExp::MapShapes order, as the import
// walks it); `solids` the file's solids. `turned` (parallel to `faces`, or
// empty) flags faces whose loop, rebuilt from the file's model-space curves,
// encloses the region on the other side of the face's edges than
// OpenCASCADE's face does (FaceWires::turned, cad_face_trims.hpp): on a
// closed surface (a sphere) that region is the rest of the surface, and a
// closed shell's volume, which says which way is out, is corrected for it
// (OpenCASCADE's volume counts the face's own region: a ball cut through
// its pole, written inside out, came in as the cut-off cap, and its shell
// was turned inside out). Throws Standard_Failure only for OpenCASCADE's
// own failures (the caller reports them for the file).
OrientationOutcome orient_faces(const TopTools_IndexedMapOfShape& faces, const TopTools_IndexedMapOfShape& solids,
                                const CadImportOptions& options, const std::vector<bool>& turned = {});

}  // namespace furrow::cad
