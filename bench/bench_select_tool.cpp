// Tool selection on the mould example (target: under 2 s on the 2-core
// machine): 10,000 contact points (a 100 x 100 grid) against a 31-tool
// library of standard sizes (11 balls, 11 bull-noses, 9 flat end mills, built
// here), with the interference check. Runs the default selection, which
// takes a tool's interference verdict from a clear tool containing it
// (docs/tool_selection.md), and the exhaustive one, which searches for every
// tool; prints per mode the median of 3 wall-clock seconds, the CPU seconds
// of that run (all threads; on a machine shared with other jobs the wall
// clock overstates the work), the interference searches run and the peak
// RSS; then whether both agree on every per-site result and how many
// per-tool verdicts differ (none expected: docs/tool_selection.md).
// Prints figures; it does not pass or fail.
//   usage: bench_select_tool [--fast-only]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "bench_clock.hpp"
#include "io/part_file.hpp"
#include "machining/gouge/tool_selection.hpp"

using namespace furrow;
using furrow::bench::peak_rss_mb;
using furrow::bench::seconds_since;

namespace {

std::string number(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", d);
  return buf;
}

// Standard sizes: the diameters a shop keeps, corner radii of its bull-noses.
std::vector<Cutter> standard_library() {
  std::vector<Cutter> tools;
  for (const double d : {1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20})
    tools.emplace_back("BALL-D" + number(d), d / 2, d / 2);
  for (const double d : {2, 3, 4, 6, 8, 10, 12, 16, 20}) tools.emplace_back("FLAT-D" + number(d), d / 2, 0);
  const double bulls[][2] = {{6, 0.5}, {6, 1},  {8, 1},  {10, 1}, {10, 2}, {12, 1},
                             {12, 2},  {16, 2}, {16, 3}, {20, 2}, {20, 4}};
  for (const auto& b : bulls)
    tools.emplace_back("BULL-D" + number(b[0]) + "-R" + number(b[1]), b[0] / 2, b[1]);
  return tools;
}

struct Run {
  double wall = 0, cpu = 0;
  ToolSelection selection;
};

Run run(const Part& part, const std::vector<Cutter>& library, const std::vector<ContactSite>& sites,
        bool share) {
  ToolSelectionOptions options;
  options.share_interference = share;
  std::vector<Run> runs(3);
  for (Run& r : runs) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    r.selection = select_tools(part, library, sites, options);
    r.wall = seconds_since(t0);
    r.cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.wall < b.wall; });
  return std::move(runs[1]);
}

void print(const char* mode, const Run& r) {
  const std::size_t searches = r.selection.interference_searches;
  std::printf("%-10s %7.2f s wall (median of 3)  %7.2f s CPU  %7zu interference searches  "
              "peak RSS %.0f MB  whole surface %s\n",
              mode, r.wall, r.cpu, searches, peak_rss_mb(),
              r.selection.whole_surface >= 0 ? r.selection.library[r.selection.whole_surface].name().c_str()
                                             : "none");
}

// Whether every per-site result agrees (always, docs/tool_selection.md).
bool same_sites(const ToolSelection& a, const ToolSelection& b) {
  if (a.sites.size() != b.sites.size() || a.whole_surface != b.whole_surface) return false;
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    const SiteSelection &s = a.sites[k], &t = b.sites[k];
    if (s.tool != t.tool || s.machinable != t.machinable || s.interference != t.interference ||
        s.smallest_gouges_locally != t.smallest_gouges_locally || s.needed.excess != t.needed.excess ||
        s.needed.design_curvature != t.needed.design_curvature)
      return false;
  }
  return true;
}

std::size_t differing_verdicts(const ToolSelection& a, const ToolSelection& b) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.verdicts.size(); ++k) n += a.verdicts[k] != b.verdicts[k];
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  const bool fast_only = argc > 1 && std::strcmp(argv[1], "--fast-only") == 0;
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const std::vector<Cutter> library = standard_library();
  const std::vector<ContactSite> sites = grid_sites(part, 100);
  std::printf("mould.json, %zu contact points x %zu tools, interference check on, %d threads\n",
              sites.size(), library.size(), omp_get_max_threads());
  const Run shared = run(part, library, sites, true);
  print("shared", shared);
  if (fast_only) return 0;
  const Run exhaustive = run(part, library, sites, false);
  print("exhaustive", exhaustive);
  std::printf("shared / exhaustive: %.1fx faster (wall), %.1fx less CPU; per-site results %s; "
              "%zu of %zu tool verdicts differ\n",
              exhaustive.wall / shared.wall, exhaustive.cpu / shared.cpu,
              same_sites(shared.selection, exhaustive.selection) ? "identical" : "DIFFER",
              differing_verdicts(shared.selection, exhaustive.selection), shared.selection.verdicts.size());
  return 0;
}
