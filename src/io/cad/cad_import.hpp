#pragma once
// CAD import: STEP (AP203/AP214/AP242) and IGES parts read through
// OpenCASCADE and turned into Furrow faces (docs/formats.md "CAD import").
//
// Every face of every solid, shell or free face becomes one Face:
// - its surface becomes one NURBS patch over the face's parameter rectangle:
//   planes, cylinders, cones, spheres, tori, linear extrusions, revolutions,
//   B-splines, Beziers and offsets with an elementary equivalent are converted
//   exactly (rational B-splines); anything else (an offset of a free-form
//   surface, ...) is approximated within options.approximation_tolerance and
//   the face report says so. Each conversion is checked against OpenCASCADE's
//   own surface on a grid and the largest deviation is reported per face.
// - its boundary wires become uv loops of a Trim (even-odd), sampled until the
//   polygon is within options.trim_chord_tolerance of the true boundary in 3-D
//   (balanced so that areas come out unbiased: cad_trim_polygon.hpp).
//   Loops are moved into the NURBS parameters (the conversion reparametrises
//   circles; see cad_parameter_map.hpp) and unwrapped across periodic seams,
//   so a closed cylinder, sphere or torus face is one continuous patch whose
//   seam lies on the domain edge (a hole across that seam is cut out on both
//   sides). A loop that is the whole rectangle gives an untrimmed face.
// - its normal points out of the material: OpenCASCADE's face orientation
//   (REVERSED flips Su x Sv) is carried into Face::reversed(), after the
//   faces are oriented (cad_orientation.hpp): by their solid, by the closed
//   shell loose faces sew into, by options.outward for open shells, or — when
//   nothing decides it — as the file has most of its shell (reported as
//   undecided per face).
// - its name is the face's name in the file (STEP ADVANCED_FACE name, IGES
//   entity name or label) when it has one, else "face_<index>" (index in
//   walking order, as `furrow info` numbers faces); duplicates get "_<index>".
// - source_type records the original surface: plane, cylinder, cone, sphere,
//   torus, extrusion, revolution, offset, b-spline, bezier, other.
// Geometry is in millimetres whatever the file's units (OpenCASCADE converts;
// Part::source_units records the file's length unit).
//
// Errors are InputError naming the file, and the face where one is to blame:
// a missing or unreadable file, a file that is not STEP/IGES, a file with no
// faces, a face entity OpenCASCADE cannot translate, a face whose surface or
// trim cannot be converted. With options.skip_bad_faces such faces are left
// out and listed in CadImportResult::skipped instead (the import still fails
// when nothing is left).
//
// This header is free of OpenCASCADE. The import runs in the CAD module
// furrow_cad.so (src/io/cad/occt/, the only files that include OpenCASCADE
// headers), loaded on the first call (docs/architecture.md "Modules loaded on
// demand"): the file's name, its first bytes and the options are checked
// before. A module that cannot be found or is of another version is a
// RuntimeModuleError (base/runtime_module.hpp), not an InputError.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geometry/part.hpp"

namespace furrow {

// How the side of the material is decided for faces that close no volume
// (docs/formats.md "Orientation").
struct OutwardRule {
  enum class Kind { none, plus_z, minus_z, away_from_point };
  Kind kind = Kind::none;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // [mm], away_from_point: inside the material
};
// "+z", "-z" or "point:x,y,z" [mm]; throws InputError naming `where`.
OutwardRule parse_outward_rule(const std::string& text, const std::string& where);

enum class CadFaceOrientation {
  solid,         // a solid of the file
  closed_shell,  // loose faces that sew into a closed shell
  rule,          // an open shell, by options.outward
  file           // undecided: the file's sense (of most of its sewn shell)
};
const char* to_string(CadFaceOrientation basis);

constexpr double kMaxSewingTolerance = 1.0;  // mm

struct CadImportOptions {
  // Loose faces are sewn into shells when their edges meet within this
  // distance [mm], at most kMaxSewingTolerance (InputError beyond); 0
  // switches sewing off (each loose face its own shell).
  double sewing_tolerance = 1e-3;
  OutwardRule outward;
  // Trim polygons (cad_trim_polygon.hpp): largest 3-D chord sag [mm] of a
  // polygon edge, measured at the boundary curve's parameter midpoint; the
  // area-balanced polygon stays within about 2/3 of it on either side ...
  double trim_chord_tolerance = 1e-5;
  // ... and largest (s,t) sag as a fraction of the domain's width/height
  // (guards corners of the parameter plane that 3-D hardly sees: poles).
  double trim_uv_tolerance = 1e-4;
  // Halvings of a polygon edge before the tolerance is given up (reported).
  int trim_max_subdivisions = 24;
  // Surfaces with no exact NURBS form are approximated to this 3-D tolerance
  // [mm] with at most this degree and number of segments per direction.
  double approximation_tolerance = 1e-5;
  int approximation_max_degree = 9;
  int approximation_max_segments = 256;
  // An exact conversion must match OpenCASCADE's surface within this [mm] on
  // the check grid (rounding only; a larger deviation means a bug or a broken
  // surface and fails the face).
  double exact_tolerance = 1e-7;
  // Leave out faces that cannot be translated or converted (listed in
  // CadImportResult::skipped) instead of failing the import.
  bool skip_bad_faces = false;
  // Called after each face with (faces done, faces total); may be empty.
  std::function<void(std::size_t, std::size_t)> progress;
};

struct CadFaceReport {
  std::string name, source_type;
  std::string entity;            // where it is in the file: "#437" (STEP), "D123" (IGES)
  bool exact = true;             // false: the surface was approximated
  double deviation = 0;          // largest sampled |NURBS - original surface| [mm]
  double approximation_bound = 0;  // OpenCASCADE's error bound of an approximation [mm]
  int loops = 0;                 // trim loops kept (0 = untrimmed rectangle)
  int trim_vertices = 0;
  double trim_deviation = 0;     // largest chord sag of the trim polygon before balancing [mm]
  bool trim_tolerance_met = true;  // false when trim_max_subdivisions stopped the refinement
  CadFaceOrientation orientation = CadFaceOrientation::file;
  bool flipped = false;          // turned round against the file's orientation
};

struct CadSkippedFace {
  std::string name, entity, reason;
};

struct CadImportResult {
  Part part;
  std::string format;                // "STEP" or "IGES"
  std::vector<std::string> products; // product names (STEP) in file order
  std::size_t solids = 0;            // closed solids in the file
  std::size_t free_faces = 0;        // faces not bounding a solid
  int sewn_shells = 0;               // shells the free faces were sewn into
  int closed_shells = 0;             // of which closed
  std::vector<CadFaceReport> faces;  // parallel to part.faces
  std::vector<CadSkippedFace> skipped;
};

// True for the extensions the importer reads: .step .stp .iges .igs (any case).
bool is_cad_file(const std::string& path);

CadImportResult import_cad(const std::string& path, const CadImportOptions& options = {});

}  // namespace furrow
