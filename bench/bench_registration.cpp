// Registration of 10 000 and 1 000 000 simulated CMM points on the mould
// example (targets <= 1 s and <= 60 s on this 2-core machine).
// Prints figures; it does not pass or fail.
//
// Data: an even (u,v) grid plan, probe 2 mm, the part misaligned by
// (4, -6, 10) degrees and (20, -12, 15) mm, 2 um probing noise, 5 % blunders
// of 0.1-1 mm. Each run reports wall time, outer iterations (re-projections),
// Ceres iterations, the coarse start's time, the recovered transform's error
// against the simulated truth and the reported 1-sigma of rz and tx.
//
//   ./build/bench_registration          (both sizes, coarse start by plan ids)
//   ./build/bench_registration --global (also the id-free global search, 10 000)
//   ./build/bench_registration --side N (only an N x N grid, ids; for
//        /usr/bin/time -v or valgrind --tool=massif on one size)
//   ./build/bench_registration --side N --write DIR (no registration: writes
//        the N x N plan and its simulated measurement to DIR/plan.json and
//        DIR/measurements.csv, to time and size `furrow compare` on them)
//   ./build/bench_registration --weak   (the weakly constrained shapes of
//        docs/registration.md at 1 000, 10 000 and 100 000 points, turned
//        183 degrees and moved 20 mm, 2 um noise, coarse start by ids;
//        target: each under 1 s at 10 000 points)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>

#include <sys/resource.h>
#include <unistd.h>

#include "inspection/measurement_simulation.hpp"
#include "inspection/registration.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Peak resident set size of the process so far [MB] (getrusage: kB on Linux).
double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// Current resident set size [MB] (/proc/self/statm, pages), 0 when unknown.
double current_rss_mb() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

void run(const ClosestPointFinder& finder, int nu, int nv, bool anonymous, const char* write_dir = nullptr) {
  auto t0 = Clock::now();
  const InspectionPlan plan = grid_plan(finder.part(), nu, nv, {"ball 2 mm", 2});
  SimulationOptions sim;
  sim.misalignment = {{4, -6, 10}, {20, -12, 15}};
  sim.noise_sigma = 0.002;
  sim.blunders = static_cast<int>(plan.points.size() / 20);
  sim.seed = 1;
  sim.anonymous = anonymous;
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  const double prepare = seconds_since(t0);
  if (write_dir) {
    write_plan(plan, std::string(write_dir) + "/plan.json");
    write_measurements_csv(m.set, std::string(write_dir) + "/measurements.csv");
    std::printf("wrote %zu points to %s/plan.json and %s/measurements.csv\n", plan.points.size(), write_dir,
                write_dir);
    return;
  }

  RegistrationOptions o;
  o.loss_scale = 0.025;
  o.outlier_floor = 0.025;
  // Stage times from the progress notes: coarse start, fit setup (Ceres
  // problem, first projection of every point), fit, covariance.
  double stage[4] = {0, 0, 0, 0};
  int current = -1;
  Clock::time_point mark;
  o.progress = [&](const std::string& what) {
    const int next = what == "coarse start" ? 0
                     : what == "fit setup"  ? 1
                     : what == "covariance" ? 3
                                            : 2;
    const Clock::time_point now = Clock::now();
    if (current >= 0) stage[current] += std::chrono::duration<double>(now - mark).count();
    current = next;
    mark = now;
  };
  const double rss_before = current_rss_mb();
  t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  const RegistrationResult r = register_measurements(finder, m.set, &plan, o);
  const double total = seconds_since(t0);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  stage[current] += std::chrono::duration<double>(Clock::now() - mark).count();

  const Eigen::Isometry3d e = r.transform * sim.misalignment.part_to_cmm();
  double displacement = 0;
  for (const PlannedPoint& p : plan.points)
    displacement = std::max(displacement, (e * p.xyz - p.xyz).norm());
  std::size_t flagged = 0;
  for (const RegisteredPoint& p : r.points) flagged += p.outlier != OutlierReason::none;
  std::printf(
      "%8zu points  %-13s  %6.2f s wall, %6.2f s cpu (coarse %.2f, setup %.2f, fit %.2f, "
      "covariance %.2f)"
      "  outer %d  ceres %d  %s\n",
      plan.points.size(), to_string(r.coarse.method), total, cpu, stage[0], stage[1], stage[2],
      stage[3], r.outer_iterations, r.solver_iterations, r.status.c_str());
  std::printf(
      "          error %.2e mm / %.2e rad; sigma %.2f um; flagged %zu of %d blunders;"
      " 1-sigma rz %.1e rad, tx %.2e mm; simulation %.1f s\n",
      displacement, Eigen::AngleAxisd(e.linear()).angle(), 1e3 * r.sigma, flagged, sim.blunders,
      r.covariance ? std::sqrt((*r.covariance)(2, 2)) : NAN,
      r.covariance ? std::sqrt((*r.covariance)(3, 3)) : NAN, prepare);
  // The process peak includes the plan and the simulated measurement held
  // by this program; "before" is what they (and earlier runs' freed, but
  // possibly retained, heap) occupied when the registration started.
  std::printf("          memory: %.0f MB resident before the registration, process peak %.0f MB\n",
              rss_before, peak_rss_mb());
}

// One weakly constrained shape at about `count` points.
void run_weak(const test::WeakShape& shape, int side) {
  const ClosestPointFinder finder(shape.part);
  const InspectionPlan plan = grid_plan(shape.part, side, side, {"ball 2 mm", 2});
  SimulationOptions sim;
  sim.misalignment = {{0, 0, 183}, {20, -12, 5}};
  sim.noise_sigma = 0.002;
  sim.seed = 1;
  const SimulatedMeasurement m = simulate_measurement(plan, sim);
  RegistrationOptions o;
  o.loss_scale = 0.025;
  o.outlier_floor = 0.025;
  const auto t0 = Clock::now();
  const RegistrationResult r = register_measurements(finder, m.set, &plan, o);
  const double total = seconds_since(t0);
  double worst = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i)
    if (r.points[i].in_fit) worst = std::max(worst, std::abs(r.points[i].deviation - m.true_deviation[i]));
  std::printf("%-11s %7zu points  %6.3f s  outer %3d  ceres %4d  weak %zu  fitted %d  in fit %zu  rms %.2f um"
              "  worst deviation error %.2f um  %s\n",
              shape.name, plan.points.size(), total, r.outer_iterations, r.solver_iterations,
              r.observability.weak.size(), r.fitted_dof, r.in_fit_count(), 1e3 * r.rms_after, 1e3 * worst,
              r.status.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const bool global = argc > 1 && std::strcmp(argv[1], "--global") == 0;
  if (argc > 1 && std::strcmp(argv[1], "--weak") == 0) {
    const std::string mould = std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json";
    std::printf("weakly constrained shapes, turned 183 deg and moved 20 mm, noise 2 um, ids\n");
    for (const test::WeakShape& shape : test::weak_shapes(mould))
      for (int side : {32, 100, 316}) run_weak(shape, side);
    return 0;
  }
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const ClosestPointFinder finder(part);
  if (argc > 2 && std::strcmp(argv[1], "--side") == 0) {
    char* end = nullptr;
    const long side = std::strtol(argv[2], &end, 10);
    if (end == argv[2] || *end != '\0' || side < 4 || side > 4000) {
      std::fprintf(stderr, "bench_registration: --side wants a whole number from 4 to 4000, not '%s'\n",
                   argv[2]);
      return 2;
    }
    run(finder, static_cast<int>(side), static_cast<int>(side), false, argc > 4 && std::strcmp(argv[3], "--write") == 0 ? argv[4] : nullptr);
    return 0;
  }
  std::printf(
      "registration on mould.json, misalignment 10 deg / 20 mm, noise 2 um, 5%% blunders\n");
  run(finder, 100, 100, false);
  if (global) run(finder, 100, 100, true);
  run(finder, 1000, 1000, false);
  return 0;
}
