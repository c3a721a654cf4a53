#pragma once
// Wall-clock seconds and peak resident memory, as the bench programs print
// them (bench/*.cpp): one definition instead of a copy per program.
#include <sys/resource.h>

#include <chrono>

namespace furrow::bench {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Peak resident set size of this process so far [MB] (getrusage: kB on Linux).
inline double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace furrow::bench
