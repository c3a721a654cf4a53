#pragma once
// Dense, roughly area-uniform sampling of a part's faces (trims respected):
// the target cloud of the coarse registration (ICP) and a reference for its
// principal axes. Deterministic: a regular (u,v) grid per face whose counts
// follow the face's extent along u and v, so spacing is about even in mm.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct SurfaceSample {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // out of the material
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

// Mean length of three iso-curves (at a quarter, half and three quarters of
// the other parameter) of a face along u (along_u) or along v [mm], each
// walked in 32 chords: the face's extent, to size a grid on it.
double iso_length(const Face& face, bool along_u);

// Samples at the centres of an nu x nv (u,v) grid of face `face` (cells
// trimmed away and degenerate points skipped), in grid order.
std::vector<SurfaceSample> sample_face_grid(const Part& part, std::size_t face, int nu, int nv);

// About `target_count` samples over all faces (fewer where trims remove
// surface; degenerate points are skipped).
std::vector<SurfaceSample> sample_part_surface(const Part& part, std::size_t target_count);

}  // namespace furrow
