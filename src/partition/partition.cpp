#include "partition/partition.hpp"

#include "partition/region_groups.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "partition/border_polyline.hpp"
#include "partition/curvature_field.hpp"
#include "partition/curvature_tolerance.hpp"
#include "partition/part_fingerprint.hpp"
#include "partition/region_adjacency.hpp"
#include "partition/region_boundary.hpp"
#include "partition/region_merge.hpp"
#include "partition/region_statistics.hpp"

namespace furrow {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void check_options(const PartitionOptions& o) {
  auto bad = [](const std::string& what, double value) {
    std::ostringstream s;
    s << "partition: " << what << ", got " << value;
    throw InputError(s.str());
  };
  if (o.grid && (o.grid->nu < 1 || o.grid->nv < 1))
    throw InputError("partition: grid " + std::to_string(o.grid->nu) + "x" +
                     std::to_string(o.grid->nv) + ": both counts must be at least 1");
  if (o.spacing && !(*o.spacing > 0 && std::isfinite(*o.spacing)))
    bad("the spacing must be a positive number of mm", *o.spacing);
  if (o.eps && !(*o.eps >= 0 && std::isfinite(*o.eps)))
    bad("eps must be a finite number >= 0 (1/mm)", *o.eps);
  if (o.min_area && !(*o.min_area >= 0 && std::isfinite(*o.min_area)))
    bad("the minimum region area must be a finite number >= 0 (mm^2)", *o.min_area);
  if (!(o.min_area_fraction >= 0 && o.min_area_fraction < 1))
    bad("the minimum area fraction must be in [0, 1)", o.min_area_fraction);
  if (!(o.chord_tolerance > 0 && std::isfinite(o.chord_tolerance)))
    bad("the border chord tolerance must be a positive number of mm", o.chord_tolerance);
}

std::vector<GridSize> choose_grids(const Part& part, const PartitionOptions& options) {
  std::vector<GridSize> grids;
  if (options.grid) {
    for (const Face& f : part.faces) {
      check_grid(*options.grid, f.name());
      grids.push_back(*options.grid);
    }
    return grids;
  }
  std::vector<FaceExtent> extents;
  for (const Face& f : part.faces) extents.push_back(face_extent(f));
  const double spacing = options.spacing ? *options.spacing : default_spacing(extents);
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    grids.push_back(grid_for_spacing(extents[f], spacing, part.faces[f].name()));
  return grids;
}

// Everything after the field for one face; appends its regions to `map`.
FaceCells regions_of_face(const Face& face, int face_index, const CurvatureField& field,
                          const PartitionOptions& options, RegionMap& map) {
  RegionFace info;
  info.name = face.name();
  info.fingerprint = face_fingerprint(face);
  info.nu = field.nu;
  info.nv = field.nv;
  info.domain = field.domain;
  const CurvatureTolerance t = face_curvature_tolerance(face);
  info.curvature_scale = t.curvature_scale;
  info.eps = options.eps ? *options.eps : t.eps;
  info.eps_from_user = options.eps.has_value();

  FaceCells cells;
  cells.first_id = static_cast<int>(map.regions.size());
  cells.cell_class = classify_cells(field, info.eps);
  for (std::size_t k = 0; k < field.samples.size(); ++k) {
    const CurvatureSample& s = field.samples[k];
    switch (s.status) {
      case SampleStatus::valid:
        ++info.valid_cells;
        info.area += s.area;
        info.class_area[cells.cell_class[k]] += s.area;
        break;
      case SampleStatus::trimmed: ++info.trimmed_cells; break;
      case SampleStatus::degenerate: ++info.degenerate_cells; break;
    }
  }
  info.min_area = options.min_area ? *options.min_area : options.min_area_fraction * info.area;

  cells.labels = connected_regions(cells.cell_class, field.nu, field.nv);
  merge_small_regions(cells.labels, field, info.min_area);

  std::vector<Region> regions =
      region_statistics(cells.labels, cells.cell_class, field, face_index, cells.first_id);
  const auto loops = trace_region_boundaries(cells.labels);
  const auto borders = shared_borders(cells.labels, field);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    Region& reg = regions[r];
    std::vector<BorderLoop> polylines;
    for (const NodeLoop& loop : loops[r]) {
      polylines.push_back(
          border_polyline(loop, face, field.domain, field.nu, field.nv, options.chord_tolerance));
      for (const Eigen::Vector2d& p : polylines.back().uv) reg.uv_box.extend(p);
      for (const Eigen::Vector3d& p : polylines.back().xyz) reg.xyz_box.extend(p);
    }
    reg.set_border(std::move(polylines));
    for (const auto& [neighbour, length] : borders[r])
      reg.neighbours.push_back({cells.first_id + neighbour, length});
    info.regions.push_back(reg.id);
    map.regions.push_back(std::move(reg));
  }
  map.faces.push_back(std::move(info));
  return cells;
}

}  // namespace

PartitionResult partition_part(const Part& part, const PartitionOptions& options,
                               const std::function<void(std::size_t, std::size_t)>& progress) {
  check_options(options);
  const std::vector<GridSize> grids = choose_grids(part, options);
  check_part_grids(grids);
  PartitionResult result;
  result.map.source_units = part.source_units;
  result.map.part_fingerprint = part_fingerprint(part);
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Clock::time_point t0 = Clock::now();
    const CurvatureField field = compute_curvature_field(part.faces[f], grids[f].nu, grids[f].nv);
    const Clock::time_point t1 = Clock::now();
    result.timing.field_seconds += std::chrono::duration<double>(t1 - t0).count();
    result.cells.push_back(
        regions_of_face(part.faces[f], static_cast<int>(f), field, options, result.map));
    result.timing.region_seconds += seconds_since(t1);
    if (progress) progress(f + 1, part.faces.size());
  }
  // Nothing to sample anywhere (every cell degenerate or trimmed away): a
  // regions file without regions would only move the failure downstream.
  if (result.map.regions.empty())
    throw InputError("the part has no face of positive size to sample");
  const Clock::time_point t2 = Clock::now();
  group_regions_across_faces(part, result);
  result.timing.region_seconds += seconds_since(t2);
  return result;
}

}  // namespace furrow
