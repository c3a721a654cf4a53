// Reading PLY and PCD with PCL's I/O inside the scan module (contract in
// io/scan/scan_read.hpp, seam in io/scan/scan_module.hpp), and the module's
// exported version.
//
// The file is read into a pcl::PCLPointCloud2, which keeps every field as
// the file stores it; x, y and z are then taken from the blob by their
// offset and type. Going through pcl::PointXYZ would round a double file
// to floats (15 um steps 200 mm from the origin: docs/scan.md "Precision").
#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <new>
#include <string>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/scan/pcl/scan_pcl_entry.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow::scan {

namespace {

// PCL reports problems on the console; the module says what went wrong in
// its own message instead, once, naming the file.
void quiet_pcl() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }

const char* type_name(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8: return "int8";
    case pcl::PCLPointField::UINT8: return "uint8";
    case pcl::PCLPointField::INT16: return "int16";
    case pcl::PCLPointField::UINT16: return "uint16";
    case pcl::PCLPointField::INT32: return "int32";
    case pcl::PCLPointField::UINT32: return "uint32";
    case pcl::PCLPointField::INT64: return "int64";
    case pcl::PCLPointField::UINT64: return "uint64";
    case pcl::PCLPointField::FLOAT32: return "float32";
    case pcl::PCLPointField::FLOAT64: return "float64";
    default: return nullptr;
  }
}

template <class T>
double load(const std::uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof value);
  return static_cast<double>(value);
}

// The value of a scalar field at `at`, exactly (every integer type up to 32
// bits and both float types convert to double without rounding).
double value_at(const std::uint8_t* at, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8: return load<std::int8_t>(at);
    case pcl::PCLPointField::UINT8: return load<std::uint8_t>(at);
    case pcl::PCLPointField::INT16: return load<std::int16_t>(at);
    case pcl::PCLPointField::UINT16: return load<std::uint16_t>(at);
    case pcl::PCLPointField::INT32: return load<std::int32_t>(at);
    case pcl::PCLPointField::UINT32: return load<std::uint32_t>(at);
    case pcl::PCLPointField::INT64: return load<std::int64_t>(at);
    case pcl::PCLPointField::UINT64: return load<std::uint64_t>(at);
    case pcl::PCLPointField::FLOAT32: return load<float>(at);
    case pcl::PCLPointField::FLOAT64: return load<double>(at);
    default: return std::nan("");
  }
}

std::size_t field_size(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
    case pcl::PCLPointField::UINT8: return 1;
    case pcl::PCLPointField::INT16:
    case pcl::PCLPointField::UINT16: return 2;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::FLOAT32: return 4;
    default: return 8;
  }
}

const pcl::PCLPointField* find_field(const pcl::PCLPointCloud2& cloud, const std::string& name,
                                     const std::string& other_name = "") {
  for (const pcl::PCLPointField& f : cloud.fields)
    if (f.name == name || (!other_name.empty() && f.name == other_name)) return &f;
  return nullptr;
}

// The PLY header's format line ("ascii", "binary_little_endian", ...) and
// the vertex count it declares; PCL reads past both without saying.
struct PlyHeader {
  std::string format;
  long long vertices = -1;
};

PlyHeader ply_header(const std::string& path) {
  PlyHeader header;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int n = 0; n < 10000 && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("format ", 0) == 0) {
      const std::size_t end = line.find(' ', 7);
      header.format = line.substr(7, end == std::string::npos ? std::string::npos : end - 7);
    } else if (line.rfind("element vertex ", 0) == 0) {
      try {
        header.vertices = std::stoll(line.substr(15));
      } catch (const std::exception&) {
        header.vertices = -1;
      }
    } else if (line == "end_header") {
      break;
    }
  }
  return header;
}

}  // namespace

ScanCloud read_with_pcl(const std::string& path) {
  quiet_pcl();
  ScanCloud scan;
  scan.file = path;
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  const bool ply = lower_extension(path) == ".ply";
  long long declared = -1;
  if (ply) {
    const PlyHeader header = ply_header(path);
    if (header.format.empty()) throw InputError(path + ": not a PLY file (no format line in its header)");
    scan.format = "ply " + header.format;
    declared = header.vertices;
    if (declared > kMaxScanPoints)
      throw InputError(path + ": the header declares " + std::to_string(declared) + " vertices, more than " +
                       std::to_string(kMaxScanPoints) + " (docs/formats.md \"Limits\")");
    pcl::PLYReader reader;
    if (reader.read(path, cloud, origin, orientation, version) < 0)
      throw InputError(path + ": PCL cannot read it as PLY (a malformed header, a property of unknown type, or "
                              "the data end before the header's element counts)");
  } else {
    scan.format = "pcd";
    pcl::PCDReader reader;
    {
      pcl::PCLPointCloud2 header;
      int data_type = 0;
      unsigned int data_index = 0;
      if (reader.readHeader(path, header, origin, orientation, version, data_type, data_index) < 0)
        throw InputError(path + ": PCL cannot read it as PCD (a malformed header)");
      const long long points = static_cast<long long>(header.width) * header.height;
      if (points > kMaxScanPoints)
        throw InputError(path + ": the header declares " + std::to_string(points) + " points, more than " +
                         std::to_string(kMaxScanPoints) + " (docs/formats.md \"Limits\")");
    }
    if (reader.read(path, cloud, origin, orientation, version) < 0)
      throw InputError(path + ": PCL cannot read it as PCD (a malformed header, or fewer data than its POINTS "
                              "says)");
    // VIEWPOINT tx ty tz qw qx qy qz: the scanner's pose in the cloud's
    // frame. PCL writes "0 0 0 1 0 0 0" when nobody set it, so that exact
    // header says nothing; any other gives the scanner's position (its
    // orientation does not change a line of sight). docs/scan.md "Line of sight".
    const bool pcl_default = origin.head<3>().isZero() && orientation.w() == 1 && orientation.x() == 0 &&
                             orientation.y() == 0 && orientation.z() == 0;
    if (!pcl_default) {
      if (!origin.head<3>().allFinite()) throw InputError(path + ": its VIEWPOINT is not a finite position");
      scan.viewpoint = origin.head<3>().cast<double>();
    }
  }
  const std::size_t count = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (declared >= 0 && static_cast<long long>(count) != declared)
    throw InputError(path + ": the header declares " + std::to_string(declared) + " vertices, PCL read " +
                     std::to_string(count));
  if (count == 0) throw InputError(path + ": the scan holds no point");
  const pcl::PCLPointField* axes[3] = {find_field(cloud, "x"), find_field(cloud, "y"), find_field(cloud, "z")};
  for (int k = 0; k < 3; ++k)
    if (!axes[k]) throw InputError(path + ": the points have no " + std::string(1, "xyz"[k]) + " coordinate");
  const pcl::PCLPointField* normal[3] = {find_field(cloud, "normal_x", "nx"), find_field(cloud, "normal_y", "ny"),
                                         find_field(cloud, "normal_z", "nz")};
  const bool has_normals = normal[0] && normal[1] && normal[2];
  const std::size_t row_needed = static_cast<std::size_t>(cloud.width) * cloud.point_step;
  if (cloud.row_step < row_needed || cloud.data.size() < static_cast<std::size_t>(cloud.row_step) * cloud.height)
    throw InputError(path + ": PCL read fewer data than the header declares (" + std::to_string(cloud.data.size()) +
                     " bytes for " + std::to_string(count) + " points)");
  for (const pcl::PCLPointField* f : {axes[0], axes[1], axes[2], normal[0], normal[1], normal[2]}) {
    if (!f) continue;
    if (!type_name(f->datatype))
      throw InputError(path + ": field " + f->name + " has a type that is not a number");
    if (f->offset + field_size(f->datatype) > cloud.point_step)
      throw InputError(path + ": field " + f->name + " lies outside the point's record");
  }
  scan.coordinate_type = type_name(axes[0]->datatype);
  if (axes[1]->datatype != axes[0]->datatype || axes[2]->datatype != axes[0]->datatype)
    scan.coordinate_type += " (x), " + std::string(type_name(axes[1]->datatype)) + " (y), " +
                            type_name(axes[2]->datatype) + " (z)";
  for (const pcl::PCLPointField& f : cloud.fields) {
    bool used = &f == axes[0] || &f == axes[1] || &f == axes[2];
    for (const pcl::PCLPointField* n : normal) used = used || (has_normals && &f == n);
    if (!used && !f.name.empty() && f.name != "_") scan.ignored_fields.push_back(f.name);
  }
  // PCL hands the data over in the host's byte order whatever the file's
  // (its PLY parser swaps big-endian files as it reads them); a blob still
  // marked big-endian would need swapping, which no reader of PCL 1.13 asks for.
  if (cloud.is_bigendian) throw InputError(path + ": PCL returned big-endian data, which Furrow does not swap");
  scan.read = count;
  scan.points.reserve(count);
  if (has_normals) scan.normals.reserve(count);
  for (std::uint32_t row = 0; row < cloud.height; ++row)
    for (std::uint32_t col = 0; col < cloud.width; ++col) {
      const std::uint8_t* record = cloud.data.data() + static_cast<std::size_t>(row) * cloud.row_step +
                                   static_cast<std::size_t>(col) * cloud.point_step;
      const Eigen::Vector3d p(value_at(record + axes[0]->offset, axes[0]->datatype),
                              value_at(record + axes[1]->offset, axes[1]->datatype),
                              value_at(record + axes[2]->offset, axes[2]->datatype));
      if (!p.allFinite()) {
        ++scan.not_finite;
        continue;
      }
      scan.points.push_back(p);
      if (has_normals) {
        Eigen::Vector3f n(static_cast<float>(value_at(record + normal[0]->offset, normal[0]->datatype)),
                          static_cast<float>(value_at(record + normal[1]->offset, normal[1]->datatype)),
                          static_cast<float>(value_at(record + normal[2]->offset, normal[2]->datatype)));
        const float length = n.norm();
        scan.normals.push_back(std::isfinite(length) && length > 0 ? Eigen::Vector3f(n / length)
                                                                   : Eigen::Vector3f::Zero());
      }
    }
  return scan;
}

}  // namespace furrow::scan

// The module's exported functions (scan_module.hpp); everything else in it
// is hidden.
extern "C" __attribute__((visibility("default"))) const char* furrow_module_version() { return FURROW_VERSION; }

extern "C" __attribute__((visibility("default"))) int furrow_scan_read(const std::string* path,
                                                                     furrow::ScanCloud* cloud, std::string* message) {
  using furrow::scan::ScanModuleOutcome;
  return furrow::scan::guarded_entry(*path, "the scan reader", ScanModuleOutcome::input_error,
                                     "PCL cannot read the scan", message,
                                     [&] { *cloud = furrow::scan::read_with_pcl(*path); });
}
