#pragma once
// Progress of long work on standard error, only when it is a terminal (a
// redirected or piped run stays quiet). One line, overwritten in place,
// at most every 100 ms; finish() ends it.
#include <chrono>
#include <string>

namespace furrow::cli {

class TerminalProgress {
 public:
  TerminalProgress();
  ~TerminalProgress();
  bool enabled() const { return enabled_; }
  void update(const std::string& stage, std::size_t done, std::size_t total);
  void finish();

 private:
  bool enabled_ = false;
  bool open_ = false;
  std::string stage_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace furrow::cli
