#include "report/process_context.hpp"

#include <algorithm>
#include <set>

#include "results/spc_statistics.hpp"

namespace furrow {

namespace {

// This part's region means put into the stored process at position `k`
// (the end, or the place of its serial's first record): what load_spc_input
// will read once the part is stored.
void put_part(SpcInput& input, const ComparisonRecord& part, std::size_t k) {
  const bool latest = k + 1 == input.parts.size();
  for (CharacteristicSeries& c : input.characteristics)
    for (std::size_t j = c.part_index.size(); j-- > 0;)
      if (c.part_index[j] == k) {
        c.part_index.erase(c.part_index.begin() + static_cast<std::ptrdiff_t>(j));
        c.values.erase(c.values.begin() + static_cast<std::ptrdiff_t>(j));
      }
  for (const StoredRegion& r : part.regions) {
    if (r.count == 0) continue;  // no evaluated point: no value, as the database reads it
    const std::string id = std::to_string(r.region);
    auto c = std::find_if(input.characteristics.begin(), input.characteristics.end(),
                          [&](const CharacteristicSeries& s) { return s.id == id; });
    if (c == input.characteristics.end()) {
      input.characteristics.push_back({id, "region", part.zone_lower, part.zone_upper, {}, {}});
      c = input.characteristics.end() - 1;
    }
    const auto at = std::lower_bound(c->part_index.begin(), c->part_index.end(), k) - c->part_index.begin();
    c->part_index.insert(c->part_index.begin() + at, k);
    c->values.insert(c->values.begin() + at, r.mean);
    if (latest) c->lower = part.zone_lower, c->upper = part.zone_upper;  // the latest part's zone
  }
  std::sort(input.characteristics.begin(), input.characteristics.end(),
            [](const CharacteristicSeries& a, const CharacteristicSeries& b) { return a.id < b.id; });
}

}  // namespace

ProcessContext process_context(ResultsDatabase& db, const ComparisonRecord& part) {
  ProcessContext pc;
  pc.source = db.location();
  pc.serial = part.serial;
  for (const StoredPart& p : db.parts())
    if (p.comparison_sha256 == part.comparison_sha256) {
      pc.stored = true;
      pc.serial = p.serial;  // the serial it is stored under
    }
  SpcInput input;
  if (pc.stored) {
    input = load_spc_input(db, SpcBy::region, {std::nullopt, pc.serial});
    pc.position = input.parts.size() - 1;
  } else {
    input = load_spc_input(db, SpcBy::region, {});
    const auto same = std::find_if(input.parts.begin(), input.parts.end(),
                                   [&](const PartRecord& p) { return p.serial == part.serial; });
    // Not stored: no Furrow version is on record for it.
    const PartRecord record{part.serial, part.date, part.verdict, part.operator_name, part.cmm, std::nullopt};
    if (same == input.parts.end()) {
      input.parts.push_back(record);
      pc.position = input.parts.size() - 1;
    } else {
      *same = record;
      pc.position = static_cast<std::size_t>(same - input.parts.begin());
    }
    put_part(input, part, pc.position);
  }
  pc.parts = input.parts.size();

  const SpcResult result = compute_spc(input);
  for (const CharacteristicSpc& c : result.characteristics) {
    RegionProcess r;
    r.region = c.id;
    r.lower = c.lower;
    r.upper = c.upper;
    r.n = c.n;
    r.mean = c.mean;
    r.cpk = c.cpk;
    // The values up to this part; the last kProcessRecentParts of them.
    const std::size_t end = static_cast<std::size_t>(
        std::upper_bound(c.part_index.begin(), c.part_index.end(), pc.position) - c.part_index.begin());
    const std::size_t begin = end > kProcessRecentParts ? end - kProcessRecentParts : 0;
    for (std::size_t j = begin; j < end; ++j) {
      r.recent.push_back(c.values[j]);
      r.serials.push_back(result.parts[c.part_index[j]].serial);
    }
    r.has_part = end > 0 && c.part_index[end - 1] == pc.position;
    std::set<int> rules;
    if (r.has_part)
      for (const SpcViolation& v : c.violations)
        if (v.index <= end - 1 && end - 1 <= v.last) rules.insert(v.rule);
    r.rules_at_part.assign(rules.begin(), rules.end());
    pc.regions.push_back(std::move(r));
  }
  std::sort(pc.regions.begin(), pc.regions.end(), [](const RegionProcess& a, const RegionProcess& b) {
    return a.region.size() != b.region.size() ? a.region.size() < b.region.size() : a.region < b.region;
  });
  return pc;
}

}  // namespace furrow
