#pragma once
// Measured versus nominal: registration, per-point deviations against a
// profile tolerance zone, statistics overall and per region, pass/fail.
// What `furrow compare` computes and comparison_file.hpp writes.
//
// Which points count: a point is evaluated unless it is a blunder, beyond a
// face edge or has no foot point (registration.hpp). Large real deviations
// (outlier reason large_deviation) are evaluated - they are left out of the
// fit only - so a gouge fails the part instead of vanishing.
//
// Regions: each point may carry a region id. Today it comes from the plan
// point with the same id; a partition (regions.json) can later assign it from
// the foot point (face, u, v) and call summarize() again - statistics per
// region are computed from whatever ids are set.
#include <optional>
#include <string>
#include <vector>

#include "inspection/registration.hpp"
#include "inspection/tolerance_zone.hpp"

namespace furrow {

struct DeviationStatistics {
  std::size_t count = 0;
  double mean = 0, sigma = 0, min = 0, max = 0;  // [mm]; sigma: sample standard deviation
};
// Deterministic (sums in index order). All zero for no values.
DeviationStatistics deviation_statistics(const std::vector<double>& values);

struct RegionStatistics {
  int region = 0;
  DeviationStatistics deviations;
  std::size_t out_of_tolerance = 0;
};

struct ComparisonSummary {
  std::size_t points = 0, in_fit = 0, evaluated = 0, outliers = 0;
  std::size_t in_tolerance = 0, out_of_tolerance = 0;
  DeviationStatistics deviations;         // over evaluated points
  double profile = 0;                     // 2 max |d| over evaluated points [mm]
  bool pass = false;  // registration converged and every evaluated point in the zone
  std::vector<RegionStatistics> regions;  // by increasing region id; empty without region ids
};

struct Comparison {
  RegistrationResult registration;
  ToleranceZone tolerance;
  std::vector<std::optional<int>> region;  // per point
  std::vector<bool> in_tolerance;          // per point (false for points not evaluated)
  ComparisonSummary summary;
};

struct CompareOptions {
  RegistrationOptions registration;
  ToleranceZone tolerance;
};

// Registers and evaluates. `plan` may be null (no id coarse start, no regions).
Comparison compare_measurements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                const InspectionPlan* plan, const CompareOptions& options);

// Recomputes in_tolerance and the summary from the registration, the zone
// and the region ids (call after changing either).
void summarize(Comparison& comparison);

}  // namespace furrow
