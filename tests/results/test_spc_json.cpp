#include <doctest/doctest.h>

#include <filesystem>
#include <iterator>
#include <set>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "results/spc_json.hpp"
#include "results/spc_outputs.hpp"
#include "results/spc_summary.hpp"
#include "results/spc_statistics.hpp"
#include "spc_batch.hpp"
#include "spc_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using nlohmann::json;
using furrow::test::scratch_dir;
using furrow::test::slurp;

namespace {

void check_number(const json& j, const std::optional<double>& v) {
  if (v) {
    REQUIRE(j.is_number());
    CHECK(j.get<double>() == *v);  // shortest round-trip text reads back exactly
  } else {
    CHECK(j.is_null());
  }
}

}  // namespace

TEST_CASE("spc.json holds every figure of the computation and reads back exactly") {
  const SpcResult r = compute_spc(spc_batch());
  const SpcSelection selection{"results.sqlite", {{"part-number", "M-100-A"}, {"last", "30"}}};
  const std::string text = spc_json(r, selection);
  const json doc = json::parse(text);
  CHECK(doc["format"] == "furrow-spc");
  CHECK(doc["version"] == 1);
  CHECK(doc["units"] == "mm");
  CHECK(doc["selection"]["source"] == "results.sqlite");
  CHECK(doc["selection"]["criteria"]["last"] == "30");
  REQUIRE(doc["parts"].size() == 30);
  CHECK(doc["parts"][29]["serial"] == "SN129");
  CHECK(doc["parts"][29]["verdict"] == "FAIL");
  CHECK(doc["parts"][29]["index"] == 29);
  CHECK(doc["parts"][3]["date"] == "2026-11-13T08:00:00Z");
  REQUIRE(doc["characteristics"].size() == 3);
  std::size_t violations = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const CharacteristicSpc& c = r.characteristics[i];
    const json& j = doc["characteristics"][i];
    CAPTURE(c.id);
    CHECK(j["id"] == c.id);
    CHECK(j["kind"] == c.kind);
    CHECK(j["n"] == c.n);
    CHECK(j["lower"].get<double>() == c.lower);
    CHECK(j["upper"].get<double>() == c.upper);
    CHECK(j["part_index"].get<std::vector<std::size_t>>() == c.part_index);
    CHECK(j["values"].get<std::vector<double>>() == c.values);
    check_number(j["mean"], c.mean);
    check_number(j["sigma_within"], c.sigma_within);
    check_number(j["sigma_overall"], c.sigma_overall);
    check_number(j["mr_mean"], c.mr_mean);
    check_number(j["mr_ucl"], c.mr_ucl);
    check_number(j["lcl"], c.lcl);
    check_number(j["ucl"], c.ucl);
    check_number(j["cp"], c.cp);
    check_number(j["cpk"], c.cpk);
    check_number(j["pp"], c.pp);
    check_number(j["ppk"], c.ppk);
    if (c.slope) {
      check_number(j["slope"]["value"], c.slope->value);
      check_number(j["slope"]["low"], c.slope->low);
      check_number(j["slope"]["high"], c.slope->high);
    } else {
      CHECK(j["slope"].is_null());
    }
    REQUIRE(j["violations"].size() == c.violations.size());
    for (std::size_t k = 0; k < c.violations.size(); ++k) {
      CHECK(j["violations"][k]["rule"] == c.violations[k].rule);
      CHECK(j["violations"][k]["index"] == c.violations[k].index);
      CHECK(j["violations"][k]["last"] == c.violations[k].last);
      CHECK(j["violations"][k]["serial"] == c.violations[k].serial);
    }
    CHECK(j["notes"].get<std::vector<std::string>>() == c.notes);
    violations += c.violations.size();
  }
  // The figures themselves, independently: the region's mean over the 29
  // values it has, and its one note-free capability.
  const json& region = doc["characteristics"][2];
  CHECK(region["id"] == "R1");
  CHECK(region["n"] == 29);
  CHECK(region["part_index"][12] == 13);
  const auto [centre, sigma] = spc_oracle::centre_and_sigma(region["values"].get<std::vector<double>>());
  CHECK(std::abs(region["mean"].get<double>() - centre) < 1e-15);
  CHECK(std::abs(region["cpk"].get<double>() - std::min(0.04 - centre, centre + 0.03) / (3 * sigma)) < 1e-12);
  // The point measured once: mean only, the rest null, and why.
  const json& once = doc["characteristics"][0];
  CHECK(once["id"] == "P0001");
  CHECK(once["mean"] == 0.01);
  CHECK(once["cpk"].is_null());
  CHECK(once["slope"].is_null());
  CHECK(once["notes"].size() == 2);
  // The drifting point raises violations, the summary counts them.
  CHECK(violations > 0);
  CHECK(doc["summary"]["violations"] == violations);
  CHECK(doc["summary"]["parts"] == 30);
  CHECK(doc["summary"]["violation_in_latest_part"] == violation_in_latest_part(r));
  CHECK(doc["summary"]["worst_first"][0] == "P0002");  // lowest cpk: its mean has drifted near the upper limit
  CHECK(doc["constants"]["d2"] == 1.128);
  CHECK(doc["constants"]["D4"] == 3.267);
}

TEST_CASE("spc.json is the same bytes whatever order the characteristics came in") {
  SpcInput in = spc_batch();
  const SpcSelection selection{"results.sqlite", {}};
  const std::string first = spc_json(compute_spc(in), selection);
  std::swap(in.characteristics[0], in.characteristics[2]);
  CHECK(spc_json(compute_spc(in), selection) == first);
  CHECK(first.find("NaN") == std::string::npos);
  CHECK(first.find("inf") == std::string::npos);
  CHECK(first.back() == '\n');
}

TEST_CASE("write_spc_outputs publishes the folder whole") {
  const std::string dir = scratch_dir("spc-outputs");
  const std::string out = dir + "/spc";
  const SpcResult r = compute_spc(spc_batch());
  const SpcSelection selection{"results.sqlite", {}};
  write_spc_outputs(r, selection, out);
  const std::vector<SpcOutputFile> files = render_spc(r, selection);
  REQUIRE_FALSE(files.empty());
  CHECK(files.back().name == "spc.json");
  for (const SpcOutputFile& f : files) CHECK(slurp(out + "/" + f.name) == f.bytes);
  // Nothing else in the folder and no temporary left beside it.
  std::size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(out)) entries += e.is_regular_file();
  CHECK(entries == files.size());
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("the summary names the worst characteristics and what the latest part violates") {
  const SpcResult r = compute_spc(spc_batch());
  const std::string text = spc_summary(r, 2);
  CHECK(text.rfind("spc: 30 parts (SN100 .. SN129), 3 characteristics, ", 0) == 0);
  // Two characteristics listed, worst first.
  CHECK(text.find("\n  P0002  n 30  cpk ") != std::string::npos);
  CHECK(text.find("\n  region R1  n 29  cpk ") != std::string::npos);
  CHECK(text.find("P0001  n") == std::string::npos);
  CHECK(text.find("P0002") < text.find("R1"));
  // The latest part: every violation that reaches it, by rule.
  // The latest part: every violation that reaches it; here the drifting
  // point's, whose rules the test collects from the violations themselves.
  const auto latest = latest_part_violations(r);
  REQUIRE_FALSE(latest.empty());
  std::set<int> rules;
  for (const auto& [k, v] : latest) {
    const CharacteristicSpc& c = r.characteristics[k];
    CHECK(c.id == "P0002");
    CHECK(c.violations[v].last + 1 == c.n);
    rules.insert(c.violations[v].rule);
  }
  std::string expected = "latest part SN129: P0002 rules ";
  for (int rule : rules) expected += std::to_string(rule) + (rule == *rules.rbegin() ? "" : ", ");
  CHECK(text.find(expected + "\n") != std::string::npos);
  SpcInput calm = spc_batch();
  calm.characteristics.erase(calm.characteristics.begin() + 1);  // without the drifting point
  CHECK(spc_summary(compute_spc(calm)).find("latest part SN129: no Nelson rule violated\n") != std::string::npos);
}
