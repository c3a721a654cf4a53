#pragma once
// Outlines of a part for the report's maps, as polylines in a figure's
// frame: the part seen from above (x, y in mm, looking down -z the way the
// tool and a vertical stylus come in) or one face's (u, v) domain.
//
// Face outlines follow the face's trim loops when it has any, else its
// parameter rectangle; curves are sampled densely enough (every edge of a
// trim loop and each rectangle side in `samples` pieces) that the polyline
// stays within a fraction of a pixel of the surface curve at report size.
#include <Eigen/Geometry>
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"
#include "report/figures.hpp"

namespace furrow {

// Every face's boundary projected on the x-y plane.
std::vector<Outline> face_outlines_xy(const Part& part, int samples = 64);
// A face's boundary in its own (u, v) frame (trim loops or the rectangle).
std::vector<Outline> face_outlines_uv(const Face& face);
// Region borders of the partition, closed, projected on x-y (all faces) or
// in (u, v) of one face (face index into map.faces).
std::vector<Outline> region_borders_xy(const RegionMap& map);
std::vector<Outline> region_borders_uv(const RegionMap& map, int face);
// A (u, v) box of a face (clamped to its domain), its border mapped onto the
// surface and projected on x-y: the footprint of a gouge site seen from above.
Outline uv_box_outline_xy(const Face& face, const Eigen::AlignedBox2d& box, int samples = 16);

}  // namespace furrow
