// Full curvature partition (field + classes + components + merging +
// statistics + borders) of examples/parts/mould.json at 1000 x 1000 cells
// (target < 0.3 s on the 2-core machine). Prints the total and the
// split between curvature evaluation and region work, best of 5 because the
// machine is shared; writing regions.json is timed separately (not part of
// the target). Prints figures; it does not pass or fail.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "partition/regions_file.hpp"

using namespace furrow;

int main(int argc, char** argv) {
  const int cells = argc > 1 ? std::atoi(argv[1]) : 1000;
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  PartitionOptions options;
  options.grid = GridSize{cells, cells};
  std::printf("partition of mould.json, %dx%d cells, %d OpenMP threads, best of 5\n", cells, cells,
              omp_get_max_threads());
  double best_total = std::numeric_limits<double>::infinity(), field = 0, regions = 0, json = 0;
  std::size_t count = 0, bytes = 0;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    const PartitionResult result = partition_part(part, options);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto t1 = std::chrono::steady_clock::now();
    const std::string text = regions_to_json_text(result.map);
    const double js = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    if (total < best_total) {
      best_total = total;
      field = result.timing.field_seconds;
      regions = result.timing.region_seconds;
      json = js;
      count = result.map.regions.size();
      bytes = text.size();
    }
  }
  std::printf("total partition              %8.3f s   (%zu regions)\n", best_total, count);
  std::printf("  curvature field            %8.3f s   (%.2f M cells/s)\n", field,
              cells * static_cast<double>(cells) / field / 1e6);
  std::printf("  regions (classes, components, merge, stats, borders) %8.3f s\n", regions);
  std::printf("  other (grid choice, fingerprint, freeing)  %8.3f s\n", best_total - field - regions);
  std::printf("regions.json text            %8.3f s   (%.1f kB, not in the total)\n", json,
              bytes / 1024.0);
  return 0;
}
