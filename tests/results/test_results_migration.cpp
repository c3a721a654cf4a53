// Migration of the results database from schema version 1
// (docs/results_database.md "Versions and migrations"), on both back ends.
// The version-1 databases are not made here: they were written by Furrow
// 0.1.0 before version 2 existed (tests/results/schema_v1/, made by its
// make_fixtures.sh): the SQLite file itself and pg_dump's script of the
// PostgreSQL database. The oracle is the database's own client reading the
// untouched version-1 tables; what this furrow reads back, after reading
// as it is or after migrating, must be those rows exactly.
#include <doctest/doctest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "results/results_backends.hpp"
#include "results/results_database.hpp"
#include "results/results_records.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

bool is_sqlite(const ResultsBackend& backend) { return backend.name == "SQLite"; }

// A version-1 database of the back end: a copy of the SQLite file, or a new
// PostgreSQL database that psql loads pg_dump's script into.
std::string version1_database(const ResultsBackend& backend, const std::string& hint) {
  const std::string location = backend.fresh(hint);
  if (is_sqlite(backend))
    fs::copy_file(source_path("tests/results/schema_v1/results.sqlite"), location);
  else
    postgres_cluster().psql_file(PostgresCluster::database_of(location),
                                 source_path("tests/results/schema_v1/results.pg.sql"));
  return location;
}

// The rows of a table by the back end's own client, each as its fields'
// text: NULL as "~", reals as text that reads back to the same double
// (SQLite: sqlite3_column_double printed with 17 digits; PostgreSQL: its
// shortest exact form, joined by string_agg).
std::vector<std::vector<std::string>> raw_rows(const ResultsBackend& backend, const std::string& location,
                                               const std::vector<std::string>& columns, const std::string& table,
                                               const std::string& order, const std::vector<bool>& real) {
  std::vector<std::vector<std::string>> rows;
  if (is_sqlite(backend)) {
    std::string sql = "SELECT ";
    for (std::size_t k = 0; k < columns.size(); ++k) sql += (k ? ", " : "") + columns[k];
    sql += " FROM " + table + " ORDER BY " + order;
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(location.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
    while (sqlite3_step(s) == SQLITE_ROW) {
      std::vector<std::string> fields;
      for (int k = 0; k < static_cast<int>(columns.size()); ++k) {
        char text[40];
        if (sqlite3_column_type(s, k) == SQLITE_NULL) {
          fields.emplace_back("~");
        } else if (real[static_cast<std::size_t>(k)]) {
          std::snprintf(text, sizeof text, "%.17g", sqlite3_column_double(s, k));
          fields.emplace_back(text);
        } else {
          fields.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, k)));
        }
      }
      rows.push_back(fields);
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    return rows;
  }
  std::string line;
  for (std::size_t k = 0; k < columns.size(); ++k)
    line += (k ? " || '|' || " : "") + ("coalesce(" + columns[k] + "::text, '~')");
  const std::string text =
      backend.query(location, "SELECT string_agg(" + line + ", E'\\n' ORDER BY " + order + ") FROM " + table);
  REQUIRE_MESSAGE(text.rfind("error:", 0) != 0, text);
  std::istringstream lines(text);
  for (std::string row; std::getline(lines, row);) {
    std::vector<std::string> fields;
    std::istringstream in(row);
    for (std::string f; std::getline(in, f, '|');) fields.push_back(f);
    if (!row.empty() && row.back() == '|') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

double real_of(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// The version-1 parts and points as the database's own client reads them.
struct Version1Rows {
  std::vector<std::vector<std::string>> parts, points;
};

Version1Rows version1_rows(const ResultsBackend& backend, const std::string& location) {
  Version1Rows v;
  v.parts = raw_rows(backend, location,
                     {"part_key", "serial", "made_at", "verdict", "comparison_sha256", "plan_fingerprint",
                      "zone_lower", "zone_upper", "operator", "cmm"},
                     "parts", "part_key", {false, false, false, false, false, false, true, true, false, false});
  v.points = raw_rows(backend, location,
                      {"part_key", "seq", "point_id", "region", "deviation", "evaluated", "in_tolerance", "outlier"},
                      "points", "part_key, seq", {false, false, false, false, true, false, false, false});
  return v;
}

// What this furrow reads equals the version-1 rows, field by field, reals
// bit for bit; the version-1 parts have no Furrow version.
void check_reads_version1_rows(ResultsDatabase& db, const Version1Rows& v) {
  const std::vector<StoredPart> parts = db.parts();
  REQUIRE(parts.size() >= v.parts.size());
  for (std::size_t k = 0; k < v.parts.size(); ++k) {
    const std::vector<std::string>& row = v.parts[k];
    REQUIRE(row.size() == 10);
    const StoredPart& p = parts[k];
    CHECK(std::to_string(p.key) == row[0]);
    CHECK(p.serial == row[1]);
    CHECK(p.date == row[2]);
    CHECK(p.verdict == row[3]);
    CHECK(p.comparison_sha256 == row[4]);
    CHECK(p.plan_fingerprint == row[5]);
    CHECK(p.zone_lower == real_of(row[6]));
    CHECK(p.zone_upper == real_of(row[7]));
    CHECK(p.operator_name == row[8]);
    CHECK(p.cmm == row[9]);
    CHECK(!p.furrow_version.has_value());
  }
  std::map<std::string, std::vector<StoredPoint>> points;  // by part key
  for (const auto& part : parts) points[std::to_string(part.key)] = db.points_of(part.key);
  std::map<std::string, std::size_t> seen;
  for (const std::vector<std::string>& row : v.points) {
    REQUIRE(row.size() == 8);
    const std::vector<StoredPoint>& of_part = points.at(row[0]);
    const std::size_t seq = std::stoul(row[1]);
    REQUIRE(seq < of_part.size());
    const StoredPoint& p = of_part[seq];
    CHECK(p.id == row[2]);
    CHECK((p.region ? std::to_string(*p.region) : "~") == row[3]);
    CHECK(p.deviation == real_of(row[4]));
    CHECK((p.evaluated ? "1" : "0") == row[5]);
    CHECK((p.in_tolerance ? std::string(*p.in_tolerance ? "1" : "0") : "~") == row[6]);
    CHECK(p.outlier == row[7]);
    ++seen[row[0]];
  }
  for (const auto& [key, count] : seen) CHECK(points.at(key).size() == count);
}

std::string column_count_sql(const ResultsBackend& backend) {
  return is_sqlite(backend) ? "SELECT count(*) FROM pragma_table_info('parts') WHERE name = 'furrow_version'"
                            : "SELECT count(*) FROM information_schema.columns WHERE table_schema = "
                              "current_schema() AND table_name = 'parts' AND column_name = 'furrow_version'";
}

std::string version_sql(const ResultsBackend& backend) {
  return is_sqlite(backend) ? "PRAGMA user_version" : "SELECT value FROM meta WHERE key = 'schema_version'";
}

}  // namespace

TEST_CASE("results migration: a version-1 database is read as it is, and reading changes nothing") {
  on_each_backend([](const ResultsBackend& backend) {
    const std::string location = version1_database(backend, "migration-read");
    const Version1Rows v = version1_rows(backend, location);
    REQUIRE(v.parts.size() == 4);  // make_fixtures.sh: SN-1, SN-2, SN-3 and SN-2 measured again
    REQUIRE(v.points.size() > 100);
    const std::string bytes = is_sqlite(backend) ? slurp(location) : "";
    {
      const std::unique_ptr<ResultsDatabase> db = open_results_database(location, DatabaseAccess::read);
      CHECK(db->schema_version() == 1);
      check_reads_version1_rows(*db, v);
      // SPC reads it too: the latest record of SN-2, in production order.
      const SpcInput spc = load_spc_input(*db, SpcBy::point, {});
      REQUIRE(spc.parts.size() == 3);
      CHECK(spc.parts[0].serial == v.parts[0][1]);
      CHECK(spc.parts[1].serial == v.parts[1][1]);
      CHECK(spc.parts[2].serial == v.parts[2][1]);
      // SN-2's values are those of its second record (the fourth stored).
      std::size_t checked = 0;
      for (const CharacteristicSeries& c : spc.characteristics)
        for (const std::vector<std::string>& row : v.points)
          if (row[0] == v.parts[3][0] && row[2] == c.id && row[5] == "1" && row[7].empty()) {
            const auto at = std::find(c.part_index.begin(), c.part_index.end(), std::size_t{1});
            REQUIRE(at != c.part_index.end());
            CHECK(c.values[static_cast<std::size_t>(at - c.part_index.begin())] == real_of(row[4]));
            ++checked;
          }
      CHECK(checked > 20);
      CHECK(!spc.parts[1].furrow_version.has_value());
    }
    CHECK(backend.query(location, version_sql(backend)) == "1");
    CHECK(backend.query(location, column_count_sql(backend)) == "0");
    if (is_sqlite(backend)) CHECK(slurp(location) == bytes);
    // Opening it for writing writes nothing until a part is stored.
    { open_results_database(location, DatabaseAccess::write); }
    CHECK(backend.query(location, version_sql(backend)) == "1");
    CHECK(backend.query(location, column_count_sql(backend)) == "0");
  });
}

TEST_CASE("results migration: storing into a version-1 database migrates it to version 2 and keeps every record") {
  on_each_backend([](const ResultsBackend& backend) {
    const std::string location = version1_database(backend, "migration-store");
    const Version1Rows v = version1_rows(backend, location);
    REQUIRE(v.parts.size() == 4);
    const ComparisonRecord added = made_up_record("SN-4", 77, 30, 4);
    {
      const std::unique_ptr<ResultsDatabase> db = open_results_database(location, DatabaseAccess::write);
      CHECK(db->store(added) == StoreResult::stored);
      CHECK(db->schema_version() == 2);
    }
    CHECK(backend.query(location, version_sql(backend)) == "2");
    CHECK(backend.query(location, "SELECT value FROM meta WHERE key = 'schema_version'") == "2");
    CHECK(backend.query(location, column_count_sql(backend)) == "1");
    // The version-1 rows are still there, as they were.
    const Version1Rows after = version1_rows(backend, location);
    CHECK(after.parts.size() == v.parts.size() + 1);
    CHECK(after.points.size() == v.points.size() + added.points.size());
    CHECK(std::vector<std::vector<std::string>>(after.parts.begin(), after.parts.begin() + 4) == v.parts);
    CHECK(backend.query(location, "SELECT count(*) FROM parts WHERE furrow_version IS NULL") == "4");
    CHECK(backend.query(location, "SELECT furrow_version FROM parts WHERE serial = 'SN-4'") == FURROW_VERSION);
    {
      const std::unique_ptr<ResultsDatabase> db = open_results_database(location, DatabaseAccess::read);
      check_reads_version1_rows(*db, v);
      const std::vector<StoredPart> parts = db->parts();
      REQUIRE(parts.size() == 5);
      CHECK(parts[4].serial == "SN-4");
      CHECK(parts[4].furrow_version == std::optional<std::string>(FURROW_VERSION));
      CHECK(parts[4].operator_name == added.operator_name);
      CHECK(parts[4].cmm == added.cmm);
    }
    // Still append-only after the migration, and a second opening changes nothing.
    CHECK(!backend.exec(location, "UPDATE parts SET verdict = 'PASS'"));
    CHECK(!backend.exec(location, "DELETE FROM points"));
    const std::string schema_sql = is_sqlite(backend)
                                       ? "SELECT group_concat(sql, ';') FROM (SELECT sql FROM sqlite_master ORDER BY name)"
                                       : "SELECT string_agg(table_name || '.' || column_name, ',' ORDER BY table_name, "
                                         "column_name) FROM information_schema.columns WHERE table_schema = "
                                         "current_schema()";
    const std::string schema = backend.query(location, schema_sql);
    {
      const std::unique_ptr<ResultsDatabase> db = open_results_database(location, DatabaseAccess::write);
      CHECK(db->store(added) == StoreResult::already_stored);
    }
    CHECK(backend.query(location, schema_sql) == schema);
    CHECK(backend.query(location, "SELECT count(*) FROM parts") == "5");
  });
}

TEST_CASE("results migration: on PostgreSQL a writer with only the documented grants cannot migrate, the owner can") {
  const ResultsBackend backend = postgres_backend();
  PostgresCluster& cluster = postgres_cluster();
  const std::string location = version1_database(backend, "migration_grants");
  const std::string name = PostgresCluster::database_of(location);
  const std::string writer = cluster.documented_writer(name);
  // Reading the old version needs no migration.
  CHECK(open_results_database(writer, DatabaseAccess::read)->parts().size() == 4);
  // Storing needs it, and ALTER TABLE is the owner's: exit 2 naming the
  // location and the documentation, the database still at version 1.
  std::string message;
  try {
    open_results_database(writer, DatabaseAccess::write)->store(made_up_record("SN-5", 5, 20, 5));
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK(message.find(writer) != std::string::npos);
  CHECK(message.find("Grants") != std::string::npos);
  CHECK(cluster.query(name, "SELECT value FROM meta WHERE key = 'schema_version'") == "1");
  CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "4");
  // The owner's store migrates; then the writer stores with the same grants.
  { open_results_database(location, DatabaseAccess::write)->store(made_up_record("SN-5", 5, 20, 5)); }
  CHECK(cluster.query(name, "SELECT value FROM meta WHERE key = 'schema_version'") == "2");
  CHECK(open_results_database(writer, DatabaseAccess::write)->store(made_up_record("SN-6", 6, 20, 6)) ==
        StoreResult::stored);
  CHECK(cluster.query(name, "SELECT furrow_version FROM parts WHERE serial = 'SN-6'") == FURROW_VERSION);
}
