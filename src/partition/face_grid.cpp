#include "partition/face_grid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "base/error.hpp"

namespace furrow {

namespace {

// Longest of the iso-curves in one direction: along u when `along_u`.
double longest_iso_curve(const NurbsSurface& s, bool along_u) {
  const ParameterDomain& d = s.domain();
  double longest = 0;
  for (int c = 0; c < kExtentIsoCurves; ++c) {
    const double fixed = static_cast<double>(c) / (kExtentIsoCurves - 1);
    double length = 0;
    Eigen::Vector3d previous;
    for (int k = 0; k <= kExtentSegments; ++k) {
      const double t = static_cast<double>(k) / kExtentSegments;
      const double u = d.u0 + d.width_u() * (along_u ? t : fixed);
      const double v = d.v0 + d.width_v() * (along_u ? fixed : t);
      const Eigen::Vector3d p = s.point(u, v);
      if (k > 0) length += (p - previous).norm();
      previous = p;
    }
    longest = std::max(longest, length);
  }
  return longest;
}

std::string grid_text(long nu, long nv) { return std::to_string(nu) + "x" + std::to_string(nv); }

}  // namespace

FaceExtent face_extent(const Face& face) {
  return {longest_iso_curve(face.surface(), true), longest_iso_curve(face.surface(), false)};
}

double default_spacing(const std::vector<FaceExtent>& extents) {
  double longest = 0;
  for (const FaceExtent& e : extents) longest = std::max({longest, e.length_u, e.length_v});
  if (!(longest > 0) || !std::isfinite(longest))
    throw InputError("the part has no face of positive size to sample");
  return longest / kDefaultCellsAlongLongestSide;
}

void check_grid(const GridSize& grid, const std::string& face_name) {
  if (grid.nu < 1 || grid.nv < 1)
    throw InputError("face \"" + face_name + "\": grid " + grid_text(grid.nu, grid.nv) +
                     ": both counts must be at least 1");
  if (grid.nu > kMaxCellsPerDirection || grid.nv > kMaxCellsPerDirection ||
      static_cast<long>(grid.nu) * grid.nv > kMaxCellsPerFace)
    throw InputError("face \"" + face_name + "\": grid " + grid_text(grid.nu, grid.nv) +
                     " is too fine (at most " + std::to_string(kMaxCellsPerDirection) +
                     " per direction and " + std::to_string(kMaxCellsPerFace) +
                     " cells per face); use a coarser grid or spacing");
}

void check_part_grids(const std::vector<GridSize>& grids) {
  double total = 0;  // in double: many faces at the per-face cap overflow nothing
  for (const GridSize& g : grids) total += static_cast<double>(g.nu) * g.nv;
  if (total > static_cast<double>(kMaxCellsPerPart)) {
    std::ostringstream s;
    s << "the grids of the " << grids.size() << " faces need " << std::llround(total)
      << " cells in all, more than the limit of " << kMaxCellsPerPart
      << " per part (docs/formats.md \"Limits\"); use a coarser grid or spacing";
    throw InputError(s.str());
  }
}

GridSize grid_for_spacing(const FaceExtent& extent, double spacing, const std::string& face_name) {
  if (!(spacing > 0) || !std::isfinite(spacing)) {
    std::ostringstream s;
    s << "the sampling spacing must be a positive number of mm, got " << spacing;
    throw InputError(s.str());
  }
  // Counted in double first: a tiny spacing must not overflow int. The slack
  // keeps a length that is a whole multiple of the spacing up to round-off
  // (90 mm at 0.5 mm) from getting one cell more.
  auto cells = [spacing](double length) {
    return std::max<double>(kMinCellsPerDirection, std::ceil(length / spacing * (1 - 1e-9)));
  };
  const double cu = cells(extent.length_u), cv = cells(extent.length_v);
  if (cu > kMaxCellsPerDirection || cv > kMaxCellsPerDirection ||
      cu * cv > static_cast<double>(kMaxCellsPerFace)) {
    std::ostringstream s;
    s << "face \"" << face_name << "\": spacing " << spacing << " mm needs " << cu << "x" << cv
      << " cells, more than the limit (" << kMaxCellsPerDirection << " per direction, "
      << kMaxCellsPerFace << " per face); use a coarser spacing";
    throw InputError(s.str());
  }
  return {static_cast<int>(cu), static_cast<int>(cv)};
}

}  // namespace furrow
