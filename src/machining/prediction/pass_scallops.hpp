#pragma once
// The scallop between each pair of adjacent passes, measured two ways on the
// same cross-sections (docs/architecture.md "Scallop between passes").
//
// Adjacent passes (consecutive in the path, on the same part) leave a ridge
// of material between them. Cross-sections are taken from every contact
// point of the first pass and every mid-step to the nearest point of the
// next pass (in xy). Along each, the error is sampled and its largest value
// refined by Brent's method; a pair's figure is the largest over its
// cross-sections:
//   - `cusp`: the error against the two cutters standing at the section's
//     ends only, the cutter of each pass at its point of the section. This
//     is the cusp height between the passes proper, the figure a side step
//     is chosen for (cross_section_scallop.hpp), free of the furrow that the
//     straight moves leave along each pass.
//   - `ridge`: the error against the whole path's z-map (error_map.hpp,
//     exact envelopes): what the part really keeps between the passes, the
//     cusp plus wherever the moves' furrows along the passes add to it.
// The two standing cutters are the passes' swept section wherever the
// cutter's section through the contact is its profile: always for the ball
// (a sphere swept along a pass leaves the great circle through the contact
// square to the pass), and for flat and bull-nose cutters whose axis lies in
// the section (the normal tilts across the pass, not along it). A flat or
// bull-nose cutter tilted along the pass touches off its axis, and the swept
// section is lower than the standing one: the cusp is then the standing
// cutters' figure, the cross-section model of cross_section_scallop.hpp
// applied in 3D, and the ridge (z-map) is the one to trust.
// At a contact point the cutter stands at the path's own tip. At a point
// between two contacts it stands at that point's exact cutter location
// (cutter_location.hpp), moved by the two contacts' tip offsets from their
// exact locations, interpolated: a path written with its tips a little
// above the part keeps that offset between its points too.
// A section ends where the next pass is nearest, on the surface (not on the
// chord between its contacts), so that it crosses the pass square. One that
// meets the next pass only beyond its end (oblique passes stopping at the
// part's edge) has no cusp: it would measure where the passes stop, not how
// far apart they are; its ridge is measured all the same.
// Passes farther apart than the cutter's diameter share no ridge and are
// skipped, as are cross-sections through unreached or unmachinable points.
#include <vector>

#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/surface_curve.hpp"

namespace furrow {

// A contact point of a path on the part (face, uv) with its surface point
// and the tool tip the path has there.
struct PathContact {
  bool valid = false;  // false: no contact point is known for this tip
  SurfacePoint at;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();  // [mm]
};

// A contact whose tip is the exact cutter location of `at` (a path that
// follows the design surface exactly); invalid when `at` is, or when the
// cutter cannot reach it from above.
PathContact exact_contact(const Cutter& cutter, const SurfacePoint& at, const CutterLocationOptions& options = {});

struct PassScallopOptions {
  double sample_spacing = 0;     // [mm] along a cross-section; 0: half the z-map spacing
  double max_pass_distance = 0;  // [mm]; 0: the cutter's diameter
  double refine_tolerance = 1e-6;  // [mm] position of the ridge along the cross-section
  NormalErrorOptions normal;
  CutterLocationOptions location;
};

// The largest error over a pair's cross-sections, where it is.
struct ScallopPeak {
  bool found = false;  // a cross-section with a reached ridge
  double height = 0;   // [mm] material left when > 0
  SurfacePoint at;
};

struct PassScallop {
  int pass_a = 0, pass_b = 0;  // indices of the two passes (b = a + 1)
  ScallopPeak ridge;           // against the z-map
  ScallopPeak cusp;            // against the two cutters of the cross-section
  int cross_sections = 0;
};

std::vector<PassScallop> pass_pair_scallops(const VerticalProjector& projector, const ZMap& zmap,
                                            const Cutter& cutter,
                                            const std::vector<std::vector<PathContact>>& passes,
                                            const PassScallopOptions& options = {});

}  // namespace furrow
