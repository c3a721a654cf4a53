// The results database under the two things a shop does to it: several
// compares storing at once, and a writer killed in the middle of a part
// (kill -9, a power cut's nearest relative a test can make). The oracle is
// the file read with SQLite's own integrity check and counted by raw SQL:
// every part present is complete, none is lost.
#include <doctest/doctest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "results/results_database.hpp"
#include "results/results_records.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr std::size_t kPoints = 20000;  // a large comparison: its transaction takes a while

// Each query's single value as an integer, on a raw connection.
long long raw_count(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(s) == SQLITE_ROW);
  const long long n = sqlite3_column_int64(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return n;
}

std::string integrity(const std::string& path) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  std::string out;
  REQUIRE(sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &s, nullptr) == SQLITE_OK);
  while (sqlite3_step(s) == SQLITE_ROW) out += reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
  sqlite3_finalize(s);
  sqlite3_close(db);
  return out;
}

// A child process storing parts; never returns.
[[noreturn]] void store_in_child(const std::string& path, const std::string& prefix, std::uint64_t first_identity,
                                 std::size_t parts, std::size_t points, int progress_fd) {
  try {
    auto db = open_results_database(path, DatabaseAccess::write);
    for (std::size_t k = 0; parts == 0 || k < parts; ++k) {
      const ComparisonRecord r = made_up_record(prefix + std::to_string(k), first_identity + k, points,
                                                static_cast<std::uint32_t>(k));
      if (progress_fd >= 0 && ::write(progress_fd, "B", 1) != 1) _exit(3);  // a store begins
      if (db->store(r) != StoreResult::stored) _exit(4);
      if (progress_fd >= 0 && ::write(progress_fd, "C", 1) != 1) _exit(3);  // and is committed
    }
  } catch (...) {
    _exit(1);
  }
  _exit(0);
}

}  // namespace

TEST_CASE("results database: two processes storing 20 parts each at once lose nothing") {
  const std::string path = scratch_dir("results-db-concurrent") + "/results.db";
  // Both start on a file that does not exist yet: creating it races too.
  pid_t children[2];
  for (int c = 0; c < 2; ++c) {
    children[c] = ::fork();
    REQUIRE(children[c] >= 0);
    if (children[c] == 0) store_in_child(path, c == 0 ? "A-" : "B-", 1000u * (c + 1), 20, 2000, -1);
  }
  for (pid_t child : children) {
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
  CHECK(integrity(path) == "ok");
  CHECK(raw_count(path, "SELECT count(*) FROM parts") == 40);
  CHECK(raw_count(path, "SELECT count(*) FROM parts WHERE serial LIKE 'A-%'") == 20);
  CHECK(raw_count(path, "SELECT count(*) FROM points") == 40 * 2000);
  auto db = open_results_database(path, DatabaseAccess::read);
  CHECK(db->parts().size() == 40);
}

TEST_CASE("results database: a writer killed with SIGKILL mid-part leaves only complete parts") {
  std::mt19937 rng(20261128);  // the moments of the kills
  int killed_mid_store = 0;
  for (int round = 0; round < 4; ++round) {
    CAPTURE(round);
    const std::string path = scratch_dir("results-db-kill-" + std::to_string(round)) + "/results.db";
    int pipe_fds[2];
    REQUIRE(::pipe(pipe_fds) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(pipe_fds[0]);
      store_in_child(path, "K-", 1, 0, kPoints, pipe_fds[1]);
    }
    ::close(pipe_fds[1]);
    // Wait for the first part to be committed, then kill at a seeded moment.
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
    long long committed = static_cast<long long>(std::count(progress.begin(), progress.end(), 'C'));
    // Killed between a commit and its 'C': one part more than counted.
    const bool last_unconfirmed = progress.back() == 'B';

    // Opened again (SQLite recovers the write-ahead log): sound, and exactly the complete parts.
    auto db = open_results_database(path, DatabaseAccess::write);
    const std::vector<StoredPart> parts = db->parts();
    CHECK(integrity(path) == "ok");
    const long long present = static_cast<long long>(parts.size());
    CHECK((present == committed || (last_unconfirmed && present == committed + 1)));
    killed_mid_store += last_unconfirmed && present == committed;
    committed = present;
    CHECK(raw_count(path, "SELECT count(*) FROM points") == committed * static_cast<long long>(kPoints));
    CHECK(raw_count(path, "SELECT count(*) FROM parts p WHERE (SELECT count(*) FROM points q WHERE "
                          "q.part_key = p.part_key) <> " + std::to_string(kPoints)) == 0);
    CHECK(raw_count(path, "SELECT count(*) FROM regions") == committed * 3);
    CHECK(raw_count(path, "SELECT count(*) FROM inputs") == committed * 2);
    // And it takes the next part.
    CHECK(db->store(made_up_record("after", 999999, 10, 1)) == StoreResult::stored);
  }
  // Most of a writer's time is inside a part's transaction: the kills must
  // have hit one there, or the test did not test what it says.
  CHECK(killed_mid_store >= 2);
}
