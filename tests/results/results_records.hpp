#pragma once
// Comparison records made up for the results-database tests: seeded
// deviations, point ids and regions, and a distinct identity (the digest
// field) per record, so that many parts can be stored fast without running
// a comparison for each.
#include <cstdint>
#include <random>
#include <string>

#include "results/results_database.hpp"

namespace furrow::test {

// `n` points P0..P(n-1) in regions 1..3 (every seventh an outlier, not
// evaluated), regions with the statistics of their evaluated points as the
// store would carry them (only their means are read back by SPC).
inline ComparisonRecord made_up_record(const std::string& serial, std::uint64_t identity, std::size_t n,
                                       std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.004);
  ComparisonRecord r;
  r.serial = serial;
  r.part = "part.json";
  r.plan_fingerprint = std::string(64, 'a');
  r.date = "2026-11-28T04:00:00Z";
  r.operator_name = "A. Operator";
  r.cmm = "CMM-1";
  r.verdict = "PASS";
  // 64 hex digits, unique per identity.
  char digest[65];
  std::snprintf(digest, sizeof digest, "%016llx%048d", static_cast<unsigned long long>(identity), 0);
  r.comparison_sha256 = digest;
  r.zone_lower = -0.025;
  r.zone_upper = 0.025;
  double sum[4] = {0, 0, 0, 0};
  std::size_t count[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < n; ++k) {
    StoredPoint p;
    p.id = "P" + std::to_string(k);
    p.region = 1 + static_cast<int>(k % 3);
    p.deviation = noise(rng);
    p.evaluated = k % 7 != 6;
    if (p.evaluated) {
      p.in_tolerance = p.deviation >= r.zone_lower && p.deviation <= r.zone_upper;
      sum[*p.region] += p.deviation;
      ++count[*p.region];
    } else {
      p.outlier = "blunder";
    }
    r.points.push_back(p);
  }
  for (int g = 1; g <= 3; ++g)
    if (count[g]) {
      StoredRegion s;
      s.region = g;
      s.count = count[g];
      s.mean = sum[g] / static_cast<double>(count[g]);
      r.regions.push_back(s);
    }
  r.inputs = {{"comparison", "comparison.json", r.comparison_sha256}, {"part", "part.json", std::string(64, 'b')}};
  return r;
}

}  // namespace furrow::test
