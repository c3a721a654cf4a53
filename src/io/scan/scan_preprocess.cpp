// Pre-processing of a scan (contract in scan_preprocess.hpp): the options
// and the grid's size are checked here, the work runs in the scan module.
#include "io/scan/scan_preprocess.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>

#include "base/error.hpp"
#include "base/number_text.hpp"
#include "base/runtime_module.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow {

const char* to_string(ScanViewKind kind) {
  switch (kind) {
    case ScanViewKind::none: return "none";
    case ScanViewKind::viewpoint: return "viewpoint";
    case ScanViewKind::direction: return "direction";
  }
  return "?";
}

ScanPreprocessed preprocess_scan(const ScanCloud& cloud, const ScanPreprocessOptions& given) {
  const std::string& name = cloud.file;
  // The line of sight, resolved here (scan_preprocess.hpp step 5): the
  // module gets at most one of the two, the viewpoint in mm.
  ScanPreprocessOptions options = given;
  if (!(std::isfinite(options.max_incidence_deg) && options.max_incidence_deg > 0 && options.max_incidence_deg < 90))
    throw InputError(name + ": --max-incidence must lie between 0 and 90 degrees, got " +
                     general(options.max_incidence_deg));
  if (options.viewpoint && options.view_direction)
    throw InputError(name + ": --viewpoint and --view-direction both given: a scanner is seen from one of them");
  std::string view_source;
  if (options.view_direction) {
    if (!options.view_direction->allFinite() || !(options.view_direction->stableNorm() > 0))
      throw InputError(name + ": --view-direction must be a non-zero vector");
    options.view_direction = Eigen::Vector3d(*options.view_direction / options.view_direction->stableNorm());
    view_source = "option";
  } else if (options.viewpoint) {
    if (!options.viewpoint->allFinite()) throw InputError(name + ": --viewpoint must be a finite point");
    options.viewpoint = Eigen::Vector3d(*options.viewpoint * cloud.mm_per_unit);
    view_source = "option";
  } else if (cloud.viewpoint) {
    options.viewpoint = cloud.viewpoint;
    view_source = "file";
  }
  if (!(std::isfinite(options.voxel) && options.voxel > 0))
    throw InputError(name + ": --voxel must be a positive number of mm, got " + general(options.voxel));
  if (options.outlier_neighbours < 2 || options.normal_neighbours < 3)
    throw InputError(name + ": the spray filter needs at least 2 neighbours and the normals 3");
  if (!(std::isfinite(options.outlier_sigmas) && options.outlier_sigmas > 0 && std::isfinite(options.spray_sigmas) &&
        options.spray_sigmas > 0))
    throw InputError(name + ": the spray threshold must be a positive number of standard deviations");
  if (cloud.points.size() <= static_cast<std::size_t>(std::max(options.outlier_neighbours,
                                                               options.normal_neighbours)))
    throw InputError(name + ": " + std::to_string(cloud.points.size()) +
                     " points are too few for a scan comparison (at least " +
                     std::to_string(std::max(options.outlier_neighbours, options.normal_neighbours) + 1) +
                     " are needed)");
  if (!cloud.normals.empty() && cloud.normals.size() != cloud.points.size())
    throw std::logic_error("preprocess_scan: one normal per point or none");
  // pcl::VoxelGrid indexes its cells with 32-bit integers and returns the
  // cloud unfiltered (with a warning on the console) when they would
  // overflow: refused here instead, with the figure.
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : cloud.points) box.extend(p);
  double cells = 1;
  for (int k = 0; k < 3; ++k) cells *= std::floor(box.sizes()[k] / options.voxel) + 1;
  if (cells > static_cast<double>(std::numeric_limits<std::int32_t>::max()))
    throw InputError(name + ": --voxel " + general(options.voxel) + " mm is too fine for a scan " +
                     general(box.sizes().maxCoeff(), 4) + " mm across (" + general(cells, 3) +
                     " voxels; at most 2^31)");
  const auto entry = reinterpret_cast<scan::PreprocessEntry>(
      runtime_module_symbol(scan::kModuleName, scan::kModuleOverride, scan::kModuleWhat, scan::kPreprocessEntry));
  ScanPreprocessed result;
  std::string message;
  switch (static_cast<scan::ScanModuleOutcome>(entry(&cloud, &options, &result, &message))) {
    case scan::ScanModuleOutcome::ok: result.view_source = view_source; return result;
    case scan::ScanModuleOutcome::input_error: throw InputError(message);
    case scan::ScanModuleOutcome::out_of_memory: throw std::bad_alloc();
    case scan::ScanModuleOutcome::failure: break;
  }
  throw std::runtime_error(message.empty() ? name + ": the scan pre-processing failed" : message);
}

}  // namespace furrow
