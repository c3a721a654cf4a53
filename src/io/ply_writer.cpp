#include "io/ply_writer.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace furrow {

namespace {

const char* type_name(PlyScalar t) {
  switch (t) {
    case PlyScalar::uchar: return "uchar";
    case PlyScalar::float32: return "float";
    case PlyScalar::float64: return "double";
  }
  return "double";
}

// Appends the bytes of `value` least significant first, so the file is
// little-endian on any host.
template <class Bits>
void append_le(std::string& out, Bits bits) {
  for (std::size_t b = 0; b < sizeof(Bits); ++b) out.push_back(static_cast<char>((bits >> (8 * b)) & 0xFF));
}

}  // namespace

std::string ply_vertex_text(const std::vector<PlyColumn>& columns, const std::vector<std::string>& comments) {
  if (columns.empty()) throw std::invalid_argument("ply_vertex_text: no column");
  const std::size_t n = columns.front().values.size();
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& c : comments) {
    if (c.find('\n') != std::string::npos) throw std::invalid_argument("ply_vertex_text: a comment holds a line end");
    out += "comment " + c + "\n";
  }
  out += "element vertex " + std::to_string(n) + "\n";
  std::size_t record = 0;
  for (const PlyColumn& c : columns) {
    if (c.values.size() != n) throw std::invalid_argument("ply_vertex_text: column " + c.name + " has another length");
    out += std::string("property ") + type_name(c.type) + " " + c.name + "\n";
    record += c.type == PlyScalar::uchar ? 1 : c.type == PlyScalar::float32 ? 4 : 8;
  }
  out += "end_header\n";
  out.reserve(out.size() + n * record);
  for (std::size_t k = 0; k < n; ++k)
    for (const PlyColumn& c : columns) {
      const double v = c.values[k];
      if (!std::isfinite(v)) throw std::invalid_argument("ply_vertex_text: column " + c.name + " holds a non-finite value");
      switch (c.type) {
        case PlyScalar::uchar:
          if (!(v >= 0 && v <= 255 && v == std::floor(v)))
            throw std::invalid_argument("ply_vertex_text: column " + c.name + " holds a value that is no uchar");
          out.push_back(static_cast<char>(static_cast<unsigned char>(v)));
          break;
        case PlyScalar::float32: {
          const float f = static_cast<float>(v);
          if (!std::isfinite(f)) throw std::invalid_argument("ply_vertex_text: column " + c.name + " overflows a float");
          std::uint32_t bits;
          std::memcpy(&bits, &f, sizeof bits);
          append_le(out, bits);
          break;
        }
        case PlyScalar::float64: {
          std::uint64_t bits;
          std::memcpy(&bits, &v, sizeof bits);
          append_le(out, bits);
          break;
        }
      }
    }
  return out;
}

}  // namespace furrow
