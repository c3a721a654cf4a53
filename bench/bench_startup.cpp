// What a user pays before any work: the furrow binary's size, the shared
// libraries the loader maps for it, and the wall time and peak memory of
// `furrow --version` (median of RUNS runs; target < 20 ms). Prints figures;
// it does not pass or fail.
//   usage: bench_startup [RUNS] [FURROW_BINARY]
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace {

// Runs `binary` with `args` and the extra environment entries, output to
// /dev/null; returns wall seconds and the child's peak RSS [KB].
std::pair<double, long> run(const std::string& binary, const std::vector<std::string>& args,
                            const std::vector<std::string>& extra_env, const std::string& out_file) {
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> env_store(extra_env);
  for (char** e = environ; *e; ++e) env_store.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : env_store) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), envp.data()) != 0) {
    std::fprintf(stderr, "bench_startup: cannot start %s\n", binary.c_str());
    std::exit(1);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  posix_spawn_file_actions_destroy(&actions);
  return {wall, usage.ru_maxrss};
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  const std::string binary = argc > 2 ? argv[2] : FURROW_CLI;
  const std::string scratch = (std::filesystem::temp_directory_path() / "bench_startup.out").string();
  // The loader's own list of what it maps (what ldd prints).
  run(binary, {}, {"LD_TRACE_LOADED_OBJECTS=1"}, scratch);
  std::FILE* f = std::fopen(scratch.c_str(), "r");
  int libraries = 0;
  for (int c, last = '\n'; f && (c = std::fgetc(f)) != EOF; last = c) libraries += c == '\n' && last != '\n';
  if (f) std::fclose(f);
  std::vector<double> times;
  long rss = 0;
  for (int r = 0; r < runs; ++r) {
    const auto [wall, kb] = run(binary, {"--version"}, {}, "/dev/null");
    times.push_back(wall);
    rss = std::max(rss, kb);
  }
  std::sort(times.begin(), times.end());
  std::printf("binary %s: %.2f MB, %d shared objects mapped (ldd)\n", binary.c_str(),
              std::filesystem::file_size(binary) / 1e6, libraries);
  std::printf("furrow --version: median %.1f ms, fastest %.1f ms over %d runs, peak RSS %.1f MB (target < 20 ms)\n",
              1000 * times[times.size() / 2], 1000 * times.front(), runs, rss / 1024.0);
  std::filesystem::remove(scratch);
  return 0;
}
