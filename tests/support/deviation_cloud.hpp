#pragma once
// The deviation cloud of `furrow compare --scan --deviations`, parsed from
// its documented layout (docs/formats.md "Deviation cloud"), not with
// Furrow's or PCL's reader: the scan tests' independent reading of it.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <cstring>
#include <string>
#include <vector>

namespace furrow::test {

struct DeviationPoint {
  Eigen::Vector3d xyz;
  float deviation = 0;
  unsigned char outlier = 0;
};

inline std::vector<DeviationPoint> parse_deviation_ply(const std::string& bytes) {
  const std::string end = "end_header\n";
  const std::size_t body = bytes.find(end);
  REQUIRE(body != std::string::npos);
  const std::string header = bytes.substr(0, body);
  REQUIRE(header.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  REQUIRE(header.find("property double x\nproperty double y\nproperty double z\nproperty float deviation\n"
                      "property uchar outlier\n") != std::string::npos);
  const std::size_t at = header.find("element vertex ");
  REQUIRE(at != std::string::npos);
  const std::size_t n = std::stoul(header.substr(at + 15));
  const std::size_t record = 3 * 8 + 4 + 1;
  REQUIRE(bytes.size() == body + end.size() + n * record);
  std::vector<DeviationPoint> out(n);
  const char* p = bytes.data() + body + end.size();
  for (std::size_t i = 0; i < n; ++i, p += record) {
    for (int k = 0; k < 3; ++k) std::memcpy(&out[i].xyz[k], p + 8 * k, 8);
    std::memcpy(&out[i].deviation, p + 24, 4);
    out[i].outlier = static_cast<unsigned char>(p[28]);
  }
  return out;
}

}  // namespace furrow::test
