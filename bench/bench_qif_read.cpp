// QIF 3.0 Results with many measured points (docs/qif.md): writes N probe
// centres (default 1,000,000) as Furrow writes simulated measurements, then
// reads the file back in a fresh process - as `furrow compare` would - and
// prints the file size, the write and read seconds and the reader's peak
// RSS (targets: read under 10 s, peak memory under 3x the file size).
// Prints figures; it does not pass or fail.
//   usage: bench_qif_read [N] [FILE]
//          bench_qif_read --read FILE   (the child: read and report)
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/cmm/measurement_qif.hpp"

using namespace furrow;

extern char** environ;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int read_child(const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  MeasurementReadOptions o;
  const MeasurementSet set = read_measurements(path, o);
  const double s = seconds_since(t0);
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const double cpu = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                     1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  // CPU time too: on a shared machine the wall time includes waiting for a core.
  std::printf("read: %zu points (%s, probe radius %g mm) in %.2f s wall, %.2f s CPU, peak RSS %.0f MB\n",
              set.points.size(), to_string(set.kind), set.probe_radius, s, cpu, u.ru_maxrss / 1024.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--read") return read_child(argv[2]);
  const long n = argc > 1 ? std::atol(argv[1]) : 1'000'000;
  const std::string path =
      argc > 2 ? argv[2] : (std::filesystem::temp_directory_path() / "bench_qif_read.qif").string();

  // A wavy sheet: nominal points and normals, centres 1 mm above with a
  // deterministic micron-scale error.
  InspectionPlan plan;
  plan.probe = {"ruby", 2};
  MeasurementSet set;
  set.source = "bench";
  set.kind = ProbePointKind::probe_centre;
  set.probe_radius = 1;
  set.ids_from_file = true;
  const long side = static_cast<long>(std::ceil(std::sqrt(static_cast<double>(n))));
  for (long i = 0; i < n; ++i) {
    const double x = 0.25 * static_cast<double>(i % side), y = 0.25 * static_cast<double>(i / side);
    PlannedPoint p;
    p.id = "P" + std::to_string(i + 1);
    p.xyz = Eigen::Vector3d(x, y, 2 * std::sin(0.01 * x) * std::cos(0.013 * y));
    p.ijk = Eigen::Vector3d(-0.02 * std::cos(0.01 * x) * std::cos(0.013 * y),
                            0.026 * std::sin(0.01 * x) * std::sin(0.013 * y), 1)
                .normalized();
    MeasuredPoint m;
    m.id = p.id;
    m.xyz = p.centre(1) + 0.001 * std::sin(0.7 * static_cast<double>(i)) * p.ijk;
    m.ijk = p.ijk;
    plan.points.push_back(std::move(p));
    set.points.push_back(std::move(m));
  }
  auto t0 = std::chrono::steady_clock::now();
  {
    const std::string text = measurements_to_qif(set, &plan, "bench sheet");
    std::ofstream(path, std::ios::binary) << text;
  }
  const double write_s = seconds_since(t0);
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / (1024.0 * 1024.0);
  std::printf("write: %ld points, %.0f MB (%.0f bytes a point) in %.2f s\n", n, mb,
              mb * 1024 * 1024 / static_cast<double>(n), write_s);
  set = {};
  plan = {};

  // The reader in a process of its own, so its peak memory is its own.
  std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string flag = "--read";
  char* child_argv[] = {self.data(), flag.data(), const_cast<char*>(path.c_str()), nullptr};
  pid_t pid = 0;
  std::fflush(stdout);
  if (posix_spawn(&pid, self.c_str(), nullptr, nullptr, child_argv, environ) != 0) return 1;
  int status = 0;
  waitpid(pid, &status, 0);
  std::printf("targets: read < 10 s, peak RSS < 3 x %.0f MB = %.0f MB\n", mb, 3 * mb);
  if (argc <= 2) std::filesystem::remove(path);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}
