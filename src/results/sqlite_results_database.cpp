#include "results/sqlite_results_database.hpp"

#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <thread>

#include "base/error.hpp"

namespace furrow {

namespace {

// Schema version 1 (docs/results_database.md "Schema"). Statements are
// constants: no value is ever pasted into one.
const char* const kSchemaV1 = R"sql(
CREATE TABLE meta (
  key TEXT PRIMARY KEY,
  value TEXT NOT NULL);
CREATE TABLE parts (
  part_key INTEGER PRIMARY KEY AUTOINCREMENT,
  serial TEXT NOT NULL,
  part TEXT NOT NULL,
  plan_fingerprint TEXT NOT NULL,
  made_at TEXT NOT NULL,
  stored_at TEXT NOT NULL,
  operator TEXT NOT NULL,
  cmm TEXT NOT NULL,
  verdict TEXT NOT NULL,
  comparison_sha256 TEXT NOT NULL UNIQUE,
  zone_lower REAL NOT NULL,
  zone_upper REAL NOT NULL);
CREATE INDEX parts_by_serial ON parts (serial);
CREATE TABLE points (
  part_key INTEGER NOT NULL REFERENCES parts (part_key),
  seq INTEGER NOT NULL,
  point_id TEXT NOT NULL,
  region INTEGER,
  deviation REAL NOT NULL,
  evaluated INTEGER NOT NULL,
  in_tolerance INTEGER,
  outlier TEXT NOT NULL,
  PRIMARY KEY (part_key, seq)) WITHOUT ROWID;
CREATE TABLE regions (
  part_key INTEGER NOT NULL REFERENCES parts (part_key),
  region INTEGER NOT NULL,
  count INTEGER NOT NULL,
  mean REAL NOT NULL,
  sigma REAL NOT NULL,
  min REAL NOT NULL,
  max REAL NOT NULL,
  out_of_tolerance INTEGER NOT NULL,
  PRIMARY KEY (part_key, region)) WITHOUT ROWID;
CREATE TABLE inputs (
  part_key INTEGER NOT NULL REFERENCES parts (part_key),
  seq INTEGER NOT NULL,
  role TEXT NOT NULL,
  path TEXT NOT NULL,
  sha256 TEXT NOT NULL,
  PRIMARY KEY (part_key, seq)) WITHOUT ROWID;
INSERT INTO meta (key, value) VALUES ('application', 'furrow results');
)sql";

const char* const kTables[] = {"parts", "points", "regions", "inputs"};

// Migration k takes a database from schema version k to k + 1; version 0
// is an empty file, so a new file passes through every migration. Each runs
// inside the transaction of the first store.
std::string migration(int from) {
  if (from == 0) {
    std::string sql = kSchemaV1;
    // Append-only in the file itself, whatever client writes to it.
    for (const char* table : kTables)
      for (const char* change : {"UPDATE", "DELETE"})
        sql += std::string("CREATE TRIGGER ") + table + "_no_" + change + " BEFORE " + change + " ON " + table +
               " BEGIN SELECT RAISE(ABORT, 'Furrow results are append-only'); END;\n";
    return sql;
  }
  // Version 2: the Furrow version that stored each part (NULL for the
  // parts stored before).
  if (from == 1) return "ALTER TABLE parts ADD COLUMN furrow_version TEXT;\n";
  throw std::logic_error("no migration from results schema version " + std::to_string(from));
}

// Corruption and a file that is no database are the user's to fix (exit 2);
// anything else SQLite reports is a failure of the computation.
[[noreturn]] void fail(sqlite3* db, int rc, const std::string& path, const std::string& what) {
  const std::string message = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  switch (rc & 0xff) {
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      throw InputError(path + ": not a Furrow results database, or a damaged one (" + message + ")");
    case SQLITE_CANTOPEN:
    case SQLITE_READONLY:
    case SQLITE_PERM:
      throw InputError(path + ": cannot " + what + " (" + message + ")");
    default:
      throw std::runtime_error(path + ": SQLite could not " + what + ": " + message);
  }
}

class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const std::string& path) : db_(db), path_(path) {
    const int rc = sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr);
    if (rc != SQLITE_OK) fail(db, rc, path, "read it");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& text(int i, const std::string& v) {
    check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
    return *this;
  }
  Statement& real(int i, double v) {
    check(sqlite3_bind_double(stmt_, i, v));
    return *this;
  }
  Statement& integer(int i, std::int64_t v) {
    check(sqlite3_bind_int64(stmt_, i, v));
    return *this;
  }
  Statement& null(int i) {
    check(sqlite3_bind_null(stmt_, i));
    return *this;
  }
  // True for a row, false when done.
  // SQLite's own result code, for a caller that retries.
  int step_code() { return sqlite3_step(stmt_); }
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    fail(db_, rc, path_, "read or write it");
  }
  void run_again() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  std::string text(int col) const {
    const unsigned char* t = sqlite3_column_text(stmt_, col);
    return t ? std::string(reinterpret_cast<const char*>(t), sqlite3_column_bytes(stmt_, col)) : std::string();
  }
  double real(int col) const { return sqlite3_column_double(stmt_, col); }
  std::int64_t integer(int col) const { return sqlite3_column_int64(stmt_, col); }
  bool is_null(int col) const { return sqlite3_column_type(stmt_, col) == SQLITE_NULL; }

 private:
  void check(int rc) {
    if (rc != SQLITE_OK) fail(db_, rc, path_, "bind a value");
  }
  sqlite3* db_;
  const std::string& path_;
  sqlite3_stmt* stmt_ = nullptr;
};

class SqliteResultsDatabase : public ResultsDatabase {
 public:
  SqliteResultsDatabase(const std::string& path, DatabaseAccess access) : path_(path) {
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (!exists && access == DatabaseAccess::read) throw InputError(path + ": no such results database");
    if (exists && !S_ISREG(st.st_mode)) throw InputError(path + ": not a file");
    if (!exists) {
      // Created by the first store (results_database.hpp): only its folder is checked now.
      check_folder_writable(path);
      return;
    }
    open(SQLITE_OPEN_READWRITE);
    try {
      const Kind kind = classify();
      if (access == DatabaseAccess::read && kind == Kind::empty) throw InputError(path_ + ": holds no Furrow results");
    } catch (...) {
      close();
      throw;
    }
  }
  ~SqliteResultsDatabase() override { close(); }

  const std::string& location() const override { return path_; }

  int schema_version() override { return db_ ? pragma_int("PRAGMA user_version") : 0; }

  StoreResult store(const ComparisonRecord& r) override {
    prepare_for_write();
    Transaction t(*this);
    std::optional<std::string> stored_as;
    {
      Statement known(db_, "SELECT serial FROM parts WHERE comparison_sha256 = ?1", path_);
      known.text(1, r.comparison_sha256);
      if (known.step()) stored_as = known.text(0);
    }
    if (stored_as) {
      const std::string& serial = *stored_as;
      if (serial == r.serial) return StoreResult::already_stored;
      throw InputError(path_ + ": this comparison (SHA-256 " + r.comparison_sha256 +
                       ") is stored already as serial \"" + serial + "\"; one measurement cannot be part \"" +
                       r.serial + "\" too");
    }
    Statement part(db_,
                   "INSERT INTO parts (serial, part, plan_fingerprint, made_at, stored_at, operator, cmm, verdict, "
                   "comparison_sha256, zone_lower, zone_upper, furrow_version) "
                   "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)",
                   path_);
    part.text(1, r.serial).text(2, r.part).text(3, r.plan_fingerprint).text(4, r.date).text(5, utc_iso8601(std::time(nullptr)));
    part.text(6, r.operator_name).text(7, r.cmm).text(8, r.verdict).text(9, r.comparison_sha256);
    part.real(10, r.zone_lower).real(11, r.zone_upper).text(12, FURROW_VERSION);
    part.step();
    const std::int64_t key = sqlite3_last_insert_rowid(db_);

    Statement point(db_,
                    "INSERT INTO points (part_key, seq, point_id, region, deviation, evaluated, in_tolerance, "
                    "outlier) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)",
                    path_);
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      const StoredPoint& p = r.points[k];
      point.integer(1, key).integer(2, static_cast<std::int64_t>(k)).text(3, p.id);
      if (p.region) point.integer(4, *p.region); else point.null(4);
      point.real(5, p.deviation).integer(6, p.evaluated);
      if (p.in_tolerance) point.integer(7, *p.in_tolerance); else point.null(7);
      point.text(8, p.outlier);
      point.step();
      point.run_again();
    }
    Statement region(db_,
                     "INSERT INTO regions (part_key, region, count, mean, sigma, min, max, out_of_tolerance) "
                     "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)",
                     path_);
    for (const StoredRegion& g : r.regions) {
      region.integer(1, key).integer(2, g.region).integer(3, static_cast<std::int64_t>(g.count));
      region.real(4, g.mean).real(5, g.sigma).real(6, g.min).real(7, g.max);
      region.integer(8, static_cast<std::int64_t>(g.out_of_tolerance));
      region.step();
      region.run_again();
    }
    Statement input(db_, "INSERT INTO inputs (part_key, seq, role, path, sha256) VALUES (?1, ?2, ?3, ?4, ?5)",
                    path_);
    for (std::size_t k = 0; k < r.inputs.size(); ++k) {
      input.integer(1, key).integer(2, static_cast<std::int64_t>(k));
      input.text(3, r.inputs[k].role).text(4, r.inputs[k].path).text(5, r.inputs[k].sha256);
      input.step();
      input.run_again();
    }
    t.commit();
    return StoreResult::stored;
  }

  std::vector<StoredPart> parts() override {
    if (!db_) return {};
    // Schema 1 has no furrow_version: read as NULL (absent).
    Statement s(db_,
                schema_version() >= 2
                    ? "SELECT part_key, serial, made_at, verdict, comparison_sha256, plan_fingerprint, zone_lower, "
                      "zone_upper, operator, cmm, furrow_version FROM parts ORDER BY part_key"
                    : "SELECT part_key, serial, made_at, verdict, comparison_sha256, plan_fingerprint, zone_lower, "
                      "zone_upper, operator, cmm, NULL FROM parts ORDER BY part_key",
                path_);
    std::vector<StoredPart> out;
    while (s.step()) {
      StoredPart p{s.integer(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5), s.real(6), s.real(7),
                   s.text(8), s.text(9), std::nullopt};
      if (!s.is_null(10)) p.furrow_version = s.text(10);
      out.push_back(std::move(p));
    }
    return out;
  }

  std::vector<StoredValue> values(SpcBy by) override {
    if (!db_) return {};
    Statement s(db_,
                by == SpcBy::point
                    ? "SELECT part_key, point_id, deviation FROM points WHERE evaluated = 1 AND outlier = '' "
                      "AND point_id <> '' ORDER BY part_key, seq"
                    : "SELECT part_key, CAST(region AS TEXT), mean FROM regions WHERE count > 0 "
                      "ORDER BY part_key, region",
                path_);
    std::vector<StoredValue> out;
    while (s.step()) out.push_back({s.integer(0), s.text(1), s.real(2)});
    return out;
  }

  std::vector<StoredPoint> points_of(std::int64_t part_key) override {
    if (!db_) return {};
    Statement s(db_,
                "SELECT point_id, region, deviation, evaluated, in_tolerance, outlier FROM points "
                "WHERE part_key = ?1 ORDER BY seq",
                path_);
    s.integer(1, part_key);
    std::vector<StoredPoint> out;
    while (s.step()) {
      StoredPoint p;
      p.id = s.text(0);
      if (!s.is_null(1)) p.region = static_cast<int>(s.integer(1));
      p.deviation = s.real(2);
      p.evaluated = s.integer(3) != 0;
      if (!s.is_null(4)) p.in_tolerance = s.integer(4) != 0;
      p.outlier = s.text(5);
      out.push_back(std::move(p));
    }
    return out;
  }

 private:
  // BEGIN IMMEDIATE takes the write lock at once (waiting up to the busy
  // timeout), so two writers queue instead of one failing on an upgrade;
  // rolled back unless committed.
  class Transaction {
   public:
    explicit Transaction(SqliteResultsDatabase& db) : db_(db) { db_.exec("BEGIN IMMEDIATE", "start a write"); }
    void commit() {
      db_.exec("COMMIT", "commit a write");
      done_ = true;
    }
    ~Transaction() {
      if (!done_) sqlite3_exec(db_.db_, "ROLLBACK", nullptr, nullptr, nullptr);
    }

   private:
    SqliteResultsDatabase& db_;
    bool done_ = false;
  };

  void exec(const std::string& sql, const std::string& what) {
    const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) fail(db_, rc, path_, what);
  }

  int pragma_int(const char* sql) {
    Statement s(db_, sql, path_);
    return s.step() ? static_cast<int>(s.integer(0)) : 0;
  }

  int object_count() {
    Statement s(db_, "SELECT count(*) FROM sqlite_master", path_);
    return s.step() ? static_cast<int>(s.integer(0)) : 0;
  }

  // Decides from the header alone (nothing written yet) whether the file is
  // Furrow's, empty, foreign or newer.
  enum class Kind { furrow, empty };
  Kind classify() {
    const int objects = object_count();  // a file that is no database fails here
    const int id = pragma_int("PRAGMA application_id");
    const int version = pragma_int("PRAGMA user_version");
    if (id == 0 && objects == 0 && version == 0) return Kind::empty;
    if (id != kSqliteApplicationId)
      throw InputError(path_ + ": an SQLite database, but not Furrow's results (application_id " +
                       std::to_string(id) + ")");
    if (version > kResultsSchemaVersion)
      throw InputError(path_ + ": results schema version " + std::to_string(version) + ", newer than the " +
                       std::to_string(kResultsSchemaVersion) + " this furrow knows; use a newer furrow");
    return Kind::furrow;
  }

  void open(int flags) {
    const int rc = sqlite3_open_v2(path_.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc != SQLITE_OK) {
      const std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
      close();
      throw InputError(path_ + ": cannot open the results database (" + message + ")");
    }
    sqlite3_busy_timeout(db_, kSqliteBusyTimeoutMs);
  }

  void close() {
    sqlite3_close(db_);
    db_ = nullptr;
  }

  // A missing file is created by the first store: its folder must let it be.
  static void check_folder_writable(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
      throw InputError(path + ": cannot create the results database (no folder " + folder + ")");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
      throw InputError(path + ": cannot create the results database (the folder " + folder + " is not writable)");
  }

  // Before the first store: the file created when missing, in WAL mode, and
  // brought to kResultsSchemaVersion.
  void prepare_for_write() {
    if (ready_) return;
    if (!db_) open(SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    exec("PRAGMA foreign_keys = ON", "set foreign keys");
    // WAL: readers do not block the writer, writers queue (docs/results_database.md "SQLite").
    // Switching needs the file to itself and does not wait on the busy
    // handler: it answers the old mode while another writer still creates
    // the file in rollback mode. So it is tried again until the busy timeout.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(kSqliteBusyTimeoutMs);
    for (;;) {
      Statement wal(db_, "PRAGMA journal_mode = WAL", path_);
      const int rc = wal.step_code();
      if (rc == SQLITE_ROW && wal.text(0) == "wal") break;
      if (rc != SQLITE_ROW && rc != SQLITE_BUSY && rc != SQLITE_LOCKED) fail(db_, rc, path_, "set WAL mode");
      if (std::chrono::steady_clock::now() > give_up)
        throw std::runtime_error(path_ + ": SQLite could not switch to WAL mode within the busy timeout");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    Kind kind = classify();
    if (kind == Kind::furrow && schema_version() == kResultsSchemaVersion) {
      ready_ = true;
      return;
    }
    Transaction t(*this);
    // Another writer may have created or migrated it since.
    kind = classify();
    for (int v = kind == Kind::empty ? 0 : schema_version(); v < kResultsSchemaVersion; ++v)
      exec(migration(v) + "PRAGMA user_version = " + std::to_string(v + 1) + ";", "migrate the schema");
    exec("PRAGMA application_id = " + std::to_string(kSqliteApplicationId), "mark the file");
    Statement meta(db_, "INSERT OR REPLACE INTO meta (key, value) VALUES ('schema_version', ?1)", path_);
    meta.text(1, std::to_string(kResultsSchemaVersion)).step();
    t.commit();
    ready_ = true;
  }

  std::string path_;
  sqlite3* db_ = nullptr;
  bool ready_ = false;  // created and at kResultsSchemaVersion, in WAL mode
};

}  // namespace

std::unique_ptr<ResultsDatabase> open_sqlite_results_database(const std::string& path, DatabaseAccess access) {
  return std::make_unique<SqliteResultsDatabase>(path, access);
}

}  // namespace furrow
