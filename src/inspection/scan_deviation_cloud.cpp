// The deviation cloud (contract in scan_deviation_cloud.hpp).
#include "inspection/scan_deviation_cloud.hpp"

#include <cstring>

namespace furrow {

namespace {

// Little endian whatever the host (Furrow builds for little-endian hosts;
// the bytes are assembled explicitly so the file says what it claims).
template <class T>
void append_le(std::string& out, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  if (first == 1)
    out.append(reinterpret_cast<const char*>(raw), sizeof(T));
  else
    for (std::size_t k = sizeof(T); k-- > 0;) out.push_back(static_cast<char>(raw[k]));
}

}  // namespace

std::string scan_deviation_ply(const ScanComparison& c, const ScanCloud& cloud) {
  const std::size_t n = cloud.points.size();
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment furrow " FURROW_VERSION
                    " deviation cloud of " + cloud.file +
                    " (part frame, mm; outlier: 0 evaluated, 1 spray far, 2 spray near, 3 off part)\n"
                    "element vertex " + std::to_string(n) +
                    "\nproperty double x\nproperty double y\nproperty double z\n"
                    "property float deviation\nproperty uchar outlier\nend_header\n";
  out.reserve(out.size() + n * 29);
  for (std::size_t i = 0; i < n; ++i) {
    // Relative to the local origin first, as the fit ran: no cancellation
    // for a cloud far from its scanner frame's origin.
    const Eigen::Vector3d p = c.registration.transform * (cloud.points[i] - c.pre.origin);
    for (int k = 0; k < 3; ++k) append_le<double>(out, p[k]);
    append_le<float>(out, c.deviation[i]);
    out.push_back(static_cast<char>(c.status[i]));
  }
  return out;
}

}  // namespace furrow
