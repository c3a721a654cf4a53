#pragma once
// The report's deviation colour scale written again for the tests, from the
// anchor table in docs/report.md (ColorBrewer RdBu, 7 classes) with plain
// linear interpolation: an oracle independent of render/colour_scale.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace furrow::test {

inline std::array<int, 3> deviation_ramp(double t) {
  static const double anchors[7][4] = {{-1.0, 5, 48, 97},   {-0.6, 33, 102, 172}, {-0.3, 146, 197, 222},
                                       {0.0, 247, 247, 247}, {0.3, 244, 165, 130}, {0.6, 214, 96, 77},
                                       {1.0, 103, 0, 31}};
  if (!std::isfinite(t)) return {150, 150, 150};  // not evaluated: grey
  t = std::max(-1.0, std::min(1.0, t));
  int k = 0;
  while (k < 5 && t > anchors[k + 1][0]) ++k;
  const double s = (t - anchors[k][0]) / (anchors[k + 1][0] - anchors[k][0]);
  std::array<int, 3> c{};
  for (int i = 0; i < 3; ++i)
    c[i] = static_cast<int>(std::lround(anchors[k][i + 1] + s * (anchors[k + 1][i + 1] - anchors[k][i + 1])));
  return c;
}

// "rrggbb" (6 hex digits) at `offset` of a packed colour string.
inline std::array<int, 3> packed_colour(const std::string& hex, std::size_t index) {
  return {std::stoi(hex.substr(6 * index, 2), nullptr, 16), std::stoi(hex.substr(6 * index + 2, 2), nullptr, 16),
          std::stoi(hex.substr(6 * index + 4, 2), nullptr, 16)};
}

}  // namespace furrow::test
