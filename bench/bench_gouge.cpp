// Local gouge checks per second (target >= 2 million per second on 2
// cores): a bull-nose end mill (diameter 10, corner radius 2) at every node
// of a 1000 x 1000 grid over the mould example. Each check is the whole job
// per contact point: surface evaluation with second derivatives, curvature
// analysis, border detection, cutter curvature and the directional
// comparison. Also the comparison alone on precomputed part geometry.
// Besides wall-clock rates it prints checks per CPU-second (process CPU time
// over all threads): on a machine shared with other jobs the wall clock
// understates what the cores do, the CPU time does not.
// Prints figures; it does not pass or fail.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

#include "io/part_file.hpp"
#include "machining/gouge/compound_border.hpp"
#include "machining/cutter/face_seeds.hpp"

using namespace furrow;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main() {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const Face& face = part.faces[0];
  const Cutter bull("BULL-D10-R2", 5, 2);
  const int n = 1000;
  const GougeOptions options;
  const BorderLocator locator(part);
  const ParameterDomain& d = face.domain();
  std::printf("mould.json, %s, %d x %d grid, %d threads, best of 3\n", bull.name().c_str(), n, n,
              omp_get_max_threads());

  double best = 0, best_cpu = 0;
  long gouges = 0, quick = 0;
  for (int rep = 0; rep < 3; ++rep) {
    long g = 0, q = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
#pragma omp parallel for schedule(dynamic, 8) reduction(+ : g, q)
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const Eigen::Vector2d uv(grid_parameter(d.u0, d.u1, i, n), grid_parameter(d.v0, d.v1, j, n));
        const LocalGouge r = check_contact(bull, contact_surfaces(locator, 0, uv), options);
        g += r.gouges();
        q += r.quick;
      }
    }
    best = std::max(best, 1.0 * n * n / seconds_since(t0));
    best_cpu = std::max(best_cpu, 1.0 * n * n / (double(std::clock() - c0) / CLOCKS_PER_SEC));
    gouges = g;
    quick = q;
  }
  std::printf("full check (evaluate + curvature + border + compare)  %6.2f M checks/s   "
              "(%ld gouging, %.1f%% quick-accepted)\n",
              best / 1e6, gouges, 100.0 * quick / (1.0 * n * n));
  std::printf("  per CPU-second %.2f M, i.e. %.2f M checks/s on %d otherwise idle cores\n",
              best_cpu / 1e6, omp_get_max_threads() * best_cpu / 1e6, omp_get_max_threads());

  // The comparison alone, on geometry precomputed for a 100-row slab.
  const int rows = 100;
  std::vector<DifferentialGeometry> slab(static_cast<std::size_t>(rows) * n);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < n; ++j)
      slab[static_cast<std::size_t>(i) * n + j] =
          face.geometry(grid_parameter(d.u0, d.u1, i * 10, n), grid_parameter(d.v0, d.v1, j, n));
  for (const bool quick_accept : {true, false}) {
    GougeOptions o = options;
    o.quick_accept = quick_accept;
    double best_cmp = 0;
    long g = 0;
    for (int rep = 0; rep < 3; ++rep) {
      long count = 0;
      const auto t0 = std::chrono::steady_clock::now();
      for (int pass = 0; pass < 10; ++pass) {
#pragma omp parallel for schedule(static) reduction(+ : count)
        for (long k = 0; k < static_cast<long>(slab.size()); ++k)
          count += check_local_gouge(bull, slab[static_cast<std::size_t>(k)], o).gouges();
      }
      best_cmp = std::max(best_cmp, 10.0 * slab.size() / seconds_since(t0));
      g = count / 10;
    }
    std::printf("comparison only, quick accept %-3s                      %6.2f M checks/s   "
                "(%ld of %zu gouging)\n",
                quick_accept ? "on" : "off", best_cmp / 1e6, g, slab.size());
  }
  return 0;
}
