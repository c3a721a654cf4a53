#pragma once
// A dense point cloud as a scanner wrote it (PLY or PCD), read by
// read_scan() (scan_read.hpp): every finite point with the coordinates the
// file holds, in double (docs/scan.md "What is read").
//
// Why double: a float's step is 7.6 um at 100 mm and 15 um at 200 mm from
// the origin, as large as a good scanner's noise; a file that stores double
// x/y/z keeps them here bit for bit, and a file of floats is widened exactly.
#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace furrow {

// Points in one scan file (docs/formats.md "Limits"): checked from the
// file's header before PCL reads the data (a 50 M-point cloud takes some
// 3 GB through the comparison).
inline constexpr long long kMaxScanPoints = 50'000'000;

struct ScanCloud {
  std::string file;    // as given, for messages and reports
  std::string format;  // "ply ascii", "ply binary_little_endian", "ply binary_big_endian", "pcd"
  // The type the file stores x, y and z in: "float32", "float64", or an
  // integer type ("int32", ...), read exactly.
  std::string coordinate_type;
  std::vector<Eigen::Vector3d> points;  // file frame, file units (mm unless the caller scales them)
  // Unit normals from the file's normal_x/y/z (PLY nx/ny/nz), one per point;
  // empty when the file has none. Zero where the file's normal is not finite
  // or has zero length.
  std::vector<Eigen::Vector3f> normals;
  std::size_t read = 0;        // points in the file
  std::size_t not_finite = 0;  // of them, points with a NaN or infinite coordinate: not in `points`
  // Where the scanner stood, file frame, in mm like `points`: a PCD's
  // VIEWPOINT translation when the file sets one (PCL writes 0 0 0 1 0 0 0
  // when nobody did; that header is taken as no viewpoint: docs/scan.md
  // "Line of sight"). A PLY has no standard place for it: none.
  std::optional<Eigen::Vector3d> viewpoint;
  // The scale read_scan() applied to the file's coordinates (25.4 for a scan
  // in inches): options given in file units (a viewpoint) are scaled by it.
  double mm_per_unit = 1.0;
  // Names of the fields the file has besides x y z and the normals (colour,
  // intensity, ...): read past, not used.
  std::vector<std::string> ignored_fields;
};

}  // namespace furrow
