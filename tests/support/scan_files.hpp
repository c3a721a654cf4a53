#pragma once
// Point-cloud files written byte by byte for the scan tests: PLY (ascii,
// binary little or big endian, float or double coordinates, extra vertex
// properties, faces) and PCD. Written here, independently of PCL, so the
// reader is checked against bytes whose values the test knows exactly.
#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace furrow::test {

// The bytes of a scalar in little (false) or big (true) endian order.
template <class T>
std::string scalar_bytes(T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  std::string bytes(raw, sizeof(T));  // the host (x86-64) is little endian
  if (big_endian) bytes = std::string(bytes.rbegin(), bytes.rend());
  return bytes;
}

struct PlyOptions {
  std::string format = "binary_little_endian";  // or "binary_big_endian", "ascii"
  bool doubles = true;                          // double x y z, else float
  // uchar red green blue before y (PCL packs them into one rgb field), float
  // intensity before z, float nx ny nz after z.
  bool extras = false;
  int faces = 0;        // triangles appended as a face element (vertex indices 0 1 2)
  // Normals written with `extras` (one per point; +z when empty).
  std::vector<Eigen::Vector3f> normals;
};

inline std::string ply_text(const std::vector<Eigen::Vector3d>& points, const PlyOptions& o) {
  const std::string type = o.doubles ? "double" : "float";
  std::string out = "ply\nformat " + o.format + " 1.0\ncomment written by the Furrow tests\n";
  out += "element vertex " + std::to_string(points.size()) + "\n";
  out += "property " + type + " x\n";
  if (o.extras) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "property " + type + " y\n";
  if (o.extras) out += "property float intensity\n";
  out += "property " + type + " z\n";
  if (o.extras) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (o.faces > 0)
    out += "element face " + std::to_string(o.faces) + "\nproperty list uchar int vertex_indices\n";
  out += "end_header\n";
  const bool ascii = o.format == "ascii";
  const bool big = o.format == "binary_big_endian";
  auto number = [&](double v, bool as_double) {
    if (ascii) {
      char text[40];
      std::snprintf(text, sizeof text, "%.17g ", v);
      out += text;
    } else if (as_double) {
      out += scalar_bytes<double>(v, big);
    } else {
      out += scalar_bytes<float>(static_cast<float>(v), big);
    }
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    number(points[i].x(), o.doubles);
    if (o.extras) {
      for (int c = 0; c < 3; ++c) {
        if (ascii) out += std::to_string((i + c) % 256) + " ";
        else out += std::string(1, static_cast<char>((i + c) % 256));
      }
    }
    number(points[i].y(), o.doubles);
    if (o.extras) number(0.25 * static_cast<double>(i % 7), false);
    number(points[i].z(), o.doubles);
    if (o.extras) {
      const Eigen::Vector3f n = i < o.normals.size() ? o.normals[i] : Eigen::Vector3f::UnitZ();
      for (int k = 0; k < 3; ++k) number(n[k], false);
    }
    if (ascii) out += "\n";
  }
  for (int f = 0; f < o.faces; ++f) {
    if (ascii) {
      out += "3 0 1 2\n";
    } else {
      out += std::string(1, '\3');
      for (int v = 0; v < 3; ++v) out += scalar_bytes<std::int32_t>(v, big);
    }
  }
  return out;
}

// PCD with double x y z (TYPE F, SIZE 8), ascii or binary; `viewpoint` is
// the VIEWPOINT header's seven numbers (PCL's default when nobody set one).
inline std::string pcd_text(const std::vector<Eigen::Vector3d>& points, bool binary,
                            const std::string& viewpoint = "0 0 0 1 0 0 0") {
  const std::string n = std::to_string(points.size());
  std::string out = "# .PCD v0.7 - written by the Furrow tests\nVERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\n"
                    "TYPE F F F\nCOUNT 1 1 1\nWIDTH " + n + "\nHEIGHT 1\nVIEWPOINT " + viewpoint + "\nPOINTS " + n +
                    "\nDATA " + (binary ? "binary" : "ascii") + "\n";
  for (const Eigen::Vector3d& p : points) {
    if (binary) {
      for (int k = 0; k < 3; ++k) out += scalar_bytes<double>(p[k], false);
    } else {
      char text[80];
      std::snprintf(text, sizeof text, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
      out += text;
    }
  }
  return out;
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace furrow::test
