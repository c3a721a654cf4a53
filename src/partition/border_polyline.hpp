#pragma once
// A traced region border (grid nodes, region_boundary.hpp) as polylines in
// uv and on the surface.
//
// Node (a, b) maps to u = u0 + a du, v = v0 + b dv (the domain's own end
// values at a = nu, b = nv), and to the surface point there. Corners of the
// uv loop are always kept, so the uv polyline is exactly the cell-edge border.
// A straight uv run maps to a curve on the surface; its inner nodes are
// thinned (Douglas-Peucker in xyz) as long as every dropped node stays within
// `chord_tolerance` mm of the xyz polyline. Dropping collinear uv vertices
// leaves the uv border unchanged, so region membership is unaffected.
#include "geometry/part.hpp"
#include "partition/region_boundary.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// Precondition: chord_tolerance > 0; the loop's nodes lie on the nu x nv
// cell grid of `domain`.
BorderLoop border_polyline(const NodeLoop& loop, const Face& face, const ParameterDomain& domain,
                           int nu, int nv, double chord_tolerance);

}  // namespace furrow
