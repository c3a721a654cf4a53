// The results database on PostgreSQL (docs/results_database.md
// "PostgreSQL"), on a real throwaway cluster (postgres_cluster.hpp): what
// only PostgreSQL has - several writers with their own connections, the
// schema made in the database, a database of another program, passwords,
// the grants a writer needs - and the same SPC input and spc.json bytes as
// SQLite for the same records. The checks both back ends share are in
// test_results_database.cpp. Oracles: the records themselves, counts by
// libpq on the tests' own connection, and the SQLite back end.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "base/error.hpp"
#include "results/postgres_cluster.hpp"
#include "results/results_database.hpp"
#include "results/results_records.hpp"
#include "results/spc_json.hpp"
#include "results/spc_statistics.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

std::string input_error_of(const std::function<void()>& work) {
  try {
    work();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError");
  return "";
}

// Every relation in the database's public schema, as one sorted text.
std::string relations(const std::string& database) {
  return postgres_cluster().query(
      database,
      "SELECT coalesce(string_agg(relname, ',' ORDER BY relname), '') FROM pg_class c JOIN pg_namespace n "
      "ON n.oid = c.relnamespace WHERE n.nspname = 'public'");
}

}  // namespace

TEST_CASE("results database on PostgreSQL: the first store gives a new database Furrow's tables, schema version 2") {
  PostgresCluster& cluster = postgres_cluster();
  const std::string uri = cluster.new_database("pg_new");
  const std::string name = PostgresCluster::database_of(uri);
  const std::string no_tables =
      "SELECT count(*) FROM information_schema.tables WHERE table_schema = 'public'";
  // Opening for writing creates nothing: a command that fails before storing leaves the database as it was.
  { CHECK(open_results_database(uri, DatabaseAccess::write)->schema_version() == 0); }
  CHECK(cluster.query(name, no_tables) == "0");
  { CHECK(open_results_database(uri, DatabaseAccess::write)->store(made_up_record("K", 1, 4, 1)) == StoreResult::stored); }
  CHECK(cluster.query(name, "SELECT value FROM meta WHERE key = 'schema_version'") == "2");
  CHECK(cluster.query(name, "SELECT value FROM meta WHERE key = 'application'") == "furrow results");
  CHECK(cluster.query(name,
                      "SELECT string_agg(table_name, ',' ORDER BY table_name) FROM information_schema.tables "
                      "WHERE table_schema = 'public'") == "inputs,meta,parts,points,regions");
  CHECK(cluster.query(name, "SELECT furrow_version FROM parts") == FURROW_VERSION);
  // Opening it again changes nothing; the same database as key=value pairs.
  const std::string before = relations(name);
  { open_results_database(cluster.key_value(name), DatabaseAccess::write)->store(made_up_record("K", 1, 4, 1)); }
  CHECK(relations(name) == before);
  CHECK(cluster.query(name, "SELECT serial FROM parts") == "K");
  // Append-only in the database: even its owner cannot update, delete or truncate.
  CHECK(!cluster.exec(name, "UPDATE parts SET serial = 'X'"));
  CHECK(!cluster.exec(name, "DELETE FROM points"));
  CHECK(!cluster.exec(name, "TRUNCATE inputs CASCADE"));
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == "4");
}

TEST_CASE("results database on PostgreSQL: four writers at once, each its own connection, lose nothing") {
  PostgresCluster& cluster = postgres_cluster();
  // They all start on an empty database: creating the tables races too.
  const std::string uri = cluster.new_database("pg_four");
  const std::string name = PostgresCluster::database_of(uri);
  constexpr int kWriters = 4, kParts = 25, kPoints = 300;
  pid_t children[kWriters];
  for (int w = 0; w < kWriters; ++w) {
    children[w] = ::fork();
    REQUIRE(children[w] >= 0);
    if (children[w] == 0) {
      int code = 0;
      try {
        auto db = open_results_database(uri, DatabaseAccess::write);
        for (int k = 0; k < kParts; ++k) {
          const ComparisonRecord r = made_up_record("W" + std::to_string(w) + "-" + std::to_string(k),
                                                    1000u * (w + 1) + k, kPoints, 100u * w + k);
          if (db->store(r) != StoreResult::stored) code = 4;
        }
        // Every writer also stores one comparison all four share, under
        // one serial: one of them stores it, three find it there.
        if (db->store(made_up_record("SHARED", 99, kPoints, 9)) == StoreResult::stored) code = code ? code : 10;
      } catch (...) {
        code = 1;
      }
      ::_exit(code);
    }
  }
  int stored_shared = 0;
  for (const pid_t c : children) {
    int status = 0;
    REQUIRE(::waitpid(c, &status, 0) == c);
    REQUIRE(WIFEXITED(status));
    CHECK((WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 10));
    stored_shared += WEXITSTATUS(status) == 10;
  }
  CHECK(stored_shared == 1);
  const int total = kWriters * kParts + 1;
  CHECK(cluster.query(name, "SELECT count(*) FROM parts") == std::to_string(total));
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == std::to_string(total * kPoints));
  CHECK(cluster.query(name, "SELECT count(DISTINCT part_key) FROM points") == std::to_string(total));
  CHECK(cluster.query(name, "SELECT count(*) FROM inputs") == std::to_string(total * 2));
  // Each writer's parts in its own order: the keys increase with storing.
  for (int w = 0; w < kWriters; ++w) {
    const std::string prefix = "W" + std::to_string(w) + "-";
    CHECK(cluster.query(name, "SELECT bool_and(ok) FROM (SELECT part_key > lag(part_key, 1, 0::bigint) OVER "
                              "(ORDER BY split_part(serial, '-', 2)::int) AS ok FROM parts WHERE serial LIKE '" +
                                  prefix + "%') t") == "t");
  }
  // And each part whole: its points are the record's, bit for bit.
  auto db = open_results_database(uri, DatabaseAccess::read);
  for (const StoredPart& p : db->parts()) {
    if (p.serial == "SHARED") continue;
    const int w = p.serial[1] - '0';
    const int k = std::stoi(p.serial.substr(3));
    const ComparisonRecord r = made_up_record(p.serial, 1000u * (w + 1) + k, kPoints, 100u * w + k);
    const std::vector<StoredPoint> back = db->points_of(p.key);
    REQUIRE(back.size() == r.points.size());
    bool same = true;
    for (std::size_t i = 0; i < back.size(); ++i)
      same = same && back[i].id == r.points[i].id && back[i].deviation == r.points[i].deviation &&
             back[i].region == r.points[i].region && back[i].outlier == r.points[i].outlier;
    CHECK(same);
  }
}

TEST_CASE("results database on PostgreSQL: a serial like SQL is stored and read back as a value") {
  PostgresCluster& cluster = postgres_cluster();
  const std::string uri = cluster.new_database("pg_injection");
  const std::string name = PostgresCluster::database_of(uri);
  const std::string evil = "'; DROP TABLE parts; --";
  ComparisonRecord r = made_up_record(evil, 7, 6, 3);
  r.points[0].id = "\"}{,NULL\\'; DELETE FROM points; --";  // array syntax and SQL at once
  r.points[1].id = "NULL";
  r.inputs[1].path = "a\"b\\c,{d}";
  { REQUIRE(open_results_database(uri, DatabaseAccess::write)->store(r) == StoreResult::stored); }
  CHECK(cluster.query(name, "SELECT serial FROM parts") == evil);
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == "6");
  CHECK(cluster.query(name, "SELECT point_id FROM points WHERE seq = 0") == r.points[0].id);
  CHECK(cluster.query(name, "SELECT point_id FROM points WHERE seq = 1") == "NULL");
  CHECK(cluster.query(name, "SELECT path FROM inputs WHERE seq = 1") == r.inputs[1].path);
  auto db = open_results_database(uri, DatabaseAccess::read);
  REQUIRE(db->parts().size() == 1);
  CHECK(db->parts()[0].serial == evil);
  const std::vector<StoredPoint> back = db->points_of(db->parts()[0].key);
  REQUIRE(back.size() == 6);
  CHECK(back[0].id == r.points[0].id);
  CHECK(back[1].id == "NULL");
  CHECK(load_spc_input(*db, SpcBy::point, parse_serial_range(evil + "..", "--serials")).parts.size() == 1);
  // What PostgreSQL text cannot keep - a NUL byte, bytes that are not UTF-8 -
  // is bad input naming the database, and nothing of the part is stored.
  ComparisonRecord nul = made_up_record("N", 8, 6, 4);
  nul.points[3].id = std::string("P\0x", 3);
  ComparisonRecord latin1 = made_up_record("L", 9, 6, 5);
  latin1.points[2].id = "R\xe9gion";
  auto writer = open_results_database(uri, DatabaseAccess::write);
  for (const ComparisonRecord* bad : {&nul, &latin1}) {
    CAPTURE(bad->serial);
    CHECK(input_error_of([&] { writer->store(*bad); }).find(uri) != std::string::npos);
  }
  CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "1");
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == "6");
  CHECK(writer->store(made_up_record("after", 10, 6, 6)) == StoreResult::stored);  // and the next part goes in
}

TEST_CASE("results database on PostgreSQL: a connection string holding a password is refused, the password never shown") {
  const std::string secret = "s3cr3t-Pw";
  for (const std::string& location :
       {"postgresql://furrow:" + secret + "@db.example/results", "postgres://furrow:" + secret + "@localhost:5432/r",
        "postgresql://db.example/results?user=furrow&password=" + secret,
        "host=db.example dbname=results user=furrow password=" + secret,
        "host=db.example password='" + secret + " x' dbname=results",
        std::string("postgresql://furrow:s3cr3t%2DPw@db.example/results")}) {
    CAPTURE(location);
    for (const DatabaseAccess access : {DatabaseAccess::write, DatabaseAccess::read}) {
      const std::string message = input_error_of([&] { open_results_database(location, access); });
      CHECK(message.find(secret) == std::string::npos);
      CHECK(message.find("s3cr3t%2DPw") == std::string::npos);
      CHECK(message.find("****") != std::string::npos);
      CHECK(message.find(".pgpass") != std::string::npos);
      CHECK(message.find("PGPASSWORD") != std::string::npos);
      CHECK(message.find("service") != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
    }
  }
  // The command line: exit 2, one line, no password, nothing written.
  const std::string out = scratch_dir("results-pg-password") + "/spc";
  const std::string location = "postgresql://furrow:" + secret + "@db.example/results";
  const CliResult spc = run_furrow({"spc", "--db", location, "--out", out});
  CHECK(spc.status == 2);
  CHECK(line_count(spc.err) == 1);
  CHECK(spc.err.find(secret) == std::string::npos);
  CHECK(spc.err.find("PGPASSFILE") != std::string::npos);
  CHECK(!std::filesystem::exists(out));
  // compare --db without --serial is refused too, and must not print it either.
  const CliResult compare = run_furrow({"compare", source_path("examples/parts/mould.json"), "--measurements",
                                        "m.csv", "--out", out + "/c.json", "--db", location});
  CHECK(compare.status == 2);
  CHECK(compare.err.find(secret) == std::string::npos);
  CHECK(compare.err.find("****") != std::string::npos);  // refused for the password, before the serial
}

TEST_CASE("results database on PostgreSQL: a database of another program, or of a newer furrow, is refused, nothing written") {
  PostgresCluster& cluster = postgres_cluster();
  SUBCASE("other tables, not Furrow's") {
    const std::string uri = cluster.new_database("pg_foreign");
    const std::string name = PostgresCluster::database_of(uri);
    REQUIRE(cluster.exec(name, "CREATE TABLE parts (serial TEXT); INSERT INTO parts VALUES ('x');"));
    const std::string before = relations(name);
    for (const DatabaseAccess access : {DatabaseAccess::write, DatabaseAccess::read}) {
      const std::string message = input_error_of([&] { open_results_database(uri, access); });
      CHECK(message.find(uri) != std::string::npos);
      CHECK(message.find("not Furrow's") != std::string::npos);
    }
    CHECK(relations(name) == before);
    CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "1");
  }
  SUBCASE("a meta table of another program") {
    const std::string uri = cluster.new_database("pg_foreign_meta");
    const std::string name = PostgresCluster::database_of(uri);
    REQUIRE(cluster.exec(name, "CREATE TABLE meta (k INTEGER)"));
    CHECK(input_error_of([&] { open_results_database(uri, DatabaseAccess::write); }).find("not Furrow's") !=
          std::string::npos);
    CHECK(relations(name) == "meta");
  }
  SUBCASE("a newer schema version") {
    const std::string uri = cluster.new_database("pg_newer");
    const std::string name = PostgresCluster::database_of(uri);
    { REQUIRE(open_results_database(uri, DatabaseAccess::write)->store(made_up_record("S0", 1, 5, 1)) ==
              StoreResult::stored); }
    REQUIRE(cluster.exec(name, "UPDATE meta SET value = '" + std::to_string(kResultsSchemaVersion + 1) +
                                   "' WHERE key = 'schema_version'"));
    for (const DatabaseAccess access : {DatabaseAccess::write, DatabaseAccess::read}) {
      const std::string message = input_error_of([&] { open_results_database(uri, access); });
      CHECK(message.find(uri) != std::string::npos);
      CHECK(message.find("newer") != std::string::npos);
    }
    CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "1");
    CHECK(cluster.query(name, "SELECT value FROM meta WHERE key = 'schema_version'") ==
          std::to_string(kResultsSchemaVersion + 1));
  }
  SUBCASE("an empty database for reading, a database that is not there, a server that is not there") {
    const std::string uri = cluster.new_database("pg_empty");
    CHECK(input_error_of([&] { open_results_database(uri, DatabaseAccess::read); }).find("holds no Furrow results") !=
          std::string::npos);
    CHECK(relations(PostgresCluster::database_of(uri)).empty());
    const std::string missing = cluster.uri("no_such_database");
    CHECK(input_error_of([&] { open_results_database(missing, DatabaseAccess::write); }).find(missing) !=
          std::string::npos);
    const std::string no_server = "postgresql:///x?host=" + cluster.socket_dir() + "/none&port=1";
    CHECK(input_error_of([&] { open_results_database(no_server, DatabaseAccess::read); }).find("cannot connect") !=
          std::string::npos);
  }
}

TEST_CASE("results database on PostgreSQL: a user with only the documented grants stores and reads") {
  PostgresCluster& cluster = postgres_cluster();
  const std::string uri = cluster.new_database("pg_grants");
  const std::string name = PostgresCluster::database_of(uri);
  // The owner's first store creates the tables (docs/results_database.md "Grants").
  { open_results_database(uri, DatabaseAccess::write)->store(made_up_record("G0", 9, 20, 9)); }
  // The grants exactly as the documentation gives them.
  const std::string writer = cluster.documented_writer(name);
  {
    auto db = open_results_database(writer, DatabaseAccess::write);
    CHECK(db->store(made_up_record("G1", 1, 20, 1)) == StoreResult::stored);
    CHECK(db->store(made_up_record("G1", 1, 20, 1)) == StoreResult::already_stored);
    CHECK(db->store(made_up_record("G2", 2, 20, 2)) == StoreResult::stored);
  }
  CHECK(load_spc_input(*open_results_database(writer, DatabaseAccess::read), SpcBy::point, {}).parts.size() == 3);
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == "60");
  // Without the grants: exit 2 naming the location and the documentation.
  REQUIRE(cluster.exec(name, "REVOKE INSERT ON points FROM furrow_writer"));
  const std::string message = input_error_of(
      [&] { open_results_database(writer, DatabaseAccess::write)->store(made_up_record("G3", 3, 20, 3)); });
  CHECK(message.find(writer) != std::string::npos);
  CHECK(message.find("Grants") != std::string::npos);
  CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "3");  // the part's transaction rolled back
}

TEST_CASE("results database on PostgreSQL: SQLite and PostgreSQL give the same SPC input and the same spc.json bytes") {
  const std::string sqlite_path = scratch_dir("results-pg-same") + "/results.db";
  const std::string uri = postgres_cluster().new_database("pg_same");
  // A re-measurement and a comparison stored twice make the order non-trivial.
  std::vector<ComparisonRecord> records;
  for (int k = 0; k < 30; ++k) records.push_back(made_up_record("SN-" + std::to_string(k), k + 1, 40, k));
  records.push_back(made_up_record("SN-3", 500, 40, 77));
  records.push_back(records[5]);
  records[7].points[2].deviation += 0.1;  // a signal for the Nelson rules
  for (const std::string& location : {sqlite_path, uri}) {
    auto db = open_results_database(location, DatabaseAccess::write);
    for (const ComparisonRecord& r : records) db->store(r);
  }
  auto sqlite = open_results_database(sqlite_path, DatabaseAccess::read);
  auto postgres = open_results_database(uri, DatabaseAccess::read);
  CHECK(sqlite->parts().size() == 31);
  CHECK(postgres->parts().size() == 31);
  for (const SpcBy by : {SpcBy::point, SpcBy::region}) {
    for (const SerialRange& range : {SerialRange{}, parse_serial_range("SN-2..SN-20", "--serials")}) {
      const SpcInput a = load_spc_input(*sqlite, by, range);
      const SpcInput b = load_spc_input(*postgres, by, range);
      REQUIRE(a.parts.size() == b.parts.size());
      for (std::size_t i = 0; i < a.parts.size(); ++i) {
        CHECK(a.parts[i].serial == b.parts[i].serial);
        CHECK(a.parts[i].date == b.parts[i].date);
        CHECK(a.parts[i].verdict == b.parts[i].verdict);
      }
      REQUIRE(a.characteristics.size() == b.characteristics.size());
      CHECK(!a.characteristics.empty());
      for (std::size_t c = 0; c < a.characteristics.size(); ++c) {
        CHECK(a.characteristics[c].id == b.characteristics[c].id);
        CHECK(a.characteristics[c].part_index == b.characteristics[c].part_index);
        CHECK(a.characteristics[c].values == b.characteristics[c].values);
        CHECK(a.characteristics[c].lower == b.characteristics[c].lower);
        CHECK(a.characteristics[c].upper == b.characteristics[c].upper);
      }
      // The same selection source string: the documents are byte for byte equal.
      const SpcSelection selection{"results", {{"by", to_string(by)}}};
      CHECK(spc_json(compute_spc(a), selection) == spc_json(compute_spc(b), selection));
    }
  }
  // furrow spc as a user runs it, on each: the same exit status, summary and
  // documents, but for the source each names.
  const std::string out = scratch_dir("results-pg-same-cli");
  const CliResult from_sqlite = run_furrow({"spc", "--db", sqlite_path, "--out", out + "/sqlite"});
  const CliResult from_postgres = run_furrow({"spc", "--db", uri, "--out", out + "/postgres"});
  CHECK((from_sqlite.status == 0 || from_sqlite.status == 1));
  CHECK(from_postgres.status == from_sqlite.status);
  CHECK(from_postgres.err == "");
  std::string json = slurp(out + "/postgres/spc.json");
  REQUIRE(json.find(uri) != std::string::npos);
  json.replace(json.find(uri), uri.size(), sqlite_path);
  CHECK(json == slurp(out + "/sqlite/spc.json"));
  CHECK(slurp(out + "/postgres/spc.html").size() > 1000);
  // The oracle for the latest record of a re-measured serial: the record itself.
  const SpcInput spc = load_spc_input(*postgres, SpcBy::point, {});
  CHECK(spc.parts.size() == 30);
  CHECK(spc.parts[3].serial == "SN-3");
  CHECK(spc.characteristics[0].id == "P0");
  CHECK(spc.characteristics[0].values[3] == records[30].points[0].deviation);
}

TEST_CASE("results database on PostgreSQL: a writer killed with SIGKILL mid-part leaves only complete parts") {
  PostgresCluster& cluster = postgres_cluster();
  constexpr std::size_t kPoints = 20000;  // a large part: its transaction takes a while
  std::mt19937 rng(20261128);            // the moments of the kills
  int killed_mid_store = 0;
  for (int round = 0; round < 4; ++round) {
    CAPTURE(round);
    const std::string uri = cluster.new_database("pg_kill");
    const std::string name = PostgresCluster::database_of(uri);
    int pipe_fds[2];
    REQUIRE(::pipe(pipe_fds) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(pipe_fds[0]);
      try {
        auto db = open_results_database(uri, DatabaseAccess::write);
        for (std::uint32_t k = 0;; ++k) {
          const ComparisonRecord r = made_up_record("K-" + std::to_string(k), k + 1, kPoints, k);
          if (::write(pipe_fds[1], "B", 1) != 1) ::_exit(3);  // a store begins
          if (db->store(r) != StoreResult::stored) ::_exit(4);
          if (::write(pipe_fds[1], "C", 1) != 1) ::_exit(3);  // and is committed
        }
      } catch (...) {
        ::_exit(1);
      }
    }
    ::close(pipe_fds[1]);
    std::string progress;
    char c = 0;
    while (progress.find('C') == std::string::npos && ::read(pipe_fds[0], &c, 1) == 1) progress += c;
    REQUIRE(progress.find('C') != std::string::npos);
    std::this_thread::sleep_for(std::chrono::milliseconds(std::uniform_int_distribution<int>(5, 400)(rng)));
    REQUIRE(::kill(child, SIGKILL) == 0);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFSIGNALED(status));
    while (::read(pipe_fds[0], &c, 1) == 1) progress += c;
    ::close(pipe_fds[0]);
    const long long confirmed = static_cast<long long>(std::count(progress.begin(), progress.end(), 'C'));
    const bool last_unconfirmed = progress.back() == 'B';  // killed inside a store, or after its commit

    // The next writer waits for the dead one's lock to go with its
    // connection, then stores; what is there is exactly the complete parts.
    auto db = open_results_database(uri, DatabaseAccess::write);
    CHECK(db->store(made_up_record("after", 999999, 10, 1)) == StoreResult::stored);
    const long long present = std::stoll(cluster.query(name, "SELECT count(*) FROM parts WHERE serial <> 'after'"));
    CHECK((present == confirmed || (last_unconfirmed && present == confirmed + 1)));
    killed_mid_store += last_unconfirmed && present == confirmed;
    CHECK(cluster.query(name, "SELECT count(*) FROM points") == std::to_string(present * kPoints + 10));
    CHECK(cluster.query(name, "SELECT count(*) FROM parts p WHERE (SELECT count(*) FROM points q WHERE "
                              "q.part_key = p.part_key) <> " + std::to_string(kPoints) + " AND serial <> 'after'") == "0");
    CHECK(cluster.query(name, "SELECT count(*) FROM regions") == std::to_string(present * 3 + 3));
    CHECK(cluster.query(name, "SELECT count(*) FROM inputs") == std::to_string(present * 2 + 2));
  }
  // The kills must have hit a part's transaction, or this did not test what it says.
  CHECK(killed_mid_store >= 2);
}

TEST_CASE("results database on PostgreSQL: furrow compare --db stores a real part once, under its serial") {
  PostgresCluster& cluster = postgres_cluster();
  const std::string dir = scratch_dir("results-pg-compare");
  const std::string part = source_path("examples/parts/mould.json");
  REQUIRE(run_furrow({"partition", part, "--out", dir + "/regions.json", "--grid", "40x40"}).status == 0);
  REQUIRE(run_furrow({"plan", part, "--regions", dir + "/regions.json", "--points", "30", "--out", dir + "/plan"})
              .status == 0);
  REQUIRE(run_furrow({"simulate-measurement", part, "--plan", dir + "/plan/plan.json", "--out", dir + "/m.csv"})
              .status == 0);
  const std::string uri = cluster.new_database("pg_compare");
  const std::string name = PostgresCluster::database_of(uri);
  const auto compare = [&](const std::string& out, const std::string& serial) {
    return run_furrow({"compare", part, "--measurements", dir + "/m.csv", "--plan", dir + "/plan/plan.json", "--out",
                       dir + "/" + out, "--db", uri, "--serial", serial});
  };
  const CliResult first = compare("c1.json", "SN-1");
  REQUIRE(first.status != 2);
  CHECK(first.out.find("stored in " + uri) != std::string::npos);
  // The oracle: the comparison.json the command wrote, counted point by point.
  const std::string written = slurp(dir + "/c1.json");
  const std::size_t points = nlohmann::json::parse(written).at("points").size();
  CHECK(points > 0);
  CHECK(cluster.query(name, "SELECT count(*) FROM points") == std::to_string(points));
  CHECK(cluster.query(name, "SELECT string_agg(role, ',' ORDER BY seq) FROM inputs") ==
        "comparison,part,measurements,plan");
  const CliResult again = compare("c2.json", "SN-1");
  CHECK(again.status == first.status);
  CHECK(again.out.find("not stored again") != std::string::npos);
  const CliResult other = compare("c3.json", "SN-2");
  CHECK(other.status == 2);
  CHECK(other.err.find(uri) != std::string::npos);
  CHECK(line_count(other.err) == 1);
  CHECK(cluster.query(name, "SELECT count(*) FROM parts") == "1");
}
