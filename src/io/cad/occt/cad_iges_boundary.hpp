#pragma once
// What an IGES file says about a face's outer boundary in the file's own
// parameter plane, read before OpenCASCADE's translation loses it
// (docs/formats.md "CAD import", "IGES boundaries").
//
// file_boundary(): which way the outer boundary of an IGES trimmed surface
// (type 144) runs in the file's own parameter plane, and, on a surface of
// revolution (type 120, whose v is the rotation angle: IGES 5.3), over what
// range of angles. The sense is 0 when the file does not tell (no
// parameter-space curve, a curve type other than 100/102/106/110/126, a curve
// moved by a transformation matrix, a degenerate loop).
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
// boundaries"). cad_face_trims.hpp routes them back (route_like_file()).
//
// Values are in the file's parameter plane as the file writes it (rotation
// angles in radians). Never fails: what cannot be read gives the "not given"
// values below.
#include <IGESGeom_TrimmedSurface.hxx>
#include <TopoDS_Wire.hxx>

namespace furrow::cad {

// What the file itself says about a face's outer boundary in its own
// parameter plane (IGES trimmed surfaces; see file_boundary()).
struct FileBoundary {
  int sense = 0;                // +1 counterclockwise, -1 clockwise, 0 not given
  double rotation_extent = -1;  // range of the rotation angle v [rad] on a type 120, -1 if not one
  // The outer boundary is a type 142 without a parameter-space curve
  // (PPTR 0): only its model-space curve says where it runs.
  bool model_space_only = false;
  double surface_rotation = -1;  // terminate minus start angle of a type 120 [rad], -1 if not one
  // For a model-space-only outer boundary, set by the reader
  // (cad_reader.hpp) from OpenCASCADE's translation, null where it has none:
  // `curves`, the boundary's model-space curves as translated, every curve
  // of the file in its order and direction, before the face's healing,
  // which may drop some (the two copies of a seam that a face written
  // inside out runs down and up: the face then came in as the region on
  // the other side of its other curves); `wire`, the wire the face's
  // healing made of them, which tells the outer wire among a face's wires.
  TopoDS_Wire curves;
  TopoDS_Wire wire;
  // OpenCASCADE split the face into pieces, which the reader merged back
  // into one face (cad_reader.cpp merge_pieces()).
  bool merged = false;
};

// The outer boundary of a type 144 entity; "not given" for a null handle
// (any other entity type, once down-cast).
FileBoundary file_boundary(const Handle(IGESGeom_TrimmedSurface)& trimmed);

}  // namespace furrow::cad
