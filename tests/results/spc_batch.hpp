#pragma once
// A small batch for the SPC document tests: 30 parts (the last FAIL), a
// drifting point that raises violations, a region in control that one part
// did not measure, and a point measured in the first part only.
#include <string>
#include <vector>

#include "results/characteristic_series.hpp"
#include "spc_oracle.hpp"

inline furrow::SpcInput spc_batch() {
  using namespace furrow;
  SpcInput in;
  for (int i = 0; i < 30; ++i)
    in.parts.push_back({"SN" + std::to_string(100 + i), "2026-11-" + std::to_string(10 + i % 18) + "T08:00:00Z",
                        i == 29 ? "FAIL" : "PASS"});
  CharacteristicSeries drift{"P0002", "point", -0.05, 0.05, {}, {}};
  const std::vector<double> noise = spc_oracle::normal_sample(42, 30, 0, 0.002);
  for (std::size_t i = 0; i < 30; ++i) {
    drift.part_index.push_back(i);
    drift.values.push_back(0.0025 * static_cast<double>(i) + noise[i]);
  }
  CharacteristicSeries region{"R1", "region", -0.03, 0.04, {}, {}};
  const std::vector<double> calm = spc_oracle::normal_sample(2029, 30, 0.005, 0.004);
  for (std::size_t i = 0; i < 30; ++i) {
    if (i == 12) continue;  // not measured in that part
    region.part_index.push_back(i);
    region.values.push_back(calm[i]);
  }
  CharacteristicSeries once{"P0001", "point", -0.05, 0.05, {0}, {0.01}};
  in.characteristics = {once, drift, region};
  return in;
}
