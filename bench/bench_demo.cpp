// The whole `furrow demo`: examples/jobs/demo.json run
// end to end in memory (everything but writing the folder), 3 times; prints
// each stage's wall time and the total of every run, and the median total
// (target < 2 s on the 2-core machine). Prints figures; it does not pass or
// fail.
//   usage: bench_demo [RUNS]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "job/job.hpp"
#include "job/pipeline.hpp"

using namespace furrow;

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const Job job = read_job(std::string(FURROW_SOURCE_DIR) + "/examples/jobs/demo.json");
  std::printf("furrow demo pipeline (%s), %d threads, %d runs\n", job.file.c_str(), omp_get_max_threads(), runs);
  std::vector<double> totals;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const PipelineResult result = run_job(job);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("run %d:", r + 1);
    for (const StageTime& t : result.stages) std::printf(" %s %.2f s;", t.stage.c_str(), t.seconds);
    std::printf(" total %.2f s (%s, %zu files)\n", wall, to_string(result.verdict), result.files.size());
    totals.push_back(wall);
  }
  std::sort(totals.begin(), totals.end());
  std::printf("median total %.2f s (target < 2 s)\n", totals[totals.size() / 2]);
  return 0;
}
