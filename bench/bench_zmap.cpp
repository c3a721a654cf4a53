// Z-map of the mould example finished with a generated path, ball 6 mm, at
// two sizes:
//   - the furrow toolpath defaults: tolerance 0.01 mm, scallop 0.005 mm,
//     z-map at 0.05 mm (about 3 M nodes, 5 k moves);
//   - a fine finish: tolerance 0.001 mm, scallop 0.0005 mm (a real path with
//     about ten times the moves, ~50 k), z-map at 0.044 mm (about 4 M nodes).
// For each prints moves, nodes, the sweep's seconds (best of 3; target for
// the fine case < 5 s for sweep and error map together on the 2-core
// machine) and the error map's seconds, separately. For the default case
// also the rapid check of the same path as `furrow toolpath` writes it (a
// rapid up, over and down per pass, samples at the z-map spacing). Prints
// figures; it does not pass or fail. Threads: OMP_NUM_THREADS (default all).
//   usage: bench_zmap [default|fine|all]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "io/part_file.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/rapid_check.hpp"
#include "machining/prediction/zmap.hpp"
#include "machining/toolpath/contact_planning.hpp"
#include "machining/toolpath/toolpath_generation.hpp"

using namespace furrow;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Case {
  const char* name;
  double tolerance, scallop, resolution;
  bool rapids;
};

void run_case(const Part& part, const Cutter& ball, const Case& c) {
  ContactPlanOptions options;
  options.forward.tolerance = c.tolerance;
  options.scallop = c.scallop;
  auto t0 = std::chrono::steady_clock::now();
  const ContactPlan plan = plan_contact_points(part, ball, {PassDirection::along_u, 0}, options);
  const double planning = seconds_since(t0);
  const std::vector<ZMapMove> moves = moves_from_toolpath(plan_tips(plan));
  std::printf("%s: mould, ball 6 mm, tolerance %g mm, scallop %g mm, %d threads\n", c.name, c.tolerance, c.scallop,
              omp_get_max_threads());
  std::printf("  path: %zu passes, %zu contact points, %zu moves (planned in %.2f s)\n", plan.passes.size(),
              plan.points, moves.size(), planning);
  double best = 1e300, map_best = 1e300;
  std::size_t nodes = 0, cut = 0;
  ErrorMap map;
  for (int run = 0; run < 3; ++run) {
    ZMap zmap(part_xy_extent(part), c.resolution);
    t0 = std::chrono::steady_clock::now();
    zmap.cut(ball, moves);
    best = std::min(best, seconds_since(t0));
    nodes = zmap.node_count();
    cut = zmap.cut_node_count();
    if (run == 2) {
      t0 = std::chrono::steady_clock::now();
      map = compute_error_map(part, zmap);
      map_best = seconds_since(t0);
    }
  }
  std::printf("  z-map sweep: %.3g mm, %zu nodes (%zu cut), %zu moves: %.3f s (best of 3)\n", c.resolution, nodes,
              cut, moves.size(), best);
  std::printf("  error map: %zu samples: %.3f s; max undercut %.2f um, max overcut %.2f um\n", map.samples, map_best,
              map.max_undercut.error * 1000, map.max_overcut.error * 1000);
  std::printf("  sweep + error map: %.3f s\n", best + map_best);
  if (!c.rapids) return;
  const double safe_z = part.control_box().max().z() + 5;
  const Toolpath written = parse_gcode(toolpath_to_gcode(plan_tips(plan), safe_z, 1000, "bench"), "bench.nc");
  RapidCheckOptions rapid;
  rapid.sample_spacing = c.resolution;
  double rapid_best = 1e300;
  RapidCheck check;
  for (int run = 0; run < 3; ++run) {
    t0 = std::chrono::steady_clock::now();
    check = check_rapids(part, ball, written.rapids, rapid);
    rapid_best = std::min(rapid_best, seconds_since(t0));
  }
  std::printf("  rapid check: %zu rapids (%zu checked), %zu rapid gouges: %.3f s (best of 3)\n", check.rapids,
              check.checked, check.gouges.size(), rapid_best);
  // As posts that feed the last approach write it: only the moves at the
  // clearance height are rapids.
  std::vector<RapidMove> high;
  for (const RapidMove& r : written.rapids)
    if (r.known && std::min(r.from.z(), r.to.z()) >= safe_z) high.push_back(r);
  t0 = std::chrono::steady_clock::now();
  check = check_rapids(part, ball, high, rapid);
  std::printf("  rapid check, clearance-height rapids only: %zu rapids: %.3f s\n", check.rapids, seconds_since(t0));
}

}  // namespace

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "all";
  if (std::strcmp(which, "all") && std::strcmp(which, "default") && std::strcmp(which, "fine")) {
    std::fprintf(stderr, "bench_zmap: unknown case '%s' (default, fine or all)\n", which);
    return 2;
  }
  const Part part = read_part(FURROW_SOURCE_DIR "/examples/parts/mould.json");
  const Cutter ball("BALL-D6", 3, 3);
  const Case cases[] = {{"default", 0.01, 0.005, 0.05, true}, {"fine", 0.001, 0.0005, 0.044, false}};
  for (const Case& c : cases)
    if (!std::strcmp(which, "all") || !std::strcmp(which, c.name)) run_case(part, ball, c);
  return 0;
}
