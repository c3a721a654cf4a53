#pragma once
// The predicted machining error over every face, from a z-map (zmap.hpp):
// at surface points on a regular (u, v) grid per face, the signed distance
// along the normal to the machined surface (normal_error.hpp; positive =
// material left, negative = overcut).
//
// Two levels per face:
//   - samples: cell centres of a fine grid whose spacing on the surface is
//     about the z-map's node spacing (so nothing the z-map resolves is
//     skipped); used for extremes, gouge sites and the PNG map;
//   - cells: blocks of block_u x block_v samples, about `cell_size` mm on a
//     side, each with the mean, the largest undercut and the largest
//     overcut of its reached samples: what prediction.json stores, since a
//     scallop pattern finer than a probe's reach is better described by its
//     band than by one sampled phase.
// A sample has a status: reached, not reached by the tool (nothing above it
// was cut), outside the face (trimmed away) or not machinable (degenerate
// normal, or n_z < 0: not reachable from above; a vertical wall, n_z = 0,
// is cut by the cutter's side and evaluated). Errors are only defined
// where reached; nothing else carries a number.
//
// Boundary samples: a sample is flagged `boundary` when its error rests on
// where the edge of a swept region lies rather than on the envelope's
// height: the sample, or the point where its normal meets the machined
// surface, is within one z-map cell of the swept region's boundary
// (ZMap::near_boundary), the normal meets a vertical wall there
// (NormalError::wall: a pass's edge), or the normal leaves the cut area.
// Everywhere else the error converges with the path (a path of G1 chords
// gives the same map, to far below 0.1 um, whether the chords' sag is 1e-6
// or 1e-7 mm: zmap.hpp height_at); at boundary samples it moves with the
// grid and the chords by up to the edge's displacement times the slope.
//
// The overall extremes are refined from the best sample by a local search in
// (u, v) on the exact z-map error. Parallel over sample rows; each sample
// depends on its position only and every sum runs in raster order, so the
// map does not depend on the thread count.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/part.hpp"
#include "machining/prediction/normal_error.hpp"
#include "machining/cutter/vertical_projection.hpp"
#include "machining/prediction/zmap.hpp"

namespace furrow {

enum class ErrorCellStatus : std::uint8_t { reached = 0, not_reached = 1, outside = 2, not_machinable = 3 };
const char* to_string(ErrorCellStatus status);

struct ErrorMapOptions {
  double sample_spacing = 0;  // [mm] on the surface; 0: the z-map's node spacing
  double cell_size = 1.0;     // [mm] on the surface, stored cells
  std::size_t max_samples = 40'000'000;  // per face; InputError beyond (4+1 bytes each)
  NormalErrorOptions normal;
  int refine_rounds = 4;      // local search rounds for the extremes (u then v each)
};

struct ErrorCell {
  ErrorCellStatus status = ErrorCellStatus::not_reached;  // reached when any sample is
  int reached = 0;          // samples of the cell that were reached
  int boundary = 0;         // samples of the cell flagged boundary (reached or not)
  double mean = 0;          // [mm] over the reached samples
  double max_undercut = 0;  // largest error over them (may be negative)
  double max_overcut = 0;   // smallest error over them (may be positive)
};

struct FaceErrorMap {
  std::size_t face = 0;
  ParameterDomain domain;
  int cells_u = 0, cells_v = 0;  // stored cells
  int block_u = 1, block_v = 1;  // samples per cell and direction
  int nu = 0, nv = 0;            // samples: nu = cells_u * block_u
  std::vector<float> error;      // [j * nu + i] (i along u) [mm]; 0 unless reached
  std::vector<ErrorCellStatus> status;
  std::vector<std::uint8_t> boundary;  // 1: a boundary sample (see above)
  std::vector<ErrorCell> cells;  // [cj * cells_u + ci]

  double u(double i) const { return domain.u0 + (i + 0.5) * domain.width_u() / nu; }
  double v(double j) const { return domain.v0 + (j + 0.5) * domain.width_v() / nv; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nu + i; }
};

struct ErrorExtremum {
  bool found = false;
  double error = 0;  // [mm]
  SurfacePoint at;
};

struct ErrorMap {
  std::vector<FaceErrorMap> faces;
  ErrorExtremum max_undercut;  // the largest error over the part (refined)
  ErrorExtremum max_overcut;   // the smallest
  std::size_t samples = 0, reached = 0, not_reached = 0, not_machinable = 0;
  std::size_t boundary = 0;  // samples flagged boundary
};

// Whether a sample whose normal search gave `e` is a boundary sample (see
// above): `point` and `normal` as given to zmap_error.
bool is_boundary_sample(const ZMap& zmap, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                        const NormalError& e);

// Error at one surface point from the z-map.
NormalError zmap_error(const ZMap& zmap, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                       const NormalErrorOptions& options = {});
// At (u, v) of a face; not reached when the normal is degenerate or n_z < 0.
NormalError zmap_error(const ZMap& zmap, const Face& face, const Eigen::Vector2d& uv,
                       const NormalErrorOptions& options = {});

// Local search around `uv` (within +-du, +-dv, clamped to the face's
// domain) for the largest (sign = +1) or smallest (sign = -1) error:
// golden-section along u, then along v, `rounds` times.
ErrorExtremum refine_error_extremum(const Part& part, const ZMap& zmap, std::size_t face,
                                    const Eigen::Vector2d& uv, double du, double dv, double sign,
                                    const ErrorMapOptions& options);

// Throws InputError when a face would need more than max_samples samples.
// `progress(done, total)` counts sample rows over all faces.
ErrorMap compute_error_map(const Part& part, const ZMap& zmap, const ErrorMapOptions& options = {},
                           const std::function<void(std::size_t, std::size_t)>& progress = {});

// Arc lengths of a face along u and along v [mm] (the longest of a few
// iso-curves, as polylines): how grids on the face are sized.
Eigen::Vector2d face_extent_lengths(const Face& face);

}  // namespace furrow
