// `furrow compare --db --serial` and `furrow import-results` as a user runs
// them: parts land in the database (counted with SQLite's own API, the
// test's oracle), the same comparison is not stored twice, and a database
// that is not Furrow's or a missing serial stops the command before it
// writes anything.
#include <doctest/doctest.h>
#include <sqlite3.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

using namespace furrow::test;
namespace fs = std::filesystem;

namespace {

std::string query(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  std::string out;
  REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
  if (sqlite3_step(s) == SQLITE_ROW && sqlite3_column_text(s, 0))
    out = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
  sqlite3_finalize(s);
  sqlite3_close(db);
  return out;
}

// The SHA-256 by coreutils, an implementation other than Furrow's.
std::string sha256sum(const std::string& path) {
  FILE* pipe = ::popen(("sha256sum " + shell_quote(path)).c_str(), "r");
  REQUIRE(pipe);
  char hex[65] = {0};
  const std::size_t n = std::fread(hex, 1, 64, pipe);
  ::pclose(pipe);
  REQUIRE(n == 64);
  return std::string(hex, 64);
}

std::string batch_part() { return source_path("examples/parts/mould.json"); }

struct Batch {
  std::string dir, part, plan, m1, m2;
};

// A plan of the mould and two measurements of it (different noise).
const Batch& batch() {
  static const Batch b = [] {
    Batch b;
    b.dir = scratch_dir("cli-results-db");
    b.part = source_path("examples/parts/mould.json");
    REQUIRE(run_furrow({"partition", b.part, "--out", b.dir + "/regions.json", "--grid", "40x40"}).status == 0);
    REQUIRE(run_furrow({"plan", b.part, "--regions", b.dir + "/regions.json", "--points", "30", "--out",
                        b.dir + "/plan"}).status == 0);
    b.plan = b.dir + "/plan/plan.json";
    b.m1 = b.dir + "/m1.csv";
    b.m2 = b.dir + "/m2.csv";
    REQUIRE(run_furrow({"simulate-measurement", b.part, "--plan", b.plan, "--out", b.m1, "--seed", "1"}).status == 0);
    REQUIRE(run_furrow({"simulate-measurement", b.part, "--plan", b.plan, "--out", b.m2, "--seed", "2"}).status == 0);
    return b;
  }();
  return b;
}

CliResult compare(const std::string& m, const std::string& out, std::vector<std::string> more) {
  std::vector<std::string> words = {"compare", batch().part, "--measurements", m, "--plan", batch().plan, "--out", out};
  words.insert(words.end(), more.begin(), more.end());
  return run_furrow(words);
}

}  // namespace

TEST_CASE("cli results database: compare --db stores a part once, and refuses what it cannot store") {
  const Batch& b = batch();
  const std::string dir = scratch_dir("cli-results-db-compare");
  const std::string db = dir + "/results.db";
  const CliResult first = compare(b.m1, dir + "/c1.json", {"--db", db, "--serial", "SN-1"});
  REQUIRE(first.status == 0);
  CHECK(first.out.find("stored in " + db) != std::string::npos);
  CHECK(query(db, "SELECT count(*) FROM parts") == "1");
  CHECK(query(db, "SELECT serial FROM parts") == "SN-1");
  CHECK(query(db, "SELECT count(*) FROM points") == query(db, "SELECT count(*) FROM points WHERE part_key = 1"));
  CHECK(query(db, "SELECT count(*) FROM points") != "0");
  // Every input's digest: the comparison, part, measurements and plan.
  CHECK(query(db, "SELECT group_concat(role, ',') FROM inputs") == "comparison,part,measurements,plan");
  CHECK(query(db, "SELECT plan_fingerprint = (SELECT sha256 FROM inputs WHERE role = 'plan') FROM parts") == "1");

  SUBCASE("the same comparison again is not stored twice, under another serial refused") {
    const CliResult again = compare(b.m1, dir + "/c1b.json", {"--db", db, "--serial", "SN-1"});
    CHECK(again.status == 0);
    CHECK(again.out.find("not stored again") != std::string::npos);
    const CliResult other = compare(b.m1, dir + "/c1c.json", {"--db", db, "--serial", "SN-9"});
    CHECK(other.status == 2);
    CHECK(other.err.find(db) != std::string::npos);
    CHECK(query(db, "SELECT count(*) FROM parts") == "1");
  }
  SUBCASE("FURROW_DB in the environment, and a serial that looks like SQL") {
    ::setenv("FURROW_DB", db.c_str(), 1);
    const CliResult env = compare(b.m2, dir + "/c2.json", {"--serial", "'; DROP TABLE parts; --"});
    ::unsetenv("FURROW_DB");
    CHECK(env.status == 0);
    CHECK(query(db, "SELECT count(*) FROM parts") == "2");
    CHECK(query(db, "SELECT serial FROM parts WHERE part_key = 2") == "'; DROP TABLE parts; --");
  }
  SUBCASE("without --serial, or --serial without a database: exit 2 before anything is written") {
    const CliResult no_serial = compare(b.m2, dir + "/c3.json", {"--db", db});
    CHECK(no_serial.status == 2);
    CHECK(no_serial.err.find("--serial") != std::string::npos);
    CHECK(!fs::exists(dir + "/c3.json"));
    const CliResult no_db = compare(b.m2, dir + "/c4.json", {"--serial", "SN-4"});
    CHECK(no_db.status == 2);
    CHECK(!fs::exists(dir + "/c4.json"));
  }
  SUBCASE("a database file that is not Furrow's: exit 2 naming it, nothing written") {
    write_text(dir + "/other.db", "a spreadsheet, not a database\n");
    const std::string before = slurp(dir + "/other.db");
    const CliResult foreign = compare(b.m2, dir + "/c5.json", {"--db", dir + "/other.db", "--serial", "SN-5"});
    CHECK(foreign.status == 2);
    CHECK(foreign.err.find(dir + "/other.db") != std::string::npos);
    CHECK(line_count(foreign.err) == 1);
    CHECK(!fs::exists(dir + "/c5.json"));
    CHECK(slurp(dir + "/other.db") == before);
  }
  SUBCASE("a compare that fails before storing leaves no new database behind") {
    // Measurements that are no measurements: exit 2 after the database was checked.
    write_text(dir + "/broken.csv", "id,x,y,z\nP1,1,2\n");
    const CliResult broken = compare(dir + "/broken.csv", dir + "/c6.json", {"--db", dir + "/new.db", "--serial", "SN-6"});
    CHECK(broken.status == 2);
    CHECK(broken.err.find("broken.csv") != std::string::npos);
    CHECK(!fs::exists(dir + "/new.db"));
    CHECK(!fs::exists(dir + "/new.db-wal"));
    // A new database in a folder that does not exist: exit 2 before the comparison is made.
    const CliResult no_folder =
        compare(b.m2, dir + "/c7.json", {"--db", dir + "/missing/new.db", "--serial", "SN-7"});
    CHECK(no_folder.status == 2);
    CHECK(no_folder.err.find(dir + "/missing/new.db") != std::string::npos);
    CHECK(!fs::exists(dir + "/c7.json"));
  }
}

TEST_CASE("cli results database: import-results stores folders under their names, once") {
  const Batch& b = batch();
  const std::string dir = scratch_dir("cli-results-db-import");
  fs::create_directories(dir + "/SN-10");
  fs::create_directories(dir + "/SN-11");
  REQUIRE(compare(b.m1, dir + "/SN-10/comparison.json", {}).status == 0);
  REQUIRE(compare(b.m2, dir + "/SN-11/comparison.json", {}).status == 0);
  const std::string db = dir + "/results.db";
  const CliResult first = run_furrow({"import-results", "--db", db, dir + "/SN-10", dir + "/SN-11"});
  REQUIRE(first.status == 0);
  CHECK(first.out.find("2 of 2 comparisons stored") != std::string::npos);
  CHECK(query(db, "SELECT group_concat(serial, ',') FROM parts") == "SN-10,SN-11");
  CHECK(query(db, "SELECT comparison_sha256 FROM parts WHERE part_key = 1") ==
        sha256sum(dir + "/SN-10/comparison.json"));
  CHECK(query(db, "SELECT sha256 FROM inputs WHERE role = 'comparison' AND part_key = 2") ==
        sha256sum(dir + "/SN-11/comparison.json"));
  CHECK(query(db, "SELECT sha256 FROM inputs WHERE role = 'part' AND part_key = 1") == sha256sum(b.part));
  const CliResult again = run_furrow({"import-results", "--db", db, dir + "/SN-10", dir + "/SN-11"});
  CHECK(again.status == 0);
  CHECK(again.out.find("0 of 2 comparisons stored") != std::string::npos);
  CHECK(query(db, "SELECT count(*) FROM parts") == "2");
  // A folder without a comparison: exit 2 before the first part is stored.
  fs::create_directories(dir + "/SN-12");
  const std::string db2 = dir + "/second.db";
  const CliResult missing = run_furrow({"import-results", "--db", db2, dir + "/SN-10", dir + "/SN-12"});
  CHECK(missing.status == 2);
  CHECK(missing.err.find(dir + "/SN-12") != std::string::npos);
  CHECK(!fs::exists(db2));
}

TEST_CASE("cli results database: run --db stores the job's part under the inspection record's serial") {
  const std::string dir = scratch_dir("cli-results-db-run");
  const std::string db = dir + "/results.db";
  const std::string job = source_path("examples/jobs/demo.json");
  // No serial anywhere: refused before the job runs.
  const CliResult no_serial = run_furrow({"run", job, "--out", dir + "/none", "--db", db});
  CHECK(no_serial.status == 2);
  CHECK(no_serial.err.find("--serial") != std::string::npos);
  CHECK(!fs::exists(dir + "/none"));
  CHECK(!fs::exists(db));
  const CliResult r = run_furrow({"run", job, "--out", dir + "/out", "--db", db, "--record",
                                  source_path("examples/records/mould_first_article.json")});
  CHECK(r.status == 1);  // the demo's confirmed gouge
  CHECK(r.out.find("stored in " + db) != std::string::npos);
  CHECK(query(db, "SELECT serial || '|' || operator || '|' || cmm || '|' || verdict FROM parts") ==
        "SN-0042|J. Doe|bridge CMM, 700 x 1000 x 600|FAIL");
  // The digest stored is that of the comparison.json the job wrote.
  CHECK(query(db, "SELECT comparison_sha256 FROM parts") == sha256sum(dir + "/out/comparison.json"));
  CHECK(query(db, "SELECT count(*) FROM points") != "0");
  // The report was rendered before the part was stored: it shows the part
  // after the stored ones (none), region means as comparison.json has them.
  const nlohmann::json report = nlohmann::json::parse(slurp(dir + "/out/report.json"));
  const nlohmann::json& process = report["process"];
  REQUIRE(process.is_object());
  CHECK(process["stored"] == false);
  CHECK(process["serial"] == "SN-0042");
  CHECK(process["parts"] == 1);
  const nlohmann::json comparison = nlohmann::json::parse(slurp(dir + "/out/comparison.json"));
  REQUIRE(process["regions"].size() == comparison["regions"].size());
  for (std::size_t k = 0; k < process["regions"].size(); ++k) {
    CHECK(process["regions"][k]["region"] == comparison["regions"][k]["region"]);
    CHECK(process["regions"][k]["recent"][0]["value"] == comparison["regions"][k]["mean"]);
  }
}

TEST_CASE("cli results database: compare --scan --db stores a scan's regions and spc follows them") {
  // Three scans of the mould with a dent on the dome's flank growing from
  // 5 to 15 um deep (inside the zone): each part stored as its regions (a scan has no
  // planned points), the rows equal to comparison.json's region statistics
  // (read back by SQLite's own API), and `spc --by region` follows them.
  const std::string dir = scratch_dir("cli-results-db-scan");
  const std::string db = dir + "/results.db";
  const std::string regions = dir + "/regions.json";
  REQUIRE(run_furrow({"partition", batch_part(), "--out", regions, "--grid", "40x40"}).status == 0);
  std::vector<nlohmann::json> docs;
  for (int k = 1; k <= 3; ++k) {
    const std::string ply = dir + "/scan" + std::to_string(k) + ".ply";
    const std::string out = dir + "/c" + std::to_string(k) + ".json";
    REQUIRE(run_furrow({"simulate-measurement", batch_part(), "--scan", "--out", ply, "--stripe-pitch", "1.2",
                        "--point-pitch", "1.2", "--view", "0.1,0.2,-1", "--seed", std::to_string(k), "--misalign",
                        "3,-2,40,5,10,-20", "--bump", "30,40,28.85,8," + std::to_string(-0.005 * k)})
                .status == 0);
    const CliResult r = run_furrow({"compare", batch_part(), "--scan", ply, "--regions", regions, "--out", out,
                                    "--voxel", "2", "--db", db, "--serial", "SCAN-" + std::to_string(k)});
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(r.out.find("stored in " + db + ": part \"SCAN-" + std::to_string(k) + "\", a scan") != std::string::npos);
    docs.push_back(nlohmann::json::parse(slurp(out)));
    const std::string key = "(SELECT part_key FROM parts WHERE serial = 'SCAN-" + std::to_string(k) + "')";
    CHECK(query(db, "SELECT comparison_sha256 FROM parts WHERE part_key = " + key) == sha256sum(out));
    CHECK(query(db, "SELECT count(*) FROM points WHERE part_key = " + key) == "0");
    const nlohmann::json& written = docs.back()["summary"]["regions"];
    REQUIRE(written.size() > 1);
    CHECK(query(db, "SELECT count(*) FROM regions WHERE part_key = " + key) == std::to_string(written.size()));
    for (const nlohmann::json& region : written) {
      const std::string where = " FROM regions WHERE part_key = " + key +
                                " AND region = " + std::to_string(region["region"].get<int>());
      CHECK(query(db, "SELECT count" + where) == std::to_string(region["deviations"]["count"].get<std::size_t>()));
      // REAL columns hold the double exactly; SQLite prints 15 digits.
      CHECK(std::abs(std::stod(query(db, "SELECT mean" + where)) - region["deviations"]["mean"].get<double>()) <
            1e-15);
    }
    // The scan was stored once: the same comparison again is not stored.
    if (k == 1) {
      const CliResult again = run_furrow({"compare", batch_part(), "--scan", ply, "--regions", regions, "--out",
                                          dir + "/again.json", "--voxel", "2", "--db", db, "--serial", "SCAN-1"});
      CHECK(again.status == 0);
      CHECK(again.out.find("already in " + db) != std::string::npos);
    }
  }
  // The QA report of the last scan shows its place in the batch: the third
  // of three stored parts, each region's recent means as stored.
  const CliResult report = run_furrow({"report", dir + "/c3.json", "--out", dir + "/report", "--db", db});
  REQUIRE_MESSAGE(report.status == 0, report.err);
  const nlohmann::json process = nlohmann::json::parse(slurp(dir + "/report/report.json"))["process"];
  REQUIRE(process.is_object());
  CHECK(process["stored"] == true);
  CHECK(process["serial"] == "SCAN-3");
  CHECK(process["parts"] == 3);
  CHECK(process["position"] == 2);  // 0-based
  REQUIRE(process["regions"].size() == docs[2]["summary"]["regions"].size());
  for (std::size_t r = 0; r < process["regions"].size(); ++r) {
    const nlohmann::json& recent = process["regions"][r]["recent"];
    REQUIRE(recent.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(recent[k]["serial"] == "SCAN-" + std::to_string(k + 1));
      for (const nlohmann::json& region : docs[k]["summary"]["regions"])
        if (region["region"] == process["regions"][r]["region"])
          CHECK(recent[k]["value"].get<double>() == region["deviations"]["mean"].get<double>());
    }
  }

  // By point a scan gives nothing to follow: inconclusive, nothing written.
  const CliResult by_point = run_furrow({"spc", "--db", db, "--out", dir + "/spc-points"});
  CHECK(by_point.status == 4);
  CHECK(by_point.err.find("--by region") != std::string::npos);
  CHECK(!fs::exists(dir + "/spc-points"));
  const CliResult spc = run_furrow({"spc", "--db", db, "--out", dir + "/spc", "--by", "region"});
  REQUIRE_MESSAGE((spc.status == 0 || spc.status == 1), spc.err);
  const nlohmann::json chart = nlohmann::json::parse(slurp(dir + "/spc/spc.json"));
  REQUIRE(chart["parts"].size() == 3);
  REQUIRE(chart["characteristics"].size() == docs[0]["summary"]["regions"].size());
  std::string deepest;
  double deepest_mean = 0;
  for (const nlohmann::json& c : chart["characteristics"]) {
    const std::string id = c["id"];
    CAPTURE(id);
    REQUIRE(c["values"].size() == 3);
    for (int k = 0; k < 3; ++k)
      for (const nlohmann::json& region : docs[static_cast<std::size_t>(k)]["summary"]["regions"])
        if (std::to_string(region["region"].get<int>()) == id)
          CHECK(c["values"][k].get<double>() == region["deviations"]["mean"].get<double>());
    if (c["values"][2].get<double>() < deepest_mean) deepest = id, deepest_mean = c["values"][2].get<double>();
  }
  // The region holding the dent reads it deepening part after part.
  REQUIRE(!deepest.empty());
  for (const nlohmann::json& c : chart["characteristics"])
    if (c["id"] == deepest) {
      CHECK(c["values"][0].get<double>() > c["values"][1].get<double>());
      CHECK(c["values"][1].get<double>() > c["values"][2].get<double>());
    }
}
