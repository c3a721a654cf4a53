#pragma once
// Curvature partition of a part: every face split into a small number of
// convex / concave / saddle / planar regions with exact borders (// docs/partition.md).
//
// Per face, independently (regions never cross faces):
//   1. curvature field on a cell-centred (u,v) grid (curvature_field.hpp;
//      counts from options.grid, or from a spacing in mm via face_grid.hpp);
//   2. each valid cell classified with eps (options.eps, or the face's
//      default from curvature_tolerance.hpp);
//   3. 4-connected components of equal class (region_labels.hpp);
//   4. regions below min_area merged into the neighbour with the longest
//      shared border, until stable (region_merge.hpp);
//   5. per region: area (area element), boxes, centroid, K/H/k1/k2 stats,
//      border loops along cell edges in uv and xyz (region_boundary.hpp),
//      neighbours, an interior point.
// Trimmed-away and degenerate cells belong to no region; a face with no valid
// cell simply has no regions. Region ids run over the whole part: face by
// face, within a face by the first cell in raster order.
//
// Deterministic: the field is computed in parallel but every sum over cells
// runs sequentially in raster order, so the same part and options give the
// same map bit for bit, whatever the thread count.
#include <functional>
#include <optional>
#include <vector>

#include "geometry/part.hpp"
#include "partition/face_grid.hpp"
#include "partition/region_labels.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// Default min_area as a fraction of each face's valid area (docs/partition.md).
constexpr double kDefaultMinAreaFraction = 0.005;
// Straight runs of a border (constant u or v) are thinned to the vertices
// needed to keep the xyz polyline within this distance of the surface curve.
constexpr double kDefaultChordTolerance = 1e-3;  // mm

struct PartitionOptions {
  std::optional<GridSize> grid;   // the same cell counts on every face
  std::optional<double> spacing;  // mm on the surface (ignored when grid is set)
  std::optional<double> eps;      // 1/mm, the same on every face; default per face
  std::optional<double> min_area; // mm^2, the same on every face; default per face
  double min_area_fraction = kDefaultMinAreaFraction;
  double chord_tolerance = kDefaultChordTolerance;
};

// Cell-level result of one face, for figures and tests.
struct FaceCells {
  std::vector<unsigned char> cell_class;  // raw class per cell (region_labels.hpp)
  RegionLabels labels;                    // final, merged; label + first_id = region id
  int first_id = 0;
};

struct PartitionTiming {
  double field_seconds = 0;   // curvature evaluation
  double region_seconds = 0;  // classes, components, merging, statistics, borders
};

struct PartitionResult {
  RegionMap map;
  std::vector<FaceCells> cells;  // per face
  PartitionTiming timing;
};

// Throws InputError for invalid options (grid counts < 1 or beyond the
// limits of face_grid.hpp, spacing <= 0, eps < 0, min_area < 0, non-finite
// values). `progress(done, total)` is called after each face when given.
PartitionResult partition_part(const Part& part, const PartitionOptions& options,
                               const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace furrow
