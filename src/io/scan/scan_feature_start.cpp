// The feature start of a scan (contract in scan_feature_start.hpp): the
// parameters are derived and checked here, the search runs in the scan
// module.
#include "io/scan/scan_feature_start.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>

#include "base/error.hpp"
#include "base/number_text.hpp"
#include "base/runtime_module.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow {

namespace {

// The part's size over which a feature cloud is thinned to about 60 x 60
// cells: a few thousand points on a part's surface.
constexpr double kCellsAcross = 60;
constexpr double kFeatureRadiusSpacings = 5;
constexpr double kInlierSpacings = 1.5;

}  // namespace

const char* to_string(ScanStart start) {
  switch (start) {
    case ScanStart::global: return "global";
    case ScanStart::features: return "features";
    case ScanStart::best: return "best";
  }
  return "?";
}

ScanStart parse_scan_start(const std::string& text, const std::string& where) {
  if (text == "global") return ScanStart::global;
  if (text == "features") return ScanStart::features;
  if (text == "best") return ScanStart::best;
  throw InputError(where + ": \"" + text + "\" is not a scan start (global, features, best)");
}

FeatureStartOptions feature_start_parameters(const FeatureStartOptions& options, double voxel, double part_size) {
  FeatureStartOptions o = options;
  if (!(o.spacing > 0)) o.spacing = std::max(voxel, part_size / kCellsAcross);
  if (!(o.feature_radius > 0)) o.feature_radius = kFeatureRadiusSpacings * o.spacing;
  if (!(o.inlier_distance > 0)) o.inlier_distance = kInlierSpacings * o.spacing;
  return o;
}

FeatureStart feature_start(const FeatureStartInput& input, const FeatureStartOptions& options) {
  const std::string& name = input.scan;
  if (!(std::isfinite(input.voxel) && input.voxel > 0 && std::isfinite(input.part_size) && input.part_size > 0))
    throw InputError(name + ": the feature start needs a positive voxel and part size, got " + general(input.voxel) +
                     " and " + general(input.part_size) + " mm");
  const FeatureStartOptions o = feature_start_parameters(options, input.voxel, input.part_size);
  if (!(std::isfinite(o.spacing) && std::isfinite(o.feature_radius) && std::isfinite(o.inlier_distance) &&
        o.feature_radius > o.spacing))
    throw InputError(name + ": the feature radius must exceed the feature spacing (" + general(o.feature_radius) +
                     " and " + general(o.spacing) + " mm)");
  if (o.iterations < 1 || o.correspondences < 1 || !(o.similarity >= 0 && o.similarity < 1) ||
      !(o.min_inlier_share > 0 && o.min_inlier_share <= 1))
    throw InputError(name + ": feature start options out of range (iterations and correspondences at least 1, "
                            "similarity in [0, 1), inlier share in (0, 1])");
  if (input.scan_normals.size() != input.scan_points.size() || input.part_normals.size() != input.part_points.size())
    throw std::logic_error("feature_start: one normal per point");
  const auto entry = reinterpret_cast<scan::FeatureStartEntry>(
      runtime_module_symbol(scan::kModuleName, scan::kModuleOverride, scan::kModuleWhat, scan::kFeatureStartEntry));
  FeatureStart result;
  std::string message;
  switch (static_cast<scan::ScanModuleOutcome>(entry(&input, &o, &result, &message))) {
    case scan::ScanModuleOutcome::ok: return result;
    case scan::ScanModuleOutcome::input_error: throw InputError(message);
    case scan::ScanModuleOutcome::out_of_memory: throw std::bad_alloc();
    case scan::ScanModuleOutcome::failure: break;
  }
  throw std::runtime_error(message.empty() ? name + ": the scan's feature start failed" : message);
}

}  // namespace furrow
