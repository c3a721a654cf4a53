#include "results/postgres_results_database.hpp"

#include <libpq-fe.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "base/error.hpp"
#include "results/postgres_location.hpp"

namespace furrow {

namespace {

// Schema version 1, the same tables and columns as in SQLite
// (docs/results_database.md "Schema"; PostgreSQL's types for SQLite's).
// Statements are constants: every value goes as a bound parameter.
const char* const kSchemaV1 = R"sql(
CREATE TABLE meta (
  key TEXT PRIMARY KEY,
  value TEXT NOT NULL);
CREATE TABLE parts (
  part_key BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  serial TEXT NOT NULL,
  part TEXT NOT NULL,
  plan_fingerprint TEXT NOT NULL,
  made_at TEXT NOT NULL,
  stored_at TEXT NOT NULL,
  operator TEXT NOT NULL,
  cmm TEXT NOT NULL,
  verdict TEXT NOT NULL,
  comparison_sha256 TEXT NOT NULL UNIQUE,
  zone_lower DOUBLE PRECISION NOT NULL,
  zone_upper DOUBLE PRECISION NOT NULL);
CREATE INDEX parts_by_serial ON parts (serial);
CREATE TABLE points (
  part_key BIGINT NOT NULL REFERENCES parts (part_key),
  seq INTEGER NOT NULL,
  point_id TEXT NOT NULL,
  region INTEGER,
  deviation DOUBLE PRECISION NOT NULL,
  evaluated INTEGER NOT NULL,
  in_tolerance INTEGER,
  outlier TEXT NOT NULL,
  PRIMARY KEY (part_key, seq));
CREATE TABLE regions (
  part_key BIGINT NOT NULL REFERENCES parts (part_key),
  region INTEGER NOT NULL,
  count INTEGER NOT NULL,
  mean DOUBLE PRECISION NOT NULL,
  sigma DOUBLE PRECISION NOT NULL,
  min DOUBLE PRECISION NOT NULL,
  max DOUBLE PRECISION NOT NULL,
  out_of_tolerance INTEGER NOT NULL,
  PRIMARY KEY (part_key, region));
CREATE TABLE inputs (
  part_key BIGINT NOT NULL REFERENCES parts (part_key),
  seq INTEGER NOT NULL,
  role TEXT NOT NULL,
  path TEXT NOT NULL,
  sha256 TEXT NOT NULL,
  PRIMARY KEY (part_key, seq));
INSERT INTO meta (key, value) VALUES ('application', 'furrow results');
CREATE FUNCTION furrow_append_only() RETURNS trigger LANGUAGE plpgsql AS
  $$ BEGIN RAISE EXCEPTION 'Furrow results are append-only'; END $$;
)sql";

const char* const kTables[] = {"meta", "parts", "points", "regions", "inputs"};
const char* const kRecordTables[] = {"parts", "points", "regions", "inputs"};

// Migration k takes a database from schema version k to k + 1; version 0 is
// a schema without any table, so a new database passes through every
// migration. Each runs inside the transaction of the first store.
std::string migration(int from) {
  if (from == 0) {
    std::string sql = kSchemaV1;
    // Append-only in the database itself, whatever client writes to it.
    for (const char* table : kRecordTables)
      sql += std::string("CREATE TRIGGER ") + table + "_append_only BEFORE UPDATE OR DELETE OR TRUNCATE ON " +
             table + " FOR EACH STATEMENT EXECUTE FUNCTION furrow_append_only();\n";
    return sql;
  }
  // Version 2: the Furrow version that stored each part (NULL for the
  // parts stored before).
  if (from == 1) return "ALTER TABLE parts ADD COLUMN furrow_version TEXT;\n";
  throw std::logic_error("no migration from results schema version " + std::to_string(from));
}

struct ResultClear {
  void operator()(PGresult* r) const { PQclear(r); }
};
using Result = std::unique_ptr<PGresult, ResultClear>;

std::string format_real(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);  // 17 digits: the double back exactly
  return text;
}

// PostgreSQL's array input syntax: every element double-quoted with `"` and
// `\` escaped, or NULL. The array is itself one bound parameter.
std::string array_literal(const std::vector<std::optional<std::string>>& elements) {
  std::string out = "{";
  for (std::size_t k = 0; k < elements.size(); ++k) {
    if (k) out += ',';
    if (!elements[k]) {
      out += "NULL";
      continue;
    }
    out += '"';
    for (const char c : *elements[k]) {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
    out += '"';
  }
  return out + "}";
}

// The values of one statement's parameters, in the text format.
class Params {
 public:
  Params& text(std::string v) {
    values_.push_back(std::move(v));
    return *this;
  }
  Params& real(double v) { return text(format_real(v)); }
  Params& integer(std::int64_t v) { return text(std::to_string(v)); }
  const std::vector<std::optional<std::string>>& values() const { return values_; }

 private:
  std::vector<std::optional<std::string>> values_;
};

class PostgresResultsDatabase : public ResultsDatabase {
 public:
  PostgresResultsDatabase(const std::string& location, DatabaseAccess access) : location_(location) {
    // Keywords after dbname override the location's, those before it are
    // overridden by it: the location may set its own connect_timeout.
    const char* keywords[] = {"connect_timeout", "dbname", "fallback_application_name", nullptr};
    const char* values[] = {"30", location.c_str(), "furrow", nullptr};
    conn_ = PQconnectdbParams(keywords, values, 1);
    if (!conn_) throw std::runtime_error(location + ": libpq could not allocate a connection");
    if (PQstatus(conn_) != CONNECTION_OK) {
      std::string message = location + ": cannot connect to the PostgreSQL results database (" +
                            postgres_one_line(PQerrorMessage(conn_)) + ")";
      if (PQconnectionNeedsPassword(conn_)) message += "; the server asks for a password: " + std::string(kPostgresPasswordHelp);
      PQfinish(conn_);
      throw InputError(message);
    }
    try {
      // Notices ("relation exists", ...) are not the user's business.
      PQsetNoticeProcessor(conn_, [](void*, const char*) {}, nullptr);
      if (PQsetClientEncoding(conn_, "UTF8") != 0) fail(nullptr, "set the client encoding to UTF8");
      // Every double in its shortest exact text (PostgreSQL 12 and later;
      // 17 digits before), so numbers read back bit for bit.
      run("SET extra_float_digits = 3", {}, "set the float format");
      if (access == DatabaseAccess::read) run("SET default_transaction_read_only = on", {}, "open it read-only");
      found_ = classify();
      if (access == DatabaseAccess::read && found_.kind == Kind::empty)
        throw InputError(location_ + ": holds no Furrow results");
    } catch (...) {
      PQfinish(conn_);
      throw;
    }
  }
  ~PostgresResultsDatabase() override { PQfinish(conn_); }

  const std::string& location() const override { return location_; }

  int schema_version() override {
    if (found_.kind == Kind::empty) return 0;
    const Result r = run("SELECT value FROM meta WHERE key = 'schema_version'", {}, "read the schema version");
    return PQntuples(r.get()) ? std::atoi(PQgetvalue(r.get(), 0, 0)) : 0;
  }

  StoreResult store(const ComparisonRecord& r) override {
    prepare_for_write();
    Transaction t(*this);
    // Writers queue here, so part_key follows the commit order and the
    // digest check below cannot race another writer (docs/results_database.md
    // "Several writers").
    run("SELECT pg_advisory_xact_lock($1)", Params().integer(kPostgresWriterLock), "wait for other writers");
    if (const std::optional<StoreResult> known = stored_already(r)) return *known;
    Params part;
    part.text(r.serial).text(r.part).text(r.plan_fingerprint).text(r.date).text(utc_iso8601(std::time(nullptr)));
    part.text(r.operator_name).text(r.cmm).text(r.verdict).text(r.comparison_sha256);
    part.real(r.zone_lower).real(r.zone_upper).text(FURROW_VERSION);
    // The unique digest is the second guard, against a client that does not
    // take the lock.
    const Result inserted = run(
        "INSERT INTO parts (serial, part, plan_fingerprint, made_at, stored_at, operator, cmm, verdict, "
        "comparison_sha256, zone_lower, zone_upper, furrow_version) "
        "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12) "
        "ON CONFLICT (comparison_sha256) DO NOTHING RETURNING part_key",
        part, "store a part");
    if (PQntuples(inserted.get()) != 1) {
      if (const std::optional<StoreResult> known = stored_already(r)) return *known;
      throw std::runtime_error(location_ + ": PostgreSQL neither stored the part nor holds its digest");
    }
    const std::string key = PQgetvalue(inserted.get(), 0, 0);

    // Each table's rows in one statement: the columns as arrays, unnested.
    std::vector<std::optional<std::string>> ids, regions, deviations, evaluated, in_tolerance, outliers;
    for (const StoredPoint& p : r.points) {
      ids.push_back(p.id);
      regions.push_back(p.region ? std::optional<std::string>(std::to_string(*p.region)) : std::nullopt);
      deviations.push_back(format_real(p.deviation));
      evaluated.push_back(p.evaluated ? "1" : "0");
      in_tolerance.push_back(p.in_tolerance ? std::optional<std::string>(*p.in_tolerance ? "1" : "0") : std::nullopt);
      outliers.push_back(p.outlier);
    }
    run("INSERT INTO points (part_key, seq, point_id, region, deviation, evaluated, in_tolerance, outlier) "
        "SELECT $1, p.seq - 1, p.point_id, p.region, p.deviation, p.evaluated, p.in_tolerance, p.outlier "
        "FROM unnest($2::text[], $3::integer[], $4::double precision[], $5::integer[], $6::integer[], $7::text[]) "
        "WITH ORDINALITY AS p (point_id, region, deviation, evaluated, in_tolerance, outlier, seq)",
        Params()
            .text(key)
            .text(array_literal(ids))
            .text(array_literal(regions))
            .text(array_literal(deviations))
            .text(array_literal(evaluated))
            .text(array_literal(in_tolerance))
            .text(array_literal(outliers)),
        "store a part's points");

    std::vector<std::optional<std::string>> g_id, g_count, g_mean, g_sigma, g_min, g_max, g_out;
    for (const StoredRegion& g : r.regions) {
      g_id.push_back(std::to_string(g.region));
      g_count.push_back(std::to_string(g.count));
      g_mean.push_back(format_real(g.mean));
      g_sigma.push_back(format_real(g.sigma));
      g_min.push_back(format_real(g.min));
      g_max.push_back(format_real(g.max));
      g_out.push_back(std::to_string(g.out_of_tolerance));
    }
    run("INSERT INTO regions (part_key, region, count, mean, sigma, min, max, out_of_tolerance) "
        "SELECT $1, g.* FROM unnest($2::integer[], $3::integer[], $4::double precision[], $5::double precision[], "
        "$6::double precision[], $7::double precision[], $8::integer[]) AS g",
        Params()
            .text(key)
            .text(array_literal(g_id))
            .text(array_literal(g_count))
            .text(array_literal(g_mean))
            .text(array_literal(g_sigma))
            .text(array_literal(g_min))
            .text(array_literal(g_max))
            .text(array_literal(g_out)),
        "store a part's regions");

    std::vector<std::optional<std::string>> roles, paths, digests;
    for (const StoredInput& in : r.inputs) {
      roles.push_back(in.role);
      paths.push_back(in.path);
      digests.push_back(in.sha256);
    }
    run("INSERT INTO inputs (part_key, seq, role, path, sha256) "
        "SELECT $1, i.seq - 1, i.role, i.path, i.sha256 "
        "FROM unnest($2::text[], $3::text[], $4::text[]) WITH ORDINALITY AS i (role, path, sha256, seq)",
        Params().text(key).text(array_literal(roles)).text(array_literal(paths)).text(array_literal(digests)),
        "store a part's inputs");
    t.commit();
    return StoreResult::stored;
  }

  std::vector<StoredPart> parts() override {
    if (found_.kind == Kind::empty) return {};
    // Schema 1 has no furrow_version: read as NULL (absent).
    const Result r = run(found_.version >= 2
                             ? "SELECT part_key, serial, made_at, verdict, comparison_sha256, plan_fingerprint, "
                               "zone_lower, zone_upper, operator, cmm, furrow_version FROM parts ORDER BY part_key"
                             : "SELECT part_key, serial, made_at, verdict, comparison_sha256, plan_fingerprint, "
                               "zone_lower, zone_upper, operator, cmm, NULL FROM parts ORDER BY part_key",
                         {}, "read the parts");
    std::vector<StoredPart> out;
    const PGresult* res = r.get();
    for (int row = 0; row < PQntuples(res); ++row) {
      StoredPart p{integer(res, row, 0), text(res, row, 1), text(res, row, 2), text(res, row, 3),
                   text(res, row, 4),    text(res, row, 5), real(res, row, 6), real(res, row, 7),
                   text(res, row, 8),    text(res, row, 9), std::nullopt};
      if (!PQgetisnull(res, row, 10)) p.furrow_version = text(res, row, 10);
      out.push_back(std::move(p));
    }
    return out;
  }

  std::vector<StoredValue> values(SpcBy by) override {
    if (found_.kind == Kind::empty) return {};
    const Result r = run(by == SpcBy::point
                             ? "SELECT part_key, point_id, deviation FROM points WHERE evaluated = 1 AND outlier = '' "
                               "AND point_id <> '' ORDER BY part_key, seq"
                             : "SELECT part_key, region::text, mean FROM regions WHERE count > 0 "
                               "ORDER BY part_key, region",
                         {}, "read the values");
    std::vector<StoredValue> out;
    const PGresult* res = r.get();
    out.reserve(static_cast<std::size_t>(PQntuples(res)));
    for (int row = 0; row < PQntuples(res); ++row)
      out.push_back({integer(res, row, 0), text(res, row, 1), real(res, row, 2)});
    return out;
  }

  std::vector<StoredPoint> points_of(std::int64_t part_key) override {
    if (found_.kind == Kind::empty) return {};
    const Result r = run(
        "SELECT point_id, region, deviation, evaluated, in_tolerance, outlier FROM points "
        "WHERE part_key = $1 ORDER BY seq",
        Params().integer(part_key), "read a part's points");
    std::vector<StoredPoint> out;
    const PGresult* res = r.get();
    for (int row = 0; row < PQntuples(res); ++row) {
      StoredPoint p;
      p.id = text(res, row, 0);
      if (!PQgetisnull(res, row, 1)) p.region = static_cast<int>(integer(res, row, 1));
      p.deviation = real(res, row, 2);
      p.evaluated = integer(res, row, 3) != 0;
      if (!PQgetisnull(res, row, 4)) p.in_tolerance = integer(res, row, 4) != 0;
      p.outlier = text(res, row, 5);
      out.push_back(std::move(p));
    }
    return out;
  }

 private:
  // Rolled back unless committed (also when the connection is dropped).
  class Transaction {
   public:
    explicit Transaction(PostgresResultsDatabase& db) : db_(db) { db_.run("BEGIN", {}, "start a write"); }
    void commit() {
      db_.run("COMMIT", {}, "commit a write");
      done_ = true;
    }
    ~Transaction() {
      if (!done_) PQclear(PQexec(db_.conn_, "ROLLBACK"));
    }

   private:
    PostgresResultsDatabase& db_;
    bool done_ = false;
  };

  static std::string text(const PGresult* r, int row, int col) {
    return std::string(PQgetvalue(r, row, col), static_cast<std::size_t>(PQgetlength(r, row, col)));
  }
  static double real(const PGresult* r, int row, int col) { return std::strtod(PQgetvalue(r, row, col), nullptr); }
  static std::int64_t integer(const PGresult* r, int row, int col) {
    return std::strtoll(PQgetvalue(r, row, col), nullptr, 10);
  }

  // A statement with its parameters bound, in the text format; its result
  // whatever the status.
  Result execute(const char* sql, const Params& params, const std::string& what) {
    std::vector<const char*> values;
    for (const std::optional<std::string>& v : params.values()) {
      if (v && v->find('\0') != std::string::npos)
        throw InputError(location_ + ": cannot " + what + ": a value holds a NUL byte, which PostgreSQL text cannot keep");
      values.push_back(v ? v->c_str() : nullptr);
    }
    Result r(PQexecParams(conn_, sql, static_cast<int>(values.size()), nullptr, values.data(), nullptr, nullptr, 0));
    if (!r) fail(nullptr, what);
    return r;
  }

  static bool ok(const Result& r) {
    const ExecStatusType s = PQresultStatus(r.get());
    return s == PGRES_COMMAND_OK || s == PGRES_TUPLES_OK;
  }

  Result run(const char* sql, const Params& params, const std::string& what) {
    Result r = execute(sql, params, what);
    if (!ok(r)) fail(r.get(), what);
    return r;
  }

  // A refused privilege and a value PostgreSQL cannot take are the user's
  // to fix (exit 2); anything else is a failure of the computation.
  [[noreturn]] void fail(const PGresult* r, const std::string& what) {
    const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
    const char* primary = r ? PQresultErrorField(r, PG_DIAG_MESSAGE_PRIMARY) : nullptr;
    const std::string message = postgres_one_line(primary ? primary : PQerrorMessage(conn_));
    const std::string code = state ? state : "";
    if (code == "42501")
      throw InputError(location_ + ": cannot " + what + " (" + message +
                       "); the user needs the grants of docs/results_database.md \"Grants\"");
    if (code.compare(0, 2, "22") == 0 || code.compare(0, 2, "08") == 0 || code == "25006")
      throw InputError(location_ + ": cannot " + what + " (" + message + ")");
    throw std::runtime_error(location_ + ": PostgreSQL could not " + what + ": " + message);
  }

  std::optional<StoreResult> stored_already(const ComparisonRecord& r) {
    const Result known = run("SELECT serial FROM parts WHERE comparison_sha256 = $1",
                             Params().text(r.comparison_sha256), "look the comparison up");
    if (PQntuples(known.get()) == 0) return std::nullopt;
    const std::string serial = text(known.get(), 0, 0);
    if (serial == r.serial) return StoreResult::already_stored;
    throw InputError(location_ + ": this comparison (SHA-256 " + r.comparison_sha256 +
                     ") is stored already as serial \"" + serial + "\"; one measurement cannot be part \"" + r.serial +
                     "\" too");
  }

  // What the connection's current schema holds, decided by reading alone.
  enum class Kind { furrow, empty };
  struct Found {
    Kind kind = Kind::empty;
    int version = 0;
  };
  Found classify() {
    const Result schema = run("SELECT current_schema()", {}, "read the current schema");
    if (PQgetisnull(schema.get(), 0, 0))
      throw InputError(location_ + ": no schema to keep the results in (the search_path names none that exists)");
    const std::string name = text(schema.get(), 0, 0);
    const Result tables = run(
        "SELECT c.relname FROM pg_catalog.pg_class c JOIN pg_catalog.pg_namespace n ON n.oid = c.relnamespace "
        "WHERE n.nspname = current_schema() AND c.relkind IN ('r', 'p', 'v', 'm', 'f')",
        {}, "list the tables");
    std::set<std::string> names;
    for (int row = 0; row < PQntuples(tables.get()); ++row) names.insert(text(tables.get(), row, 0));
    if (names.empty()) return {};
    const std::string foreign = location_ + ": a PostgreSQL database whose schema \"" + name +
                                "\" holds other tables, but not Furrow's results";
    if (!names.count("meta")) throw InputError(foreign);
    // meta's columns are checked first: reading another program's meta
    // table cannot fail (a failed statement would abort the transaction).
    const Result columns = run(
        "SELECT count(*) FROM information_schema.columns WHERE table_schema = current_schema() "
        "AND table_name = 'meta' AND column_name IN ('key', 'value')",
        {}, "read the meta table");
    if (text(columns.get(), 0, 0) != "2") throw InputError(foreign);
    const Result meta = run("SELECT key, value FROM meta WHERE key IN ('application', 'schema_version')", {},
                            "read the meta table");
    std::string application, version_text;
    for (int row = 0; row < PQntuples(meta.get()); ++row)
      (text(meta.get(), row, 0) == "application" ? application : version_text) = text(meta.get(), row, 1);
    if (application != "furrow results") throw InputError(foreign);
    char* end = nullptr;
    const long version = std::strtol(version_text.c_str(), &end, 10);
    if (version_text.empty() || *end != '\0' || version < 1)
      throw InputError(location_ + ": not a Furrow results database, or a damaged one (schema version \"" +
                       version_text + "\")");
    if (version > kResultsSchemaVersion)
      throw InputError(location_ + ": results schema version " + std::to_string(version) + ", newer than the " +
                       std::to_string(kResultsSchemaVersion) + " this furrow knows; use a newer furrow");
    for (const char* table : kTables)
      if (!names.count(table))
        throw InputError(location_ + ": not a Furrow results database, or a damaged one (no table " + table + ")");
    return {Kind::furrow, static_cast<int>(version)};
  }

  // Before the first store: the tables created, or migrated to
  // kResultsSchemaVersion, under the writers' lock.
  void prepare_for_write() {
    if (found_.kind == Kind::furrow && found_.version == kResultsSchemaVersion) return;
    Transaction t(*this);
    run("SELECT pg_advisory_xact_lock($1)", Params().integer(kPostgresWriterLock), "wait for other writers");
    // Another writer may have created or migrated it since.
    const Found now = classify();
    for (int v = now.kind == Kind::empty ? 0 : now.version; v < kResultsSchemaVersion; ++v) {
      // Constant DDL, no value in it: the one place a statement runs without
      // parameters through PQexec (which takes several statements).
      const std::string sql = migration(v);
      const Result r(PQexec(conn_, sql.c_str()));
      if (!r || !ok(r)) fail(r.get(), "create the results tables");
    }
    run("INSERT INTO meta (key, value) VALUES ('schema_version', $1) "
        "ON CONFLICT (key) DO UPDATE SET value = EXCLUDED.value",
        Params().text(std::to_string(kResultsSchemaVersion)), "write the schema version");
    t.commit();
    found_ = {Kind::furrow, kResultsSchemaVersion};
  }

  std::string location_;
  PGconn* conn_ = nullptr;
  Found found_;  // what the database held when opened, or after prepare_for_write()
};

}  // namespace

std::unique_ptr<ResultsDatabase> open_postgres_results_database(const std::string& location,
                                                                DatabaseAccess access) {
  check_postgres_location(location);
  return std::make_unique<PostgresResultsDatabase>(location, access);
}

}  // namespace furrow
