#pragma once
// Statistical process control of each characteristic over the parts of a
// batch: individuals and moving-range (I-MR) chart limits, process
// capability against the profile zone, the trend per part with its 95 %
// confidence interval, and the Nelson rules (docs/spc.md).
//
// Input: SpcInput (characteristic_series.hpp), deviations and zone limits
// in mm, parts in storing order. Output: the same characteristics sorted by
// id, each with its figures; a figure that the series cannot give (fewer
// than two values, a series without variation, fewer than three values for
// the interval) is absent (std::nullopt) and `notes` says why, so no
// infinity or NaN ever reaches a document.
//
// compute_spc throws InputError naming the characteristic when the input
// breaks its contract (arrays of different lengths, a part index out of
// range or not increasing, a value or limit not finite or beyond 1e6 mm,
// lower >= upper, a kind other than "point" or "region", an id twice).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/characteristic_series.hpp"

namespace furrow {

// The SPC constants for individuals (subgroups of one, moving ranges of two
// consecutive values): d2 and D4 for n = 2 (docs/spc.md "Constants").
constexpr double kSpcD2 = 1.128;
constexpr double kSpcD4 = 3.267;
// Two-sided confidence level of the slope's interval.
constexpr double kSpcSlopeConfidence = 0.95;

struct SpcViolation {
  int rule = 0;           // Nelson rule 1 .. 8 (spc_nelson_rules.hpp)
  std::size_t index = 0;  // position in the characteristic's series of the first value
  std::size_t last = 0;   // position of the last value of the pattern
  std::string serial;     // serial of the part at `index`
};

struct SpcSlope {
  double value = 0;           // least-squares slope of value on part index [mm/part]
  std::optional<double> low;  // 95 % interval (Student t, n - 2 dof) [mm/part]
  std::optional<double> high;
};

struct CharacteristicSpc {
  std::string id;
  std::string kind;
  double lower = 0;  // profile zone [mm]
  double upper = 0;
  // The series as read (for the charts): part indices and values [mm].
  std::vector<std::size_t> part_index;
  std::vector<double> values;

  std::size_t n = 0;
  std::optional<double> mean;           // centre line [mm]
  std::optional<double> sigma_within;   // mean moving range / d2 [mm]
  std::optional<double> sigma_overall;  // sample standard deviation (n - 1) [mm]
  std::optional<double> mr_mean;        // mean moving range [mm]
  std::optional<double> mr_ucl;         // D4 * mean moving range [mm] (the lower limit is 0)
  std::optional<double> lcl, ucl;       // mean -+ 3 sigma_within [mm]
  std::optional<double> cp, cpk, pp, ppk;
  std::optional<SpcSlope> slope;
  std::vector<SpcViolation> violations;  // by (index, rule)
  std::vector<std::string> notes;        // why a figure is absent, in computing order
};

struct SpcResult {
  std::vector<PartRecord> parts;                   // storing order, as read
  std::vector<CharacteristicSpc> characteristics;  // sorted by id
};

SpcResult compute_spc(const SpcInput& input);

// Whether some characteristic's violation includes the latest part's value:
// the series holds a value of the last part in storing order and a violation
// ends there (a violation that ends at the last value is still going on).
// The `furrow spc` command exits 1 when it does (docs/spc.md "Exit status").
bool violation_in_latest_part(const SpcResult& result);

// The violations that reach the latest part, as (characteristic position,
// violation position) pairs, characteristics by id, violations by index.
std::vector<std::pair<std::size_t, std::size_t>> latest_part_violations(const SpcResult& result);

// Characteristic positions, worst first: lowest cpk first (those without a
// cpk after all that have one), then most violations, then by id.
std::vector<std::size_t> worst_first(const SpcResult& result);

}  // namespace furrow
