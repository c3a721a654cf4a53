#pragma once
// How finely a face is sampled: cell counts along u and v for the curvature
// field (curvature_field.hpp).
//
// A user thinks in millimetres on the part ("one sample every 0.25 mm"), the
// field in parameter cells. face_extent measures how long a face is along u
// and along v on the surface, so a spacing turns into counts that give
// roughly square cells of that size whatever the parametrisation. The default
// spacing comes from the faces themselves: the longest side of the largest
// face gets kDefaultCellsAlongLongestSide cells, every face the same spacing.
//
// Limits are explicit: at least kMinCellsPerDirection cells per direction
// (a narrow fillet still gets a usable grid), at most kMaxCellsPerDirection
// and kMaxCellsPerFace (memory: a cell of the field takes about 90 bytes).
// A request beyond them is an InputError naming the face, never a silent clamp.
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct GridSize {
  int nu = 0, nv = 0;  // cells along u and along v
};

constexpr int kDefaultCellsAlongLongestSide = 400;
constexpr int kMinCellsPerDirection = 16;
constexpr int kMaxCellsPerDirection = 8000;
constexpr long kMaxCellsPerFace = 4L << 20;  // 4 Mi cells, ~670 MB of field
// All faces together: the fields are made one face at a time, but every
// face's cell classes and labels (5 bytes a cell) stay for the regions file,
// and the time grows with the total (about 5 M cells/s). 64 Mi cells keep a
// 140-face part under about 350 MB and half a minute.
constexpr long kMaxCellsPerPart = 64L << 20;

// Length of a face on the surface along u and along v [mm]: the longest of
// kExtentIsoCurves iso-parameter curves in each direction, each measured as a
// polyline of kExtentSegments chords (an underestimate below 0.1 % for the
// smooth faces Furrow handles). Trims are ignored: the grid covers the whole
// parameter rectangle.
struct FaceExtent {
  double length_u = 0, length_v = 0;
};
constexpr int kExtentIsoCurves = 9;
constexpr int kExtentSegments = 64;
FaceExtent face_extent(const Face& face);

// Default spacing for a part [mm]: the largest length_u / length_v of any face
// divided by kDefaultCellsAlongLongestSide. Throws InputError when every face
// has zero extent.
double default_spacing(const std::vector<FaceExtent>& extents);

// Cells for one face at `spacing` mm: ceil(length / spacing) per direction
// (a relative 1e-9 below a whole count rounds down), raised to
// kMinCellsPerDirection. Throws InputError naming `face_name` when
// the result exceeds the limits, or when spacing is not a positive number.
GridSize grid_for_spacing(const FaceExtent& extent, double spacing, const std::string& face_name);

// Checks explicit counts against the limits (InputError naming `face_name`).
void check_grid(const GridSize& grid, const std::string& face_name);

// Checks the cells of all faces together against kMaxCellsPerPart
// (InputError giving the total and the face count).
void check_part_grids(const std::vector<GridSize>& grids);

}  // namespace furrow
