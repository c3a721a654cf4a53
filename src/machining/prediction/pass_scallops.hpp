#pragma once
// The largest scallop between each pair of adjacent passes, from the z-map.
//
// Adjacent passes (consecutive in the path, on the same part) leave a ridge
// of material between them. Cross-sections are taken from every contact
// point of the first pass and every mid-step to the nearest point of the
// next pass (in xy); along each, the z-map error (error_map.hpp, exact
// envelopes) is sampled and its largest value refined by Brent's method; the
// pair's scallop is the largest over its cross-sections. Passes farther
// apart than the cutter's diameter share no ridge and are skipped, as are
// cross-sections through unreached or unmachinable points.
#include <vector>

#include "machining/prediction/error_map.hpp"
#include "machining/prediction/surface_curve.hpp"

namespace furrow {

// A contact point of a path on the part (face, uv) with its surface point.
struct PathContact {
  bool valid = false;  // false: no contact point is known for this tip
  SurfacePoint at;
};

struct PassScallopOptions {
  double sample_spacing = 0;     // [mm] along a cross-section; 0: half the z-map spacing
  double max_pass_distance = 0;  // [mm]; 0: the cutter's diameter
  double refine_tolerance = 1e-6;  // [mm] position of the ridge along the cross-section
  NormalErrorOptions normal;
};

struct PassScallop {
  int pass_a = 0, pass_b = 0;  // indices of the two passes (b = a + 1)
  bool found = false;          // a cross-section with a reached ridge
  double height = 0;           // [mm] largest error between them (material left when > 0)
  SurfacePoint at;
  int cross_sections = 0;
};

std::vector<PassScallop> pass_pair_scallops(const VerticalProjector& projector, const ZMap& zmap,
                                            double cutter_diameter,
                                            const std::vector<std::vector<PathContact>>& passes,
                                            const PassScallopOptions& options = {});

}  // namespace furrow
