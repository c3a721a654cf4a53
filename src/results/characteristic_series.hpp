#pragma once
// What statistical process control reads from the results database: each
// characteristic (a plan point, or a curvature region) followed over the
// parts of a batch, in the order the parts were stored (docs/spc.md).
//
// The database fills it (results_database.hpp); the SPC computation, its
// charts and its QIF Statistics document read it and nothing else, so the
// statistics can be tested on designed series without a database.
//
// Units: deviations and zone limits in mm, signed as everywhere in Furrow
// (+ material left, - material removed). Parts are indexed 0, 1, ... in
// storing order over the whole selection; a characteristic that a part did
// not measure (the point not measured, or an outlier) has no entry for that
// part, so `part_index` may skip numbers.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace furrow {

// One part of the batch, as stored.
struct PartRecord {
  std::string serial;   // --serial given when the part was stored
  std::string date;     // ISO 8601 UTC, when the comparison was made
  std::string verdict;  // "PASS", "FAIL", "INCONCLUSIVE" (report's wording)
  std::string operator_name, cmm;  // from the inspection record; empty when none
  std::optional<std::string> furrow_version;  // that stored it; none before schema 2
};

struct CharacteristicSeries {
  std::string id;        // plan point id, or region id (kind "region")
  std::string kind;      // "point" or "region"
  double lower = 0;      // profile zone's lower limit [mm]
  double upper = 0;      // profile zone's upper limit [mm], lower < upper
  // Parallel arrays, oldest part first: the part's index into
  // SpcInput::parts and the characteristic's value in that part (a point's
  // signed deviation; a region's mean signed deviation) [mm].
  std::vector<std::size_t> part_index;
  std::vector<double> values;
};

struct SpcInput {
  std::vector<PartRecord> parts;                     // storing order
  std::vector<CharacteristicSeries> characteristics; // sorted by id
};

}  // namespace furrow
