#pragma once
// Reading a scan (a dense point cloud) from a PLY or PCD file
// (docs/scan.md "What is read").
//
// PLY: ascii, binary little or big endian; x, y, z of any numeric type
// (float and double above all); any further vertex properties and any other
// element (a mesh's faces) are read past. PCD: any of PCL's encodings.
// The reading itself is PCL's (pcl::PLYReader, pcl::PCDReader into a
// pcl::PCLPointCloud2, which keeps each field as the file stores it), done
// in the scan module furrow_scan.so, loaded on the first scan
// (scan_module.hpp, docs/architecture.md "Modules loaded on demand").
//
// Failures: InputError naming the file for a file that does not exist, is
// not .ply or .pcd, is empty, truncated or not a point cloud, has no x, y
// and z, or has no finite point; RuntimeModuleError (exit 3) when the
// module cannot be loaded. The file is only read.
#include <string>

#include "io/scan/scan_cloud.hpp"

namespace furrow {

// True for a name ending in .ply or .pcd (any case).
bool is_scan_file(const std::string& path);

// `mm_per_unit` scales the coordinates after reading (25.4 for a scan in
// inches); it must be positive and finite.
ScanCloud read_scan(const std::string& path, double mm_per_unit = 1.0);

}  // namespace furrow
