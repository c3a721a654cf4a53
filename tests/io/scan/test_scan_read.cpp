// Reading scans (io/scan/scan_read.hpp) through the scan module and PCL's
// readers: every PLY and PCD variant is written byte by byte by the test
// (tests/support/scan_files.hpp), so the oracle is the values the test put
// in the file - doubles must come back bit for bit, floats widened exactly.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/scan/scan_read.hpp"
#include "support/input_error.hpp"
#include "support/run_cli.hpp"
#include "support/scan_files.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// Values no float holds: 17 significant digits, signs, a tiny and a large one.
std::vector<Eigen::Vector3d> awkward_points() {
  return {{123.45678901234567, -0.000123456789012345, 98765.432101234567},
          {-1.0000000000000002, 3.1415926535897931, 1e-9},
          {250.12345678901234, 250.98765432109876, -250.55555555555556},
          {0, -0, 42}};
}

void check_exact_points(const ScanCloud& c, const std::vector<Eigen::Vector3d>& expected) {
  REQUIRE(c.points.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(c.points[i][k] == expected[i][k]);
}

void check_exact(const ScanCloud& c, const std::vector<Eigen::Vector3d>& expected) {
  REQUIRE(c.points.size() == expected.size());
  CHECK(c.read == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(c.points[i][k] == expected[i][k]);
}

std::vector<Eigen::Vector3d> as_floats(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> out;
  // Per component: Eigen folds p.cast<float>().cast<double>() into no cast.
  auto widened = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  for (const Eigen::Vector3d& p : points) out.emplace_back(widened(p.x()), widened(p.y()), widened(p.z()));
  return out;
}

}  // namespace

TEST_CASE("scan PLY binary little and big endian doubles come back bit for bit") {
  const std::string dir = scratch_dir("scan-read-binary");
  for (const std::string format : {"binary_little_endian", "binary_big_endian"}) {
    CAPTURE(format);
    PlyOptions o;
    o.format = format;
    const std::string path = dir + "/" + format + ".ply";
    write_bytes(path, ply_text(awkward_points(), o));
    const ScanCloud c = read_scan(path);
    check_exact(c, awkward_points());
    CHECK(c.format == "ply " + format);
    CHECK(c.coordinate_type == "float64");
    CHECK(c.normals.empty());
  }
}

TEST_CASE("scan PLY float coordinates in both byte orders widen exactly") {
  const std::string dir = scratch_dir("scan-read-float");
  for (const std::string format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
    CAPTURE(format);
    PlyOptions o;
    o.format = format;
    o.doubles = false;
    const std::string path = dir + "/" + format + ".ply";
    write_bytes(path, ply_text(awkward_points(), o));
    const ScanCloud c = read_scan(path);
    // ascii: the 17 digits are parsed into a float by PCL, which is the
    // nearest float, the same one the cast picks.
    check_exact(c, as_floats(awkward_points()));
    CHECK(c.coordinate_type == "float32");
  }
}

TEST_CASE("scan PLY ascii doubles keep their 17 digits") {
  const std::string dir = scratch_dir("scan-read-ascii");
  PlyOptions o;
  o.format = "ascii";
  write_bytes(dir + "/a.ply", ply_text(awkward_points(), o));
  check_exact(read_scan(dir + "/a.ply"), awkward_points());
}

TEST_CASE("scan PLY extra properties normals and a mesh's faces are read past") {
  const std::string dir = scratch_dir("scan-read-extras");
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3f> normals;
  for (int i = 0; i < 300; ++i) {
    points.emplace_back(0.1 * i + 1e-7, std::sin(0.01 * i), 1000 + 0.001 * i);
    normals.push_back(Eigen::Vector3f(0.6f, 0.0f, 0.8f) * 2.0f);  // not unit in the file: normalised
  }
  for (const std::string format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
    CAPTURE(format);
    PlyOptions o;
    o.format = format;
    o.extras = true;
    o.faces = 5;
    o.normals = normals;
    const std::string path = dir + "/" + format + ".ply";
    write_bytes(path, ply_text(points, o));
    const ScanCloud c = read_scan(path);
    check_exact(c, points);
    REQUIRE(c.normals.size() == points.size());
    CHECK(std::abs(c.normals[17].x() - 0.6f) < 1e-6f);
    CHECK(std::abs(c.normals[17].z() - 0.8f) < 1e-6f);
    CHECK(c.ignored_fields.size() == 2);  // rgb (PCL packs red, green, blue into one field), intensity
  }
}

TEST_CASE("scan PCD ascii and binary doubles come back bit for bit") {
  const std::string dir = scratch_dir("scan-read-pcd");
  for (const bool binary : {false, true}) {
    CAPTURE(binary);
    const std::string path = dir + (binary ? "/b.pcd" : "/a.pcd");
    write_bytes(path, pcd_text(awkward_points(), binary));
    const ScanCloud c = read_scan(path);
    check_exact(c, awkward_points());
    CHECK(c.format == "pcd");
    CHECK(c.coordinate_type == "float64");
  }
}

TEST_CASE("scan a double cloud 10 km from the origin keeps its sub-micrometre steps") {
  // At 1e7 mm a float's step is 1 m and a double's 1.9e-9 mm: points 0.1 um
  // apart stay 0.1 um apart only if nothing went through a float.
  const std::string dir = scratch_dir("scan-read-far");
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector3d far(1e7, -1e7, 5e6);
  for (int i = 0; i < 50; ++i) points.push_back(far + Eigen::Vector3d(1e-4 * i, 2e-4 * i, -3e-4 * i));
  write_bytes(dir + "/far.ply", ply_text(points, PlyOptions{}));
  const ScanCloud c = read_scan(dir + "/far.ply");
  check_exact(c, points);
  for (int i = 1; i < 50; ++i) {
    const Eigen::Vector3d step = c.points[i] - c.points[0];
    CHECK((step - Eigen::Vector3d(1e-4 * i, 2e-4 * i, -3e-4 * i)).norm() < 1e-8);  // 10 pm
  }
}

TEST_CASE("scan inches are converted to mm after reading") {
  const std::string dir = scratch_dir("scan-read-inch");
  write_bytes(dir + "/in.ply", ply_text(awkward_points(), PlyOptions{}));
  const ScanCloud c = read_scan(dir + "/in.ply", 25.4);
  for (std::size_t i = 0; i < c.points.size(); ++i) CHECK(c.points[i] == awkward_points()[i] * 25.4);
}

TEST_CASE("scan bad files are refused naming the file") {
  const std::string dir = scratch_dir("scan-read-bad");
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(i, 2 * i, 3 * i);
  const std::string binary = ply_text(points, PlyOptions{});
  PlyOptions ascii;
  ascii.format = "ascii";
  const std::string text = ply_text(points, ascii);
  const std::string pcd = pcd_text(points, true);
  struct Bad {
    std::string name, bytes, says;
  };
  const std::vector<Bad> cases = {
      {"empty.ply", "", "empty"},
      {"garbage.ply", "\x13\x37 not a cloud at all \xff\xfe", "not a PLY"},
      {"header-only.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty double x\n", ""},
      {"truncated.ply", binary.substr(0, binary.size() - 24 * 50), ""},
      {"truncated-ascii.ply", text.substr(0, text.size() / 2), ""},
      {"no-xyz.ply",
       "ply\nformat ascii 1.0\nelement vertex 2\nproperty float a\nproperty float b\nend_header\n1 2\n3 4\n",
       "no x"},
      {"no-points.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                        "property float z\nend_header\n", ""},
      {"garbage.pcd", "this is no point cloud\n", "not a PCD"},
      {"truncated.pcd", pcd.substr(0, pcd.size() - 24 * 50), ""},
      {"cloud.xyz", text, "PLY (.ply) or PCD"},
      {"huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 50000001\nproperty double x\n"
                   "property double y\nproperty double z\nend_header\n", "more than 50000000"},
      {"huge.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 60000000\nHEIGHT 1\n"
                   "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 60000000\nDATA binary\n", "more than 50000000"},
  };
  for (const Bad& b : cases) {
    CAPTURE(b.name);
    const std::string path = dir + "/" + b.name;
    write_bytes(path, b.bytes);
    const std::string error = input_error_of([&] { read_scan(path); });
    CHECK(error.find(path) != std::string::npos);
    CHECK(error.find(b.says) != std::string::npos);
  }
  CHECK(input_error_of([&] { read_scan(dir + "/missing.ply"); }).find("missing.ply") != std::string::npos);
}

TEST_CASE("scan non-finite points of an organised PCD are counted and left out") {
  // An organised scan (WIDTH x HEIGHT) marks the pixels without a return
  // with NaN; they are counted, the others read exactly.
  const std::string dir = scratch_dir("scan-read-nan");
  const std::string text =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 2\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA ascii\n"
      "1.25 2.5 3.125\nnan nan nan\n-7.0000000000000009 8 9\n10 11 12\nnan 1 2\n0.1 0.2 0.30000000000000004\n";
  write_bytes(dir + "/organised.pcd", text);
  const ScanCloud c = read_scan(dir + "/organised.pcd");
  CHECK(c.read == 6);
  CHECK(c.not_finite == 2);
  check_exact_points(c, {{1.25, 2.5, 3.125}, {-7.0000000000000009, 8, 9}, {10, 11, 12}, {0.1, 0.2, 0.30000000000000004}});
}
