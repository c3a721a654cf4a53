#pragma once
// A tool path moved by a measured error field (docs/compensation.md "The
// offset"): the part came out with error e(u, v) (+ material left), so the
// next one is cut against the surface moved by -gain e along its normal.
//
// For every located pass point (path_contacts.hpp: contact on face f at
// (u, v), point P, unit normal n):
//   offset  d = -gain * e(u, v), clipped to [-max_offset, max_offset]
//           (a clipped point is listed with what it asked for);
//   contact P' = P + d n, on the compensated surface S' = S + d n;
//   normal  n' = the normal of S' at P', to first order in d:
//           n' = normalise(n - grad_S d), grad_S d the surface gradient
//           (d_u, d_v) G^-1 (S_u, S_v) of the offset, G the first
//           fundamental form. Exact for a plane and for a constant d on any
//           surface (then n' = n: an offset surface has the same normals);
//           otherwise the term d n_u of S'_u, a change of the tangent's
//           length by d times the curvature (0.1 % for 10 um on R 10 mm),
//           is left out. A clipped point has d constant nearby: no tilt.
//   tip     T' = T + L(P', n') - L(P, n), L = cutter_location (cutter_location.hpp),
//           the same rule the path planner and the predictor use, so a
//           ball, bull-nose or flat end mill, side contacts included, moves
//           as it would have been planned against S'. The tip moves by the
//           change of its exact location rather than being replaced by
//           L(P', n'): what the program had beside the exact location (a
//           stock allowance, the posted 4 decimals) is kept.
// Local gouging: the compensated surface curves more than the nominal one
// where the offset moves it towards a concave centre (an offset d along the
// normal turns a principal curvature k into k / (1 - d k), docs/architecture.md
// "Conventions" for the sign), so a cutter that fits the nominal concave
// radius may not fit the compensated one. Each moved point whose nominal
// contact is clear is checked with check_local_gouge (machining/gouge/) on
// the compensated curvatures (principal directions and the normal kept:
// the tilt is the offset's slope, ~1e-3 rad); a point that would gouge has
// its offset cut back by bisection to the largest clear one
// (`gouge_iterations` halvings of [0, d]), is listed in `gouge_clipped`,
// and moves without tilt. A nominal contact that already gouges is the
// path's own fault (the prediction reports it) and is not checked.
// Points without a contact (not over the part) and points in the air keep
// their tip: the field is of the part's surface, not of the approach moves.
// A point whose tilted normal points down (n'_z < 0, unreachable from
// above) keeps its tip too and is listed.
//
// Parallel over passes (OpenMP); the result does not depend on the threads.
// Frames and units: the part frame, mm. The path's structure (passes,
// points, lines) is the input's; only tips change.
#include <Eigen/Core>
#include <vector>

#include "geometry/part.hpp"
#include "machining/compensation/error_field.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/cutter/path_tools.hpp"
#include "machining/gouge/local_gouge.hpp"
#include "machining/prediction/path_contacts.hpp"

namespace furrow {

struct PathOffsetOptions {
  double gain = 1;          // share of the measured error taken off, in (0, 2]
  double max_offset = 0.2;  // [mm] largest |d| applied, > 0
  bool check_gouge = true;  // cut back offsets that would gouge locally
  int gouge_iterations = 40;  // bisection halvings of [0, d] (2^-40 d: sub-picometre)
  GougeOptions gouge;       // its location options are `location` below
  CutterLocationOptions location;
};

struct OffsetPoint {
  std::size_t pass = 0, point = 0;  // indices in the path
  int line = 0;                     // source line
  double requested = 0;             // -gain e [mm]
  double applied = 0;               // after clipping [mm]
};

struct PathOffset {
  std::vector<std::vector<Eigen::Vector3d>> tips;  // per pass and point, the new tips [mm]
  std::vector<std::vector<double>> offsets;        // applied d per point [mm] (0 where not moved)
  std::vector<std::vector<Eigen::Vector3d>> tilts; // n' - n before normalising (0 where not tilted)
  std::vector<OffsetPoint> clipped;                // |requested| > max_offset
  std::vector<OffsetPoint> gouge_clipped;          // cut back to the largest clear offset
  std::vector<OffsetPoint> unreachable;            // tilted normal faces down: tip kept
  std::size_t moved = 0;        // points whose tip was recomputed
  std::size_t no_contact = 0;   // kept: no contact under the tip
  std::size_t in_air = 0;       // kept: in the air
  double largest_offset = 0;    // max |applied| [mm]
};

// `geometry` is locate_path's result for `tools`' passes (one cutter per
// pass by tools.of_pass). Throws InputError for a gain outside (0, 2] or a
// non-positive max_offset, naming the option.
PathOffset offset_path(const Part& part, const PathTools& tools, const PathGeometry& geometry,
                       const ErrorField& field, const PathOffsetOptions& options = {});

// Point `point` of pass `pass` moved again with its correction scaled by
// `factor` in (0, 1): the applied offset d and the tilt of the normal both
// times factor (the tip T + L(P + f d n, n + f t) - L(P, n), t the tilt
// offset_path applied), as if the field there were f times smaller. What
// the clip-back of docs/compensation.md ("Safety") does, round after round,
// to the ends of a move the z-map check blames. Updates tips, offsets,
// tilts and largest_offset. Precondition: the point was moved by
// offset_path, `cutter` is its pass's. Throws std::out_of_range for a
// point that is not in the path.
void reduce_offset(PathOffset& offset, const Cutter& cutter, const PathGeometry& geometry, std::size_t pass,
                   std::size_t point, double factor, const CutterLocationOptions& location = {});

}  // namespace furrow
