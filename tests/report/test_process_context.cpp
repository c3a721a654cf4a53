// A part's place in its process (report/process_context.hpp) against an
// oracle computed from the records themselves: the region means the
// records carry, in storing order, with Cpk and the Nelson rules by the
// definitions (tests/results/spc_oracle.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "report/process_context.hpp"
#include "results/results_records.hpp"
#include "results/spc_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

constexpr std::size_t kStored = 30;

struct Batch {
  std::vector<ComparisonRecord> records;  // as stored, SN-1 .. SN-30
  std::unique_ptr<ResultsDatabase> db;
};

Batch stored_batch(const std::string& name) {
  Batch b;
  b.db = open_results_database(test::scratch_dir(name) + "/results.db", DatabaseAccess::write);
  for (std::size_t k = 0; k < kStored; ++k) {
    b.records.push_back(test::made_up_record("SN-" + std::to_string(k + 1), k + 1, 40, static_cast<std::uint32_t>(k)));
    b.db->store(b.records.back());
  }
  return b;
}

double region_mean(const ComparisonRecord& r, int region) {
  for (const StoredRegion& s : r.regions)
    if (s.region == region) return s.mean;
  FAIL("region " << region << " not in the record");
  return 0;
}

// The oracle's view of region `region` for parts `series` (this part last).
void check_region(const RegionProcess& got, const std::vector<const ComparisonRecord*>& series, int region) {
  CAPTURE(region);
  std::vector<double> x;
  for (const ComparisonRecord* r : series) x.push_back(region_mean(*r, region));
  REQUIRE(got.n == x.size());
  const std::size_t shown = std::min(x.size(), kProcessRecentParts);
  REQUIRE(got.recent.size() == shown);
  for (std::size_t k = 0; k < shown; ++k) {
    CHECK(got.recent[k] == x[x.size() - shown + k]);  // the same doubles, not recomputed
    CHECK(got.serials[k] == series[x.size() - shown + k]->serial);
  }
  CHECK(got.has_part);
  const auto [centre, sigma] = spc_oracle::centre_and_sigma(x);
  const double lower = series.back()->zone_lower, upper = series.back()->zone_upper;
  REQUIRE(got.cpk);
  // The Cpk of ~30 means of ~11 deviations each: relative 1e-9 is far above
  // the summation-order differences and far below any figure's meaning.
  const double cpk = std::min(upper - centre, centre - lower) / (3 * sigma);
  CHECK(std::abs(*got.cpk - cpk) <= 1e-9 * std::abs(cpk));
  std::vector<int> rules;
  for (const spc_oracle::Found& f : spc_oracle::nelson(x, centre, sigma))
    if (f.first <= x.size() - 1 && x.size() - 1 <= f.last) rules.push_back(f.rule);
  std::sort(rules.begin(), rules.end());
  rules.erase(std::unique(rules.begin(), rules.end()), rules.end());
  CHECK(got.rules_at_part == rules);
}

}  // namespace

TEST_CASE("process context: a stored part sees the parts up to it, with the region means it stored") {
  Batch b = stored_batch("process-stored");
  const ProcessContext p = process_context(*b.db, b.records[9]);  // SN-10
  CHECK(p.stored);
  CHECK(p.serial == "SN-10");
  CHECK(p.parts == 10);
  CHECK(p.position == 9);
  REQUIRE(p.regions.size() == 3);
  std::vector<const ComparisonRecord*> series;
  for (std::size_t k = 0; k < 10; ++k) series.push_back(&b.records[k]);
  for (int g = 1; g <= 3; ++g) {
    CHECK(p.regions[g - 1].region == std::to_string(g));
    check_region(p.regions[g - 1], series, g);
  }
}

TEST_CASE("process context: a part not stored yet comes after the stored ones, its last 25 values shown") {
  Batch b = stored_batch("process-appended");
  // A new part whose region 2 sits far above the process: rule 1 at it.
  ComparisonRecord next = test::made_up_record("SN-31", 31, 40, 31);
  for (StoredRegion& r : next.regions)
    if (r.region == 2) r.mean += 0.02;
  const ProcessContext p = process_context(*b.db, next);
  CHECK_FALSE(p.stored);
  CHECK(p.parts == kStored + 1);
  CHECK(p.position == kStored);
  std::vector<const ComparisonRecord*> series;
  for (const ComparisonRecord& r : b.records) series.push_back(&r);
  series.push_back(&next);
  REQUIRE(p.regions.size() == 3);
  for (int g = 1; g <= 3; ++g) check_region(p.regions[g - 1], series, g);
  CHECK(std::find(p.regions[1].rules_at_part.begin(), p.regions[1].rules_at_part.end(), 1) !=
        p.regions[1].rules_at_part.end());
}

TEST_CASE("process context: a serial measured again takes its place with the new values") {
  Batch b = stored_batch("process-remeasured");
  ComparisonRecord again = test::made_up_record("SN-5", 99, 40, 1234);  // another comparison of SN-5
  const ProcessContext p = process_context(*b.db, again);
  CHECK_FALSE(p.stored);
  CHECK(p.parts == kStored);
  CHECK(p.position == 4);
  std::vector<const ComparisonRecord*> series;
  for (std::size_t k = 0; k < 5; ++k) series.push_back(k == 4 ? &again : &b.records[k]);
  // Up to the part: SN-1 .. SN-4 and the new SN-5; the process's n and Cpk
  // are over all 30, which the oracle of the first case covers.
  for (const RegionProcess& r : p.regions) {
    CAPTURE(r.region);
    const int g = std::stoi(r.region);
    REQUIRE(r.recent.size() == 5);
    for (std::size_t k = 0; k < 5; ++k) CHECK(r.recent[k] == region_mean(*series[k], g));
    CHECK(r.has_part);
    CHECK(r.n == kStored);
  }
}
