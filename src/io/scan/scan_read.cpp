// Reading a scan (contract in scan_read.hpp): the name, existence and first
// bytes are checked here; the reading runs in the scan module
// (scan_module.hpp), loaded on the first scan.
#include "io/scan/scan_read.hpp"

#include <cmath>
#include <fstream>
#include <new>
#include <stdexcept>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/number_text.hpp"
#include "base/runtime_module.hpp"
#include "base/text_fields.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow {

bool is_scan_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".ply" || ext == ".pcd";
}

namespace {

// The first bytes say what the file is before the module is loaded: a PLY
// starts with the line "ply", a PCD with comments or its VERSION/FIELDS
// header. Anything else is refused here, the same with or without PCL.
void check_signature(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the scan file");
  char head[16] = {};
  in.read(head, sizeof head);
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  if (start.empty()) throw InputError(path + ": the scan file is empty");
  if (lower_extension(path) == ".ply") {
    if (start.rfind("ply\n", 0) != 0 && start.rfind("ply\r\n", 0) != 0)
      throw InputError(path + ": not a PLY file (it does not start with the line \"ply\")");
  } else if (start[0] != '#' && start.rfind("VERSION", 0) != 0 && start.rfind("FIELDS", 0) != 0) {
    throw InputError(path + ": not a PCD file (it starts with neither a comment nor VERSION or FIELDS)");
  }
}

}  // namespace

ScanCloud read_scan(const std::string& path, double mm_per_unit) {
  if (!(std::isfinite(mm_per_unit) && mm_per_unit > 0))
    throw InputError(path + ": the unit must be a positive number of mm, got " + general(mm_per_unit));
  if (!is_scan_file(path))
    throw InputError(path + ": a scan must be a PLY (.ply) or PCD (.pcd) file");
  check_signature(path);
  const auto entry = reinterpret_cast<scan::ReadEntry>(
      runtime_module_symbol(scan::kModuleName, scan::kModuleOverride, scan::kModuleWhat, scan::kReadEntry));
  ScanCloud cloud;
  std::string message;
  switch (static_cast<scan::ScanModuleOutcome>(entry(&path, &cloud, &message))) {
    case scan::ScanModuleOutcome::ok: break;
    case scan::ScanModuleOutcome::input_error: throw InputError(message);
    case scan::ScanModuleOutcome::out_of_memory: throw std::bad_alloc();
    case scan::ScanModuleOutcome::failure:
      throw std::runtime_error(message.empty() ? path + ": the scan reader failed" : message);
  }
  if (cloud.points.empty())
    throw InputError(path + ": the scan has no finite point (" + std::to_string(cloud.read) + " read)");
  cloud.mm_per_unit = mm_per_unit;
  if (cloud.viewpoint) {
    *cloud.viewpoint *= mm_per_unit;
    if (!cloud.viewpoint->allFinite() || cloud.viewpoint->cwiseAbs().maxCoeff() > limits::kMaxScanCoordinateMm)
      throw InputError(path + ": the VIEWPOINT lies beyond ±1e8 mm (100 km) of the origin");
  }
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    Eigen::Vector3d& p = cloud.points[i];
    if (mm_per_unit != 1.0) p *= mm_per_unit;
    if (p.cwiseAbs().maxCoeff() > limits::kMaxScanCoordinateMm)
      throw InputError(path + ": point " + std::to_string(i) + " lies beyond ±1e8 mm (100 km) of the origin (" +
                       general(p.x()) + ", " + general(p.y()) + ", " + general(p.z()) + " mm)");
  }
  return cloud;
}

}  // namespace furrow
