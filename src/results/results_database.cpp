#include "results/results_database.hpp"

#include <algorithm>
#include <ctime>
#include <map>

#include "base/error.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/scan_comparison_document.hpp"
#include "io/qif/qif_uuid.hpp"
#include "results/postgres_results_database.hpp"
#include "results/sqlite_results_database.hpp"

namespace furrow {

namespace {

constexpr std::size_t kMaxSerialBytes = 200;

void check_serial(const std::string& serial) {
  if (serial.empty()) throw InputError("--serial: the part's serial number is empty");
  if (serial.size() > kMaxSerialBytes)
    throw InputError("--serial: longer than " + std::to_string(kMaxSerialBytes) + " bytes");
  for (const char c : serial)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw InputError("--serial \"" + serial + "\": holds a control character");
}

}  // namespace

ComparisonRecord make_comparison_record(const std::string& bytes, const std::string& name,
                                        const RecordContext& context) {
  check_serial(context.serial);
  ComparisonRecord r;
  r.serial = context.serial;
  r.date = context.date;
  r.operator_name = context.operator_name;
  r.cmm = context.cmm;
  // The same digest the QA report and QIF give the comparison (io/qif sits
  // below results, report above).
  r.comparison_sha256 = qif_sha256_hex(bytes);
  const auto take_regions = [&r](const std::vector<RegionStatistics>& regions) {
    for (const RegionStatistics& s : regions)
      r.regions.push_back({s.region, s.deviations.count, s.deviations.mean, s.deviations.sigma, s.deviations.min,
                           s.deviations.max, s.out_of_tolerance});
  };
  if (is_scan_comparison_text(bytes)) {
    // A scan has no planned points: its record is its regions
    // (docs/results_database.md "Scans").
    const ScanComparisonDocument doc = parse_scan_comparison(bytes, name);
    r.part = doc.sources.part;
    r.verdict = to_string(doc.summary.verdict);
    r.zone_lower = doc.tolerance.lower();
    r.zone_upper = doc.tolerance.upper();
    take_regions(doc.summary.regions);
  } else {
    const ComparisonDocument doc = parse_comparison(bytes, name);
    r.part = doc.sources.part;
    r.verdict = to_string(doc.summary.verdict);
    r.zone_lower = doc.options.tolerance.lower();
    r.zone_upper = doc.options.tolerance.upper();
    r.points.reserve(doc.points.size());
    for (const ComparisonDocument::Point& p : doc.points)
      r.points.push_back({p.id, p.region, p.deviation, p.evaluated, p.in_tolerance, p.outlier});
    take_regions(doc.summary.regions);
  }
  r.inputs.push_back({"comparison", name, r.comparison_sha256});
  for (const StoredInput& in : context.inputs) {
    r.inputs.push_back(in);
    if (in.role == "plan") r.plan_fingerprint = in.sha256;
  }
  return r;
}

std::string utc_iso8601(std::time_t time) {
  std::tm utc{};
  gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

const char* to_string(SpcBy by) { return by == SpcBy::point ? "point" : "region"; }

SpcBy parse_spc_by(const std::string& text, const std::string& where) {
  if (text == "point") return SpcBy::point;
  if (text == "region") return SpcBy::region;
  throw InputError(where + ": \"" + text + "\" is neither point nor region");
}

std::unique_ptr<ResultsDatabase> open_results_database(const std::string& location, DatabaseAccess access) {
  if (location.empty()) throw InputError("--db: the results database's location is empty");
  if (is_postgres_location(location)) return open_postgres_results_database(location, access);
  return open_sqlite_results_database(location, access);
}

void check_results_location(const std::string& location) {
  if (is_postgres_location(location)) check_postgres_location(location);
}

SerialRange parse_serial_range(const std::string& text, const std::string& where) {
  const std::size_t dots = text.find("..");
  if (dots == std::string::npos || text.find("..", dots + 2) != std::string::npos || text == "..")
    throw InputError(where + ": \"" + text + "\" is not FROM..TO, FROM.. or ..TO");
  SerialRange range;
  if (dots > 0) range.from = text.substr(0, dots);
  if (dots + 2 < text.size()) range.to = text.substr(dots + 2);
  return range;
}

SpcInput load_spc_input(ResultsDatabase& db, SpcBy by, const SerialRange& range) {
  const std::vector<StoredPart> parts = db.parts();
  // Production order: each serial where it was first stored; its latest record.
  std::vector<std::string> serials;
  std::map<std::string, std::size_t> latest;  // serial -> index into parts
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (!latest.count(parts[k].serial)) serials.push_back(parts[k].serial);
    latest[parts[k].serial] = k;
  }
  auto position = [&](const std::string& serial, const char* side) {
    const auto it = std::find(serials.begin(), serials.end(), serial);
    if (it == serials.end())
      throw InputError(db.location() + ": no part with serial \"" + serial + "\" (the range's " + side + ")");
    return static_cast<std::size_t>(it - serials.begin());
  };
  const std::size_t first = range.from ? position(*range.from, "FROM") : 0;
  const std::size_t end = range.to ? position(*range.to, "TO") + 1 : serials.size();
  if (range.from && range.to && end <= first)  // one side alone cannot be empty: its serial is in it
    throw InputError(db.location() + ": serial \"" + *range.to + "\" was stored before \"" + *range.from +
                     "\" (FROM..TO follows the order the parts were stored)");

  SpcInput input;
  std::map<std::int64_t, std::size_t> index_of_key;  // a selected record's key -> part index
  for (std::size_t s = first; s < end; ++s) {
    const StoredPart& p = parts[latest.at(serials[s])];
    index_of_key[p.key] = input.parts.size();
    input.parts.push_back({p.serial, p.date, p.verdict, p.operator_name, p.cmm, p.furrow_version});
  }
  std::map<std::string, CharacteristicSeries> series;
  for (const StoredValue& v : db.values(by)) {
    const auto it = index_of_key.find(v.part_key);
    if (it == index_of_key.end()) continue;
    CharacteristicSeries& c = series[v.id];
    // A part that named one point twice: its first value counts.
    if (!c.part_index.empty() && c.part_index.back() == it->second) continue;
    c.part_index.push_back(it->second);
    c.values.push_back(v.value);
  }
  std::map<std::int64_t, const StoredPart*> by_key;
  for (const StoredPart& p : parts) by_key[p.key] = &p;
  std::vector<std::int64_t> key_of_index(input.parts.size());
  for (const auto& [key, index] : index_of_key) key_of_index[index] = key;
  for (auto& entry : series) {
    // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
    const std::string& id = entry.first;
    CharacteristicSeries& c = entry.second;
    // values() lists parts in storing order; the selection is in production
    // order, which differs after a re-measurement.
    std::vector<std::size_t> order(c.part_index.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return c.part_index[a] < c.part_index[b];
    });
    CharacteristicSeries sorted;
    sorted.id = id;
    sorted.kind = to_string(by);
    for (const std::size_t k : order) {
      sorted.part_index.push_back(c.part_index[k]);
      sorted.values.push_back(c.values[k]);
    }
    const StoredPart& zone_part = *by_key.at(key_of_index[sorted.part_index.back()]);
    sorted.lower = zone_part.zone_lower;
    sorted.upper = zone_part.zone_upper;
    input.characteristics.push_back(std::move(sorted));
  }
  return input;
}

}  // namespace furrow
