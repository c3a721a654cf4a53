// Z-map of the mould example finished with a generated path: ball 6 mm, tolerance 0.01 mm, scallop 0.005 mm (the furrow
// toolpath defaults), z-map at 0.05 mm. Prints moves, nodes and seconds
// (best of 3; target < 5 s on the 2-core machine), and for context the
// planning and error-map times, and the rapid check of the same path as
// `furrow toolpath` writes it (a rapid up, over and down per pass, samples
// at the z-map spacing). Prints figures; it does not pass or fail.
//   usage: bench_zmap [RESOLUTION_MM]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "io/part_file.hpp"
#include "machining/toolpath/contact_planning.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/rapid_check.hpp"
#include "machining/toolpath/toolpath_generation.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const double resolution = argc > 1 ? std::atof(argv[1]) : 0.05;
  const Part part = read_part(FURROW_SOURCE_DIR "/examples/parts/mould.json");
  const Cutter ball("BALL-D6", 3, 3);
  ContactPlanOptions options;
  options.forward.tolerance = 0.01;
  options.scallop = 0.005;
  auto t0 = std::chrono::steady_clock::now();
  const ContactPlan plan = plan_contact_points(part, ball, {PassDirection::along_u, 0}, options);
  const double planning = seconds_since(t0);
  const std::vector<ZMapMove> moves = moves_from_toolpath(plan_tips(plan));
  std::printf("mould, ball 6 mm, tolerance 0.01 mm, scallop 0.005 mm, %d threads\n", omp_get_max_threads());
  std::printf("path: %zu passes, %zu contact points, %zu moves (planned in %.2f s)\n", plan.passes.size(),
              plan.points, moves.size(), planning);
  double best = 1e300;
  std::size_t nodes = 0, cut = 0;
  for (int run = 0; run < 3; ++run) {
    ZMap zmap(part_xy_extent(part), resolution);
    t0 = std::chrono::steady_clock::now();
    zmap.cut(ball, moves);
    best = std::min(best, seconds_since(t0));
    nodes = zmap.node_count();
    cut = zmap.cut_node_count();
    if (run == 2) {
      t0 = std::chrono::steady_clock::now();
      const ErrorMap map = compute_error_map(part, zmap);
      std::printf("error map: %zu samples in %.2f s; max undercut %.2f um, max overcut %.2f um\n", map.samples,
                  seconds_since(t0), map.max_undercut.error * 1000, map.max_overcut.error * 1000);
    }
  }
  std::printf("z-map: %.3g mm, %zu nodes (%zu cut), %zu moves: %.3f s (best of 3)\n", resolution, nodes, cut,
              moves.size(), best);
  const double safe_z = part.control_box().max().z() + 5;
  const Toolpath written = parse_gcode(toolpath_to_gcode(plan_tips(plan), safe_z, 1000, "bench"), "bench.nc");
  RapidCheckOptions rapid;
  rapid.sample_spacing = resolution;
  double rapid_best = 1e300;
  RapidCheck check;
  for (int run = 0; run < 3; ++run) {
    t0 = std::chrono::steady_clock::now();
    check = check_rapids(part, ball, written.rapids, rapid);
    rapid_best = std::min(rapid_best, seconds_since(t0));
  }
  std::printf("rapid check: %zu rapids (%zu checked), %zu rapid gouges: %.3f s (best of 3)\n", check.rapids,
              check.checked, check.gouges.size(), rapid_best);
  // As posts that feed the last approach write it: only the moves at the
  // clearance height are rapids.
  std::vector<RapidMove> high;
  for (const RapidMove& r : written.rapids)
    if (r.known && std::min(r.from.z(), r.to.z()) >= safe_z) high.push_back(r);
  t0 = std::chrono::steady_clock::now();
  check = check_rapids(part, ball, high, rapid);
  std::printf("rapid check, clearance-height rapids only: %zu rapids: %.3f s\n", check.rapids, seconds_since(t0));
  return 0;
}
