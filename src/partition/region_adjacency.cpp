#include "partition/region_adjacency.hpp"

namespace furrow {

std::vector<std::map<int, double>> shared_borders(const RegionLabels& labels,
                                                  const CurvatureField& field) {
  std::vector<std::map<int, double>> borders(static_cast<std::size_t>(labels.count()));
  // Both directions receive the same additions in the same order, so
  // borders[a][b] == borders[b][a] exactly.
  auto add = [&](int a, int b, double length) {
    borders[static_cast<std::size_t>(a)][b] += length;
    borders[static_cast<std::size_t>(b)][a] += length;
  };
  const int nu = labels.nu, nv = labels.nv;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const int a = labels.at(i, j);
      if (a < 0) continue;
      const CurvatureSample& s = field.at(i, j);
      if (i + 1 < nu) {
        const int b = labels.at(i + 1, j);
        // Neighbour along u: the shared edge has constant u and runs along v.
        if (b >= 0 && b != a) add(a, b, 0.5 * (s.length_v + field.at(i + 1, j).length_v));
      }
      if (j + 1 < nv) {
        const int b = labels.at(i, j + 1);
        if (b >= 0 && b != a) add(a, b, 0.5 * (s.length_u + field.at(i, j + 1).length_u));
      }
    }
  }
  return borders;
}

}  // namespace furrow
