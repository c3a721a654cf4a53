// The results database and SPC at batch size (targets: storing a part under
// 20 ms, `furrow spc` over every characteristic under 2 s): PARTS parts of
// POINTS points each (default 1,000 x 300; the records are the results
// tests' made-up ones, tests/results/results_records.hpp) stored one by one
// in a fresh SQLite file, each store timed (mean, median, 99th percentile,
// worst); then `furrow spc --db ... --out ...` run as a user runs it, by
// point and by region, timed whole after its steps are timed one by one
// in this process (reading, statistics, each document rendered in memory) (median of 3 wall-clock seconds, and the
// CPU seconds of the child processes over the three). Prints figures; it
// does not pass or fail. With a third argument the same runs on PostgreSQL
// (docs/results_database.md "PostgreSQL"): `postgres` starts a throwaway
// cluster as the tests do (tests/results/postgres_cluster.hpp; with fsync
// on, as a production server commits), a
// postgresql:// location names an empty database of a running server.
//   usage: bench_spc [PARTS [POINTS [postgres|LOCATION]]]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_clock.hpp"
#include "results/postgres_cluster.hpp"
#include "results/results_database.hpp"
#include "results/results_records.hpp"
#include "results/spc_html.hpp"
#include "results/spc_json.hpp"
#include "results/spc_qif.hpp"

using namespace furrow;
using furrow::bench::seconds_since;

namespace {

double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Median of 3 runs of the command [s], and the CPU seconds of all three.
void time_command(const std::string& what, const std::string& command) {
  std::vector<double> wall;
  const double cpu0 = children_cpu_seconds();
  for (int k = 0; k < 3; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    wall.push_back(seconds_since(t0));
    // furrow spc exits 1 on a process signal: a result, not a failure.
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) > 1) {
      std::printf("%s: the command failed (status %d): %s\n", what.c_str(), status, command.c_str());
      std::exit(3);
    }
  }
  std::sort(wall.begin(), wall.end());
  std::printf("%-26s %7.3f s wall (median of 3)  %7.3f s CPU per run\n", what.c_str(), wall[1],
              (children_cpu_seconds() - cpu0) / 3);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t parts = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000;
  const std::size_t points = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 300;
  const std::string backend = argc > 3 ? argv[3] : "";
  if (parts < 2 || points < 1) {
    std::fprintf(stderr, "usage: bench_spc [PARTS >= 2 [POINTS >= 1 [postgres|LOCATION]]]\n");
    return 2;
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "furrow-bench-spc";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string db_path = (dir / "results.db").string();
  std::unique_ptr<test::PostgresCluster> cluster;
  if (backend == "postgres") {
    cluster = std::make_unique<test::PostgresCluster>(/*durable=*/true);
    db_path = cluster->new_database("bench_spc");
  } else if (!backend.empty()) {
    db_path = backend;
  }
  const bool is_file = backend.empty();

  std::vector<double> store_ms;
  {
    const std::unique_ptr<ResultsDatabase> db = open_results_database(db_path, DatabaseAccess::write);
    for (std::size_t k = 0; k < parts; ++k) {
      char serial[32];
      std::snprintf(serial, sizeof serial, "SN-%05zu", k + 1);
      const ComparisonRecord record = test::made_up_record(serial, k + 1, points, static_cast<std::uint32_t>(k));
      const auto t0 = std::chrono::steady_clock::now();
      db->store(record);
      store_ms.push_back(1000 * seconds_since(t0));
    }
  }
  double sum = 0;
  for (double t : store_ms) sum += t;
  std::vector<double> sorted = store_ms;
  std::sort(sorted.begin(), sorted.end());
  if (is_file)
    std::printf("stored %zu parts x %zu points in %s (%.1f MB)\n", parts, points, db_path.c_str(),
                static_cast<double>(std::filesystem::file_size(db_path)) / 1e6);
  else
    std::printf("stored %zu parts x %zu points in PostgreSQL %s\n", parts, points, db_path.c_str());
  std::printf("store per part: mean %.2f ms  median %.2f ms  p99 %.2f ms  worst %.2f ms  (target < 20 ms)\n",
              sum / static_cast<double>(parts), sorted[parts / 2], sorted[(parts * 99) / 100], sorted.back());

  {
    // The command's steps, by point, one by one.
    const std::unique_ptr<ResultsDatabase> db = open_results_database(db_path, DatabaseAccess::read);
    auto t0 = std::chrono::steady_clock::now();
    const SpcInput input = load_spc_input(*db, SpcBy::point, {});
    std::printf("steps: read %.3f s", seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    const SpcResult result = compute_spc(input);
    std::printf("  statistics %.3f s", seconds_since(t0));
    const SpcSelection selection{db_path, {}};
    t0 = std::chrono::steady_clock::now();
    std::size_t bytes = spc_json(result, selection).size();
    std::printf("  spc.json %.3f s", seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    bytes += spc_html(result, selection).size();
    std::printf("  spc.html %.3f s", seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    bytes += spc_qif(result, selection).size();
    std::printf("  spc.qif %.3f s  (%.1f MB rendered)\n", seconds_since(t0), static_cast<double>(bytes) / 1e6);
  }

  const std::string cli = FURROW_CLI;
  const std::string base = cli + " spc --db " + test::shell_quote(db_path) + " --out " + (dir / "spc").string();
  time_command("furrow spc (by point)", base + " > /dev/null");
  time_command("furrow spc --by region", base + "-regions --by region > /dev/null");
  for (const char* name : {"spc.json", "spc.html", "spc.qif"})
    std::printf("  %s: %.1f MB\n", name, static_cast<double>(std::filesystem::file_size(dir / "spc" / name)) / 1e6);
  std::filesystem::remove_all(dir);
  return 0;
}
