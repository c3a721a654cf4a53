#pragma once
// The results database: every comparison of a batch, one record per part,
// so that statistical process control can follow each characteristic over
// the parts (docs/results_database.md). The interface is the same for
// every back end; open_results_database() picks one from the location
// (a PostgreSQL connection string: PostgreSQL; anything else is a file
// path: SQLite).
//
// Contract of every back end:
// - Append-only: a part is stored whole in one transaction or not at all
//   (a crash or kill -9 while storing leaves the database as before it);
//   nothing is ever updated or deleted.
// - A comparison is known by the SHA-256 of its comparison.json bytes. The
//   same comparison stored again under the same serial is ignored
//   (StoreResult::already_stored); under another serial it is refused with
//   an InputError (one measurement cannot be two parts).
// - The same serial with a different comparison is a re-measurement: a new
//   record; SPC reads the latest record of each serial (load_spc_input).
// - Every value reaches SQL through bound parameters.
// - A location that is not Furrow's database, is corrupt, or has a newer
//   schema version than this program knows: InputError naming it, before
//   anything is written.
//
// Units: deviations, statistics and zone limits in mm, signed as everywhere
// (docs/architecture.md "Conventions").
#include <cstdint>
#include <ctime>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"
#include "results/characteristic_series.hpp"

namespace furrow {

// One input file the comparison rests on, by role ("comparison", "part",
// "measurements", "plan", "regions", "prediction", ...).
struct StoredInput {
  std::string role, path, sha256;  // sha256: lower-case hex
};

struct StoredPoint {
  std::string id;               // plan point id; may be empty (a file without ids)
  std::optional<int> region;    // region holding the foot point
  double deviation = 0;         // [mm]
  bool evaluated = false;       // counted against the zone (not an outlier, foot point found)
  std::optional<bool> in_tolerance;
  std::string outlier;          // reason, empty for none
};

struct StoredRegion {
  int region = 0;
  std::size_t count = 0;        // evaluated points
  double mean = 0, sigma = 0, min = 0, max = 0;  // [mm]
  std::size_t out_of_tolerance = 0;
};

// Everything stored for one part.
struct ComparisonRecord {
  std::string serial;            // the part's serial number (--serial)
  std::string part;              // the part file as the comparison names it
  std::string plan_fingerprint;  // SHA-256 of the plan file; empty without a plan
  std::string date;              // ISO 8601 UTC, when the comparison was made
  std::string operator_name, cmm;  // from the inspection record; empty when none
  std::string verdict;           // "PASS", "FAIL", "INCONCLUSIVE"
  std::string comparison_sha256; // of the comparison.json bytes: the record's identity
  double zone_lower = 0, zone_upper = 0;  // profile zone [mm]
  std::vector<StoredPoint> points;        // in the comparison's order
  std::vector<StoredRegion> regions;      // by increasing region id
  std::vector<StoredInput> inputs;        // the comparison first
};

// The record of comparison.json's `bytes` (read back as `name` in
// messages: parse_comparison). `inputs` are the source files' digests the
// caller found (the comparison itself is put first here); the plan's
// digest among them is the plan fingerprint. InputError for a serial that
// is empty, longer than 200 bytes or holds a control character.
struct RecordContext {
  std::string serial, date, operator_name, cmm;
  std::vector<StoredInput> inputs;  // without the comparison
};
ComparisonRecord make_comparison_record(const std::string& bytes, const std::string& name,
                                        const RecordContext& context);

// A time as ISO 8601 UTC ("2026-11-28T04:08:23Z"); std::time(nullptr) for now.
std::string utc_iso8601(std::time_t time);

// A stored part, as listed in storing order.
struct StoredPart {
  std::int64_t key = 0;  // storing order: increases with every part stored
  std::string serial, date, verdict, comparison_sha256, plan_fingerprint;
  double zone_lower = 0, zone_upper = 0;
  std::string operator_name, cmm;  // empty when the part had no inspection record
  // The Furrow version that stored the part; none for parts stored before
  // schema version 2, which did not record it.
  std::optional<std::string> furrow_version;
};

// One characteristic value of one stored part.
struct StoredValue {
  std::int64_t part_key = 0;
  std::string id;  // point id, or region id as decimal text
  double value = 0;
};

enum class SpcBy { point, region };
const char* to_string(SpcBy by);
SpcBy parse_spc_by(const std::string& text, const std::string& where);  // "point" or "region"

enum class StoreResult { stored, already_stored };

class ResultsDatabase {
 public:
  virtual ~ResultsDatabase() = default;
  // The location as the user gave it (a file path), for messages.
  virtual const std::string& location() const = 0;
  // See the contract above. InputError naming the location for a digest
  // stored under another serial.
  virtual StoreResult store(const ComparisonRecord& record) = 0;
  // Every stored part, in storing order.
  virtual std::vector<StoredPart> parts() = 0;
  // The values SPC follows, of every part: by point, the deviation of each
  // evaluated point with an id; by region, each region's mean deviation
  // over its evaluated points (regions with none are left out).
  virtual std::vector<StoredValue> values(SpcBy by) = 0;
  // Every point of one part, in the comparison's order (for checks and
  // exports); empty for an unknown key.
  virtual std::vector<StoredPoint> points_of(std::int64_t part_key) = 0;
  // The schema version of the database as it is now: 0 while a database
  // opened for write has not been created yet (nothing stored).
  virtual int schema_version() = 0;
};

// The schema version this program writes (docs/results_database.md
// "Schema versions"). It reads every version from 1 on.
constexpr int kResultsSchemaVersion = 2;

enum class DatabaseAccess { write, read };
// Opens the database at `location` and checks it, writing nothing.
// InputError naming it when it cannot be opened, is not Furrow's, is
// corrupt or is newer; for read, also when it does not exist or holds no
// Furrow results; for write, when a missing SQLite file could not be
// created in its folder. A database opened for write is created, or
// migrated to kResultsSchemaVersion, by the first store(): a command that
// fails before storing leaves no new file and no changed schema behind.
// Until then an absent database reads as empty.
std::unique_ptr<ResultsDatabase> open_results_database(const std::string& location, DatabaseAccess access);

// InputError for a location no message may print: a PostgreSQL connection
// string holding a password (docs/results_database.md "Passwords"). Callers
// that name the location before opening it check it first.
void check_results_location(const std::string& location);

// Serials FROM..TO, inclusive, in production order (below); an empty side
// is open ("..S-10", "S-05..").
struct SerialRange {
  std::optional<std::string> from, to;
};
// "FROM..TO", "FROM..", "..TO"; InputError naming `where` otherwise.
SerialRange parse_serial_range(const std::string& text, const std::string& where);

// What SPC reads (characteristic_series.hpp). One part per serial, ordered
// by the first time the serial was stored (production order), its values
// from the serial's latest record (a re-measurement replaces the earlier
// one); restricted to `range` (InputError naming the database when a bound
// is not a stored serial, or TO comes before FROM). Each characteristic's
// zone is the profile zone of the latest part that has it.
SpcInput load_spc_input(ResultsDatabase& db, SpcBy by, const SerialRange& range);

}  // namespace furrow
