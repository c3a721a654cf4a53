// The results database (results/results_database.hpp) on SQLite and, for
// every check that does not look at the file itself, on PostgreSQL too
// (results_backends.hpp): what is stored reads back unchanged, a comparison stored twice is recognised,
// values reach SQL only as bound parameters, the SPC selection follows
// production order with the latest record per serial, and a file that is
// not Furrow's, damaged or newer is refused before anything is written.
// The oracles are the records themselves (what went in) and the database's
// own client library reading it behind Furrow's back.
#include <doctest/doctest.h>
#include <sqlite3.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>

#include "base/error.hpp"
#include "inspection/comparison_file.hpp"
#include "results/results_database.hpp"
#include "results/sqlite_results_database.hpp"
#include "results/results_backends.hpp"
#include "results/results_records.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// A real comparison.json of the mould, made by the CLI once per process.
const std::string& mould_comparison_path() {
  static const std::string path = [] {
    const std::string dir = scratch_dir("results-db-comparison");
    const std::string part = source_path("examples/parts/mould.json");
    REQUIRE(run_furrow({"partition", part, "--out", dir + "/regions.json", "--grid", "40x40"}).status == 0);
    REQUIRE(run_furrow({"plan", part, "--regions", dir + "/regions.json", "--points", "30", "--out",
                        dir + "/plan"}).status == 0);
    REQUIRE(run_furrow({"simulate-measurement", part, "--plan", dir + "/plan/plan.json", "--out", dir + "/m.csv",
                        "--blunders", "1"}).status == 0);
    const CliResult c = run_furrow({"compare", part, "--measurements", dir + "/m.csv", "--plan",
                                    dir + "/plan/plan.json", "--out", dir + "/comparison.json"});
    REQUIRE(c.status != 2);
    return dir + "/comparison.json";
  }();
  return path;
}

std::string expect_input_error(const std::function<void()>& work) {
  try {
    work();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError");
  return "";
}

}  // namespace

TEST_CASE("results database: a real comparison stored and read back gives its deviations bit for bit") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-roundtrip");
    const std::string bytes = slurp(mould_comparison_path());
    const ComparisonDocument doc = parse_comparison(bytes, "comparison.json");
    RecordContext context;
    context.serial = "S-001";
    context.date = "2026-11-28T04:00:00Z";
    context.operator_name = "J. Doe";
    context.cmm = "Contura";
    context.inputs = {{"plan", "plan.json", std::string(64, 'c')}};
    const ComparisonRecord record = make_comparison_record(bytes, "comparison.json", context);
    CHECK(record.plan_fingerprint == std::string(64, 'c'));
    CHECK(record.inputs.front().role == "comparison");
    CHECK(record.comparison_sha256.size() == 64);
    REQUIRE(record.points.size() == doc.points.size());
    {
      auto db = open_results_database(db_path, DatabaseAccess::write);
      CHECK(db->store(record) == StoreResult::stored);
    }
    auto db = open_results_database(db_path, DatabaseAccess::read);
    const std::vector<StoredPart> parts = db->parts();
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].serial == "S-001");
    CHECK(parts[0].verdict == to_string(doc.summary.verdict));
    CHECK(bits(parts[0].zone_lower) == bits(doc.options.tolerance.lower()));
    CHECK(bits(parts[0].zone_upper) == bits(doc.options.tolerance.upper()));
    const std::vector<StoredPoint> back = db->points_of(parts[0].key);
    REQUIRE(back.size() == doc.points.size());
    std::size_t evaluated = 0, outliers = 0;
    for (std::size_t k = 0; k < back.size(); ++k) {
      CAPTURE(k);
      CHECK(back[k].id == doc.points[k].id);
      CHECK(back[k].region == doc.points[k].region);
      CHECK(back[k].evaluated == doc.points[k].evaluated);
      CHECK(back[k].outlier == doc.points[k].outlier);
      CHECK(back[k].in_tolerance == doc.points[k].in_tolerance);
      // A zero deviation reads back as a zero (SQLite keeps no sign of
      // zero, docs/results_database.md); every other one bit for bit.
      if (doc.points[k].deviation == 0)
        CHECK(back[k].deviation == 0);
      else
        CHECK(bits(back[k].deviation) == bits(doc.points[k].deviation));
      evaluated += doc.points[k].evaluated;
      outliers += !doc.points[k].outlier.empty();
    }
    CHECK(outliers >= 1);  // the blunder: stored, and not a value SPC reads
    // SPC by point: exactly the evaluated points with an id, bit for bit.
    const SpcInput spc = load_spc_input(*db, SpcBy::point, {});
    REQUIRE(spc.parts.size() == 1);
    CHECK(spc.parts[0].date == "2026-11-28T04:00:00Z");
    std::size_t values = 0;
    for (const CharacteristicSeries& c : spc.characteristics) {
      REQUIRE(c.values.size() == 1);
      const ComparisonDocument::Point& p = doc.points[doc.points_by_id.at(c.id)];
      CHECK(p.evaluated);
      CHECK(bits(c.values[0]) == bits(p.deviation));
      CHECK(c.kind == "point");
      values += c.values.size();
    }
    CHECK(values == evaluated);
    // By region: each region's mean, as the comparison wrote it.
    const SpcInput by_region = load_spc_input(*db, SpcBy::region, {});
    std::size_t regions_with_points = 0;
    for (const RegionStatistics& s : doc.summary.regions) {
      if (s.deviations.count == 0) continue;
      ++regions_with_points;
      const std::string id = std::to_string(s.region);
      bool found = false;
      for (const CharacteristicSeries& c : by_region.characteristics)
        if (c.id == id) {
          found = true;
          CHECK(bits(c.values.at(0)) == bits(s.deviations.mean));
        }
      CHECK(found);
    }
    CHECK(by_region.characteristics.size() == regions_with_points);
    CHECK(b.query(db_path, "SELECT operator || '/' || cmm FROM parts") == "J. Doe/Contura");
  });
}

TEST_CASE("results database: awkward doubles read back bit for bit") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-doubles");
    ComparisonRecord r = made_up_record("S-1", 1, 6, 7);
    const double awkward[] = {DBL_TRUE_MIN, DBL_MAX, 0.1 + 0.2, std::nextafter(1.0, 2.0), -DBL_MIN, 3.0};
    for (std::size_t k = 0; k < 6; ++k) r.points[k].deviation = awkward[k];
    auto db = open_results_database(db_path, DatabaseAccess::write);
    REQUIRE(db->store(r) == StoreResult::stored);
    const std::vector<StoredPoint> back = db->points_of(db->parts().at(0).key);
    REQUIRE(back.size() == 6);
    for (std::size_t k = 0; k < 6; ++k) CHECK(bits(back[k].deviation) == bits(awkward[k]));
  });
}

TEST_CASE("results database: the same comparison again is ignored, under another serial refused") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-twice");
    auto db = open_results_database(db_path, DatabaseAccess::write);
    const ComparisonRecord r = made_up_record("S-7", 42, 30, 1);
    CHECK(db->store(r) == StoreResult::stored);
    CHECK(db->store(r) == StoreResult::already_stored);
    ComparisonRecord other = r;
    other.serial = "S-8";
    const std::string message = expect_input_error([&] { db->store(other); });
    CHECK(message.find(db_path) != std::string::npos);
    CHECK(message.find("\"S-7\"") != std::string::npos);
    CHECK(db->parts().size() == 1);
    CHECK(b.query(db_path, "SELECT count(*) FROM points") == "30");
    // Append-only in the file itself: another client's UPDATE is refused.
    CHECK(!b.exec(db_path, "UPDATE parts SET serial = 'X'"));
    CHECK(!b.exec(db_path, "DELETE FROM points"));
    CHECK(b.query(db_path, "SELECT serial FROM parts") == "S-7");
  });
}

TEST_CASE("results database: serials and ids like SQL reach the file as values") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-injection");
    const std::string evil = "'; DROP TABLE parts; --";
    ComparisonRecord r = made_up_record(evil, 3, 5, 2);
    r.points[0].id = "x'); DELETE FROM points; --";
    r.points[1].id = "\"; DROP TABLE points; /*";
    r.operator_name = "O'Brien";
    r.cmm = "Robert'); DROP TABLE parts;--";
    r.part = "part'.json";
    {
      auto db = open_results_database(db_path, DatabaseAccess::write);
      REQUIRE(db->store(r) == StoreResult::stored);
      REQUIRE(db->store(made_up_record("plain", 4, 5, 3)) == StoreResult::stored);
    }
    CHECK(b.query(db_path, "SELECT count(*) FROM parts") == "2");
    CHECK(b.query(db_path, "SELECT count(*) FROM points") == "10");
    CHECK(b.query(db_path, "SELECT serial FROM parts ORDER BY part_key LIMIT 1") == evil);
    CHECK(b.query(db_path, "SELECT cmm FROM parts ORDER BY part_key LIMIT 1") == r.cmm);
    auto db = open_results_database(db_path, DatabaseAccess::read);
    const std::vector<StoredPoint> back = db->points_of(db->parts().at(0).key);
    REQUIRE(back.size() == 5);
    CHECK(back[0].id == r.points[0].id);
    CHECK(back[1].id == r.points[1].id);
    const SpcInput spc = load_spc_input(*db, SpcBy::point, parse_serial_range(evil + "..plain", "--serials"));
    REQUIRE(spc.parts.size() == 2);
    CHECK(spc.parts[0].serial == evil);
  });
}

TEST_CASE("results database: SPC reads one part per serial in production order, the latest record of each") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-spc-order");
    // Stored: S1, S2, S3, S2 again (a re-measurement), S4.
    const std::vector<ComparisonRecord> stored = {made_up_record("S1", 1, 14, 11), made_up_record("S2", 2, 14, 12),
                                                  made_up_record("S3", 3, 14, 13), made_up_record("S2", 4, 14, 14),
                                                  made_up_record("S4", 5, 14, 15)};
    auto db = open_results_database(db_path, DatabaseAccess::write);
    for (const ComparisonRecord& r : stored) REQUIRE(db->store(r) == StoreResult::stored);
    // The oracle: production order S1 S2 S3 S4, S2's values from record 3.
    const std::vector<std::size_t> expected_records = {0, 3, 2, 4};
    const SpcInput spc = load_spc_input(*db, SpcBy::point, {});
    REQUIRE(spc.parts.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) CHECK(spc.parts[i].serial == stored[expected_records[i]].serial);
    std::size_t evaluated_ids = 0;
    for (const StoredPoint& p : stored[0].points) evaluated_ids += p.evaluated;
    REQUIRE(spc.characteristics.size() == evaluated_ids);
    for (std::size_t c = 1; c < spc.characteristics.size(); ++c)
      CHECK(spc.characteristics[c - 1].id < spc.characteristics[c].id);
    for (const CharacteristicSeries& c : spc.characteristics) {
      CAPTURE(c.id);
      REQUIRE(c.part_index.size() == 4);
      const std::size_t k = std::stoul(c.id.substr(1));
      for (std::size_t i = 0; i < 4; ++i) {
        CHECK(c.part_index[i] == i);
        CHECK(bits(c.values[i]) == bits(stored[expected_records[i]].points[k].deviation));
      }
      CHECK(c.lower == -0.025);
      CHECK(c.upper == 0.025);
    }
    // By region: the region means, ids as text.
    const SpcInput regions = load_spc_input(*db, SpcBy::region, {});
    REQUIRE(regions.characteristics.size() == 3);
    for (const CharacteristicSeries& c : regions.characteristics) {
      CHECK(c.kind == "region");
      const int g = std::stoi(c.id);
      for (std::size_t i = 0; i < 4; ++i)
        CHECK(bits(c.values.at(i)) == bits(stored[expected_records[i]].regions.at(g - 1).mean));
    }
    // A range, inclusive, in production order.
    const SpcInput middle = load_spc_input(*db, SpcBy::point, parse_serial_range("S2..S3", "--serials"));
    REQUIRE(middle.parts.size() == 2);
    CHECK(middle.parts[0].serial == "S2");
    CHECK(middle.parts[1].serial == "S3");
    CHECK(middle.characteristics.at(0).part_index == std::vector<std::size_t>{0, 1});
    CHECK(load_spc_input(*db, SpcBy::point, parse_serial_range("S3..", "--serials")).parts.size() == 2);
    CHECK(load_spc_input(*db, SpcBy::point, parse_serial_range("..S1", "--serials")).parts.size() == 1);
    CHECK(expect_input_error([&] { load_spc_input(*db, SpcBy::point, parse_serial_range("S9..", "s")); })
              .find("\"S9\"") != std::string::npos);
    CHECK(expect_input_error([&] { load_spc_input(*db, SpcBy::point, parse_serial_range("S3..S1", "s")); })
              .find(db_path) != std::string::npos);
    CHECK(expect_input_error([&] { parse_serial_range("S1-S3", "--serials"); }).find("--serials") !=
          std::string::npos);
  });
}

TEST_CASE("results database: an empty database gives an empty selection, and a one-sided range its part on") {
  on_each_backend([](const ResultsBackend& b) {
    auto db = open_results_database(b.fresh("results-db-empty"), DatabaseAccess::write);
    for (SpcBy by : {SpcBy::point, SpcBy::region}) {
      const SpcInput none = load_spc_input(*db, by, {});
      CHECK(none.parts.empty());
      CHECK(none.characteristics.empty());
    }
    REQUIRE(db->store(made_up_record("S1", 1, 7, 1)) == StoreResult::stored);
    REQUIRE(db->store(made_up_record("S2", 2, 7, 2)) == StoreResult::stored);
    CHECK(load_spc_input(*db, SpcBy::point, {std::string("S2"), std::nullopt}).parts.size() == 1);
    CHECK(load_spc_input(*db, SpcBy::point, {std::nullopt, std::string("S1")}).parts.size() == 1);
    CHECK(load_spc_input(*db, SpcBy::point, {std::string("S2"), std::string("S2")}).parts.size() == 1);
    CHECK_THROWS_AS(load_spc_input(*db, SpcBy::point, {std::string("S2"), std::string("S1")}), InputError);
  });
}

TEST_CASE("results database: a point measured in some parts only has entries for those parts") {
  on_each_backend([](const ResultsBackend& b) {
    const std::string db_path = b.fresh("results-db-gaps");
    auto db = open_results_database(db_path, DatabaseAccess::write);
    // P6 is an outlier in every made-up record (k % 7 == 6); make P0 one in the second part.
    ComparisonRecord second = made_up_record("B", 2, 10, 2);
    second.points[0].evaluated = false;
    second.points[0].outlier = "blunder";
    REQUIRE(db->store(made_up_record("A", 1, 10, 1)) == StoreResult::stored);
    REQUIRE(db->store(second) == StoreResult::stored);
    REQUIRE(db->store(made_up_record("C", 3, 10, 3)) == StoreResult::stored);
    const SpcInput spc = load_spc_input(*db, SpcBy::point, {});
    std::map<std::string, std::vector<std::size_t>> indices;
    for (const CharacteristicSeries& c : spc.characteristics) indices[c.id] = c.part_index;
    CHECK(indices.at("P0") == std::vector<std::size_t>{0, 2});
    CHECK(indices.at("P1") == std::vector<std::size_t>{0, 1, 2});
    CHECK(indices.count("P6") == 0);
  });
}

TEST_CASE("results database: a file that is not Furrow's, damaged or newer is refused, nothing written") {
  const std::string dir = scratch_dir("results-db-refused");
  const auto refused_unchanged = [&](const std::string& path, const std::string& says) {
    const std::string before = slurp(path);
    const std::string message =
        expect_input_error([&] { open_results_database(path, DatabaseAccess::write)->store(made_up_record("S", 1, 3, 1)); });
    CHECK(message.find(path) != std::string::npos);
    CHECK(message.find(says) != std::string::npos);
    CHECK(slurp(path) == before);
    CHECK(!fs::exists(path + "-wal"));
  };
  SUBCASE("a text file") {
    write_text(dir + "/notes.db", "these are my notes, not a database\n" + std::string(600, 'x'));
    refused_unchanged(dir + "/notes.db", "not a Furrow results database");
  }
  SUBCASE("another program's SQLite database") {
    REQUIRE(sqlite_exec(dir + "/other.db", "CREATE TABLE parts (serial TEXT); INSERT INTO parts VALUES ('x');") ==
            SQLITE_OK);
    refused_unchanged(dir + "/other.db", "not Furrow's");
  }
  SUBCASE("a newer schema version") {
    { open_results_database(dir + "/newer.db", DatabaseAccess::write)->store(made_up_record("S0", 9, 3, 1)); }
    REQUIRE(sqlite_exec(dir + "/newer.db", "PRAGMA user_version = " + std::to_string(kResultsSchemaVersion + 1)) ==
            SQLITE_OK);
    refused_unchanged(dir + "/newer.db", "newer");
    CHECK(expect_input_error([&] { open_results_database(dir + "/newer.db", DatabaseAccess::read); })
              .find("newer") != std::string::npos);
  }
  SUBCASE("a damaged file") {
    { open_results_database(dir + "/damaged.db", DatabaseAccess::write)->store(made_up_record("S0", 9, 300, 1)); }
    std::string bytes = slurp(dir + "/damaged.db");
    REQUIRE(bytes.size() > 4096);
    for (std::size_t k = 100; k < 4096; ++k) bytes[k] = static_cast<char>(0xA5);  // page 1's b-tree
    write_text(dir + "/damaged.db", bytes);
    refused_unchanged(dir + "/damaged.db", "damaged");
  }
  SUBCASE("a folder, and a database that is not there for reading") {
    fs::create_directories(dir + "/folder.db");
    CHECK(expect_input_error([&] { open_results_database(dir + "/folder.db", DatabaseAccess::write); })
              .find(dir + "/folder.db") != std::string::npos);
    CHECK(expect_input_error([&] { open_results_database(dir + "/none.db", DatabaseAccess::read); })
              .find(dir + "/none.db") != std::string::npos);
    CHECK(!fs::exists(dir + "/none.db"));
  }
}

TEST_CASE("results database: a new file is made by the first store, marked as Furrow's, schema version 2, in WAL mode") {
  const std::string dir = scratch_dir("results-db-new");
  const std::string db_path = dir + "/results.db";
  // Opening for writing creates nothing: a command that fails before storing leaves no file.
  { CHECK(open_results_database(db_path, DatabaseAccess::write)->schema_version() == 0); }
  CHECK(!fs::exists(db_path));
  {
    const std::unique_ptr<ResultsDatabase> db = open_results_database(db_path, DatabaseAccess::write);
    CHECK(db->parts().empty());
    CHECK(db->values(SpcBy::point).empty());
    CHECK(!fs::exists(db_path));
    CHECK(db->store(made_up_record("S1", 1, 4, 1)) == StoreResult::stored);
    CHECK(db->schema_version() == 2);
  }
  CHECK(sqlite_query(db_path, "PRAGMA application_id") == std::to_string(kSqliteApplicationId));
  CHECK(sqlite_query(db_path, "PRAGMA user_version") == "2");
  CHECK(sqlite_query(db_path, "PRAGMA journal_mode") == "wal");
  CHECK(sqlite_query(db_path, "SELECT value FROM meta WHERE key = 'schema_version'") == "2");
  CHECK(sqlite_query(db_path, "SELECT value FROM meta WHERE key = 'application'") == "furrow results");
  CHECK(sqlite_query(db_path, "SELECT furrow_version FROM parts") == FURROW_VERSION);
  // Opening it again neither fails nor changes the schema.
  const std::string schema = sqlite_query(db_path, "SELECT group_concat(sql, ';') FROM sqlite_master");
  { open_results_database(db_path, DatabaseAccess::write)->store(made_up_record("S1", 1, 4, 1)); }
  CHECK(sqlite_query(db_path, "SELECT group_concat(sql, ';') FROM sqlite_master") == schema);
  // A new file in a folder that is not there: refused when opened, before any work.
  const std::string message =
      expect_input_error([&] { open_results_database(dir + "/no-such-folder/results.db", DatabaseAccess::write); });
  CHECK(message.find(dir + "/no-such-folder/results.db") != std::string::npos);
  CHECK(message.find("no folder") != std::string::npos);
}
