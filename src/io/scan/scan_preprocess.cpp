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

ScanPreprocessed preprocess_scan(const ScanCloud& cloud, const ScanPreprocessOptions& options) {
  const std::string& name = cloud.file;
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
    case scan::ScanModuleOutcome::ok: return result;
    case scan::ScanModuleOutcome::input_error: throw InputError(message);
    case scan::ScanModuleOutcome::out_of_memory: throw std::bad_alloc();
    case scan::ScanModuleOutcome::failure: break;
  }
  throw std::runtime_error(message.empty() ? name + ": the scan pre-processing failed" : message);
}

}  // namespace furrow
