#include "partition/part_fingerprint.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace furrow {

namespace {

class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) {
      hash_ ^= p[k];
      hash_ *= 0x100000001b3ULL;
    }
  }
  void number(double x) {
    x += 0.0;  // -0.0 and 0.0 describe the same geometry
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    bytes(&bits, sizeof bits);
  }
  void integer(long long x) { bytes(&x, sizeof x); }
  void text(const std::string& s) {
    integer(static_cast<long long>(s.size()));
    bytes(s.data(), s.size());
  }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
    return buf;
  }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

std::string face_fingerprint(const Face& face) {
  const NurbsSurface& s = face.surface();
  Fnv1a h;
  h.text(face.name());
  h.integer(face.reversed() ? 1 : 0);
  h.integer(s.degree_u());
  h.integer(s.degree_v());
  h.integer(s.num_u());
  h.integer(s.num_v());
  for (double k : s.knots_u()) h.number(k);
  for (double k : s.knots_v()) h.number(k);
  for (int i = 0; i < s.num_u(); ++i) {
    for (int j = 0; j < s.num_v(); ++j) {
      const Eigen::Vector3d& p = s.control_point(i, j);
      h.number(p.x());
      h.number(p.y());
      h.number(p.z());
      h.number(s.weight(i, j));
    }
  }
  h.integer(static_cast<long long>(face.trim().loops().size()));
  for (const UvLoop& loop : face.trim().loops()) {
    h.integer(static_cast<long long>(loop.size()));
    for (const Eigen::Vector2d& p : loop) {
      h.number(p.x());
      h.number(p.y());
    }
  }
  return h.hex();
}

std::string part_fingerprint(const Part& part) {
  Fnv1a h;
  h.integer(static_cast<long long>(part.faces.size()));
  for (const Face& f : part.faces) h.text(face_fingerprint(f));
  return h.hex();
}

}  // namespace furrow
