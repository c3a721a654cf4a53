// Reading a million measured points (docs/formats.md "Measurements"): writes
// POINTS points (default 1,000,000) as CSV, DMIS output and an I++ DME
// response log into a temporary folder with the library's writers, and an
// I++ DME client session log as NIST's clients write them (time stamps,
// Sent: PtMeas commands, Received: answers with ER, CR CR LF and blank lines
// between: docs/formats.md "Reading any I++ DME session"), then
// reads each in a fresh process (so that its peak memory is the reader's
// alone) and prints the file size, the wall time of the read and the peak
// RSS (VmHWM). Targets: CSV < 2 s, the I++ DME session log < 2 s, every format
// < 10 s, peak memory < 3x the file.
// Prints figures; it does not pass or fail.
//   usage: bench_measurement_read [POINTS]
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "io/cmm/measurement_file.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

// Child mode: read one file, print the seconds and the point count.
int read_one(const std::string& path) {
  furrow::MeasurementReadOptions o;
  // The session log's answers carry ER(): ball centres, compensated by it.
  if (fs::path(path).extension() != ".log") o.kind = furrow::ProbePointKind::contact;
  const auto t0 = std::chrono::steady_clock::now();
  const furrow::MeasurementSet set = furrow::read_measurements(path, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // VmHWM belongs to this process's memory since exec; getrusage's maxrss
  // would carry over the parent's peak through posix_spawn's exec.
  long hwm_kb = -1;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) hwm_kb = std::atol(line.c_str() + 6);
  std::printf("%.3f %zu %ld\n", s, set.points.size(), hwm_kb);
  return 0;
}

// Runs this program on `file`; returns its output line.
std::string run_child(const std::string& file, const std::string& out_file) {
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::vector<char*> argv{const_cast<char*>(self.c_str()), const_cast<char*>("--read"),
                          const_cast<char*>(file.c_str()), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  if (posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
    std::fprintf(stderr, "bench_measurement_read: cannot start %s\n", self.c_str());
    std::exit(1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  posix_spawn_file_actions_destroy(&actions);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "bench_measurement_read: reading %s failed\n", file.c_str());
    std::exit(1);
  }
  std::ifstream in(out_file);
  std::string line;
  std::getline(in, line);
  return line;
}

// A client's session log of `n` PtMeas, each sent and answered (&, data
// with IJK and ER, %), tags counting from 00001 and wrapping after 99999.
std::string session_log(long n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(-400, 400), d(-1, 1);
  std::string out;
  out.reserve(static_cast<std::size_t>(n) * 420);
  char line[512];
  auto stamp = [&](long second) {
    std::snprintf(line, sizeof line, "04:08:18_%02ld:%02ld:%02ld ", (second / 3600) % 24, (second / 60) % 60,
                  second % 60);
    out += line;
  };
  stamp(0);
  out += "*********** Starting DME file: bench.prg **********\r\r\n\r\n";
  for (long k = 0; k < n; ++k) {
    const int tag = static_cast<int>(k % 99999) + 1;
    const Eigen::Vector3d p(c(rng), c(rng), c(rng));
    const Eigen::Vector3d v = Eigen::Vector3d(d(rng), d(rng), d(rng) + 2).normalized();
    const Eigen::Vector3d centre = p + 1.4985 * v;
    stamp(k);
    std::snprintf(line, sizeof line, "Sent: %05d PtMeas(X(%.6f), Y(%.6f), Z(%.6f), IJK(%.9f, %.9f, %.9f))\r\r\n\r\n",
                  tag, p.x(), p.y(), p.z(), v.x(), v.y(), v.z());
    out += line;
    stamp(k);
    std::snprintf(line, sizeof line, "Received: %05d &\r\r\n\r\n", tag);
    out += line;
    stamp(k);
    std::snprintf(line, sizeof line,
                  "Received: %05d # X(%.5f), Y(%.5f), Z(%.5f), IJK(%.5f, %.5f, %.5f), ER(1.4985)\r\r\n\r\n", tag,
                  centre.x(), centre.y(), centre.z(), v.x(), v.y(), v.z());
    out += line;
    stamp(k);
    std::snprintf(line, sizeof line, "Received: %05d %%\r\r\n\r\n", tag);
    out += line;
  }
  stamp(n);
  out += "Final Tag: 00001\r\r\n\r\n";
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--read") return read_one(argv[2]);
  const long n = argc > 1 ? std::max(1L, std::atol(argv[1])) : 1000000L;
  const fs::path dir = fs::temp_directory_path() / ("bench_measurement_read-" + std::to_string(::getpid()));
  fs::create_directories(dir);

  std::printf("%ld points, files in %s\n", n, dir.c_str());
  std::printf("%-18s %10s %10s %12s %10s\n", "format", "file MB", "read s", "peak RSS MB", "RSS/file");
  const std::pair<const char*, furrow::MeasurementFormat> formats[] = {
      {"m.csv", furrow::MeasurementFormat::csv},
      {"m.dmo", furrow::MeasurementFormat::dmis},
      {"m.res", furrow::MeasurementFormat::ippdme_log},
      {"session.log", furrow::MeasurementFormat::automatic}};
  for (const auto& [name, format] : formats) {
    if (format == furrow::MeasurementFormat::automatic) {
      std::ofstream(dir / name, std::ios::binary) << session_log(n);
    } else {
      // A part's worth of points with full-precision coordinates, as a CMM
      // reports them; the set is freed before the read.
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> c(-400, 400), d(-1, 1);
      furrow::MeasurementSet set;
      set.kind = furrow::ProbePointKind::contact;
      set.points.reserve(static_cast<std::size_t>(n));
      for (long k = 0; k < n; ++k) {
        furrow::MeasuredPoint p;
        p.id = "P" + std::to_string(k + 1);
        p.xyz = {c(rng), c(rng), c(rng)};
        p.ijk = Eigen::Vector3d(d(rng), d(rng), d(rng) + 2).normalized();
        p.nominal = p.xyz.array().round();
        p.nominal_ijk = p.ijk;
        set.points.push_back(std::move(p));
      }
      std::ofstream(dir / name, std::ios::binary) << furrow::measurements_text(set, format);
    }
    const double mb = static_cast<double>(fs::file_size(dir / name)) / (1024.0 * 1024.0);
    const std::string out = run_child((dir / name).string(), (dir / "child.out").string());
    double seconds = 0;
    long points = 0, rss_kb = 0;
    std::sscanf(out.c_str(), "%lf %ld %ld", &seconds, &points, &rss_kb);
    if (points != n) std::fprintf(stderr, "bench_measurement_read: %s gave %ld points\n", name, points);
    const double rss = static_cast<double>(rss_kb) / 1024.0;
    std::printf("%-18s %10.1f %10.2f %12.1f %10.2f\n", name, mb, seconds, rss, rss / mb);
    std::fflush(stdout);
    fs::remove(dir / name);
  }
  fs::remove_all(dir);
  return 0;
}
