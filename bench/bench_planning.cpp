// Probe planning on examples/parts/mould.json with the default options at
// 5,000, 10,000 and 100,000 points: regions, allocation, sampling, collision
// checks of every point (ball, shaft, approach path, vertical access),
// ordering and moves (targets on the 2-core machine: 5,000 points under
// 2 s in all; ordering 100,000 points under 5 s). The partition (the
// planner's input, regions.json) is made once beforehand and not timed;
// the program texts and the PNG are timed separately. Best of 5 (of 2 at
// 100,000 points) because the machine is shared. Prints per size the time
// per stage, the peak resident memory so far (getrusage) and the tour
// length against nearest neighbour alone and against the greedy start.
// Prints figures; it does not pass or fail.
//
//   ./build/bench_planning [points] [strategy]     (one size)
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "bench_clock.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "planning/plan_image.hpp"
#include "planning/probe_planner.hpp"

using namespace furrow;
using furrow::bench::peak_rss_mb;
using furrow::bench::seconds_since;

namespace {

void plan_size(const Part& part, const RegionMap& map, long points, const char* strategy) {
  PlannerOptions options;
  options.points = points;
  if (strategy) options.strategy = parse_sampling_strategy(strategy, "strategy");
  const int reps = points > 50000 ? 2 : 5;
  std::printf("\nplan %ld points on mould.json (%zu regions), strategy %s, %d OpenMP threads, best of %d\n", points,
              map.regions.size(), to_string(options.strategy), omp_get_max_threads(), reps);
  double best = std::numeric_limits<double>::infinity();
  PlanResult kept;
  for (int rep = 0; rep < reps; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    PlanResult r = plan_probe_points(part, map, options);
    const double total = seconds_since(t0);
    if (total < best) {
      best = total;
      kept = std::move(r);
    }
  }
  const PlanTiming& t = kept.timing;
  std::printf("total planning               %8.3f s   (%zu points planned)\n", best, kept.plan.points.size());
  std::printf("  regions (domains, finder)  %8.3f s\n", t.regions_seconds);
  std::printf("  sampling                   %8.3f s\n", t.sampling_seconds);
  std::printf("  collision checks           %8.3f s\n", t.access_seconds);
  std::printf("  ordering                   %8.3f s   (%d passes, %s)\n", t.tour_seconds, kept.tour.passes,
              kept.tour.converged ? "converged" : "pass cap");
  std::printf("  moves and cycle time       %8.3f s   (%d straight, %d over the clearance plane)\n", t.moves_seconds,
              kept.cycle.straight_moves, kept.cycle.plane_moves);
  std::printf("peak resident memory so far  %8.1f MB\n", peak_rss_mb());
  std::printf("tour between probe centres: nearest neighbour %.1f mm, greedy start %.1f mm, 2-opt + Or-opt %.1f mm "
              "(%.1f %% shorter than nearest neighbour)\n",
              kept.tour.nearest_neighbour_length, kept.tour.start_length, kept.tour.length,
              100 * (1 - kept.tour.length / kept.tour.nearest_neighbour_length));
  std::printf("cycle time estimate %.1f min\n", kept.cycle.seconds / 60);
  const auto t1 = std::chrono::steady_clock::now();
  const ProbeProgram program = make_probe_program(kept, "bench", options);
  const std::size_t bytes = dmis_program_text(program).size() + ippdme_program_text(program).size();
  const double texts = seconds_since(t1);
  const auto t2 = std::chrono::steady_clock::now();
  const std::size_t png = plan_image_png(part, map, kept).size();
  std::printf("DMIS + I++ texts %.3f s (%.1f kB), PNG %.3f s (%.1f kB), not in the total\n", texts, bytes / 1024.0,
              seconds_since(t2), png / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const RegionMap map = partition_part(part, {}).map;
  const char* strategy = argc > 2 ? argv[2] : nullptr;
  if (argc > 1) {
    plan_size(part, map, std::atol(argv[1]), strategy);
  } else {
    for (const long points : {5000L, 10000L, 100000L}) plan_size(part, map, points, strategy);
  }
  return 0;
}
