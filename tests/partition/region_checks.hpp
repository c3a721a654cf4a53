#pragma once
// Helpers and checks shared by the partition tests.
#include <doctest/doctest.h>

#include "partition/partition.hpp"

namespace furrow::test {

// The same cell counts on every face.
inline PartitionOptions grid(int nu, int nv) {
  PartitionOptions o;
  o.grid = GridSize{nu, nv};
  return o;
}

inline double total_region_area(const RegionMap& map) {
  double a = 0;
  for (const Region& r : map.regions) a += r.area;
  return a;
}

// Every cell centre is found by region_at in the region it was labelled with,
// and cells without a region are found in none.
inline void check_region_at_matches_labels(const PartitionResult& result) {
  for (std::size_t f = 0; f < result.cells.size(); ++f) {
    const FaceCells& cells = result.cells[f];
    const RegionFace& info = result.map.faces[f];
    const double du = info.domain.width_u() / info.nu, dv = info.domain.width_v() / info.nv;
    int mismatches = 0;
    for (int i = 0; i < info.nu; ++i) {
      for (int j = 0; j < info.nv; ++j) {
        const int l = cells.labels.at(i, j);
        const auto found = result.map.region_at(static_cast<int>(f), info.domain.u0 + (i + 0.5) * du,
                                                info.domain.v0 + (j + 0.5) * dv);
        const bool ok = l < 0 ? !found.has_value() : (found && *found == cells.first_id + l);
        mismatches += ok ? 0 : 1;
      }
    }
    CHECK(mismatches == 0);
  }
}

}  // namespace furrow::test
