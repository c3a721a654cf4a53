#pragma once
// The results-database tests run on every back end: a back end here is a
// way to make a fresh, empty location and to read and write it behind
// Furrow's back with the database's own client library (the tests'
// oracle): SQLite's C API on a file, libpq on a database of the throwaway
// PostgreSQL cluster (postgres_cluster.hpp).
#include <doctest/doctest.h>
#include <sqlite3.h>

#include <functional>
#include <string>

#include "results/postgres_cluster.hpp"
#include "support/run_cli.hpp"

namespace furrow::test {

struct ResultsBackend {
  std::string name;
  // A new location nothing is stored in yet (`hint`: letters, digits, '-').
  std::function<std::string(const std::string& hint)> fresh;
  // The first value of the first row as text; "" for no row.
  std::function<std::string(const std::string& location, const std::string& sql)> query;
  // True when the statements ran.
  std::function<bool(const std::string& location, const std::string& sql)> exec;
};

inline std::string sqlite_query(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  std::string out;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW &&
      sqlite3_column_text(s, 0))
    out = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
  else if (!s)
    out = std::string("error: ") + sqlite3_errmsg(db);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return out;
}

inline int sqlite_exec(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) == SQLITE_OK);
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
  sqlite3_close(db);
  return rc;
}

inline ResultsBackend sqlite_backend() {
  return {"SQLite", [](const std::string& hint) { return scratch_dir(hint) + "/results.db"; }, sqlite_query,
          [](const std::string& path, const std::string& sql) { return sqlite_exec(path, sql) == SQLITE_OK; }};
}

inline ResultsBackend postgres_backend() {
  return {"PostgreSQL",
          [](const std::string& hint) {
            std::string name;
            for (const char c : hint) name += (c == '-') ? '_' : c;
            return postgres_cluster().new_database(name);
          },
          [](const std::string& uri, const std::string& sql) {
            return postgres_cluster().query(PostgresCluster::database_of(uri), sql);
          },
          [](const std::string& uri, const std::string& sql) {
            return postgres_cluster().exec(PostgresCluster::database_of(uri), sql);
          }};
}

// The check once per back end, each a subcase of its own: a PostgreSQL
// cluster that cannot start fails its subcase, SQLite's still runs.
inline void on_each_backend(const std::function<void(const ResultsBackend&)>& check) {
  SUBCASE("SQLite") { check(sqlite_backend()); }
  SUBCASE("PostgreSQL") { check(postgres_backend()); }
}

}  // namespace furrow::test
