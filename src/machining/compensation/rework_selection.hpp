#pragma once
// Which parts of a compensated path re-cut a part that came out with
// material left (docs/compensation.md "Rework").
//
// Each cutting move of the original path is divided into pieces of at most
// `step` mm (a quarter of the cutter radius by default: the bump of a
// planted test, 15 mm across, then spans dozens of pieces even where the
// program's moves are 100 mm long). The division points are located on the
// part (machining/prediction/path_contacts.hpp) and the fitted error field
// e (+ material left) read at their contacts: the compensated contact of a
// point is its nominal one moved along the normal, at the same (u, v), so
// the field there is the same. A piece is kept when e exceeds `threshold`
// at either of its ends; a point without a contact or in the air has
// e = 0. The kept piece is cut along the compensated move: its tips are
// the compensated end tips interpolated at the same fractions, so every
// kept piece lies on a line the compensated full path cuts. Consecutive
// kept pieces of a pass make one stretch.
//
// Regions: stretches grouped when their tips' boxes in xy, grown by the
// cutter radius, overlap (directly or through others): what a programmer
// would call one spot to re-cut.
//
// Clearance height: the highest z of the original's rapids (both ends of
// every rapid in the part frame). A program without such a rapid has
// none: InputError.
// Units: mm, part frame.
#include <Eigen/Geometry>
#include <vector>

#include "geometry/part.hpp"
#include "io/machining/rework_program.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/compensation/error_field.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/cutter/cutter.hpp"

namespace furrow {

struct ReworkOptions {
  double threshold = 0.025;  // [mm] e above this is material to re-cut
  double step = 0;           // [mm] longest piece; 0: a quarter of the cutter radius
};

struct ReworkRegion {
  Eigen::AlignedBox2d box;       // xy box of its stretches' tips [mm]
  std::vector<std::size_t> stretches;  // indices
};

struct ReworkSelection {
  std::vector<ReworkStretch> stretches;  // in path order
  std::vector<ReworkRegion> regions;
  std::size_t pieces = 0, pieces_kept = 0;  // all pieces of the path, kept ones
  std::size_t moves_kept = 0;  // original cutting moves with a kept piece
  std::size_t moves = 0;       // original cutting moves
  double largest_field = 0;    // [mm] largest e at a division point
  double clearance = 0;        // [mm]
  double step = 0;             // [mm] used
};

// `original` the path as read, `offset` its compensation (tips per pass and
// point, as written), `field` the fitted error field. Throws InputError for
// a threshold that is negative or not finite, or a program without a
// rapid in the part frame.
ReworkSelection select_rework(const Part& part, const Cutter& cutter, const Toolpath& original,
                              const PathOffset& offset, const ErrorField& field, const ReworkOptions& options);

}  // namespace furrow
