#include "cli/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace furrow::cli {

TerminalProgress::TerminalProgress() : enabled_(::isatty(STDERR_FILENO) == 1) {}

TerminalProgress::~TerminalProgress() { finish(); }

void TerminalProgress::update(const std::string& stage, std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool new_stage = stage != stage_;
  if (!new_stage && done < total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  stage_ = stage;
  const double percent = total > 0 ? 100.0 * double(done) / double(total) : 100.0;
  std::fprintf(stderr, "\r%-24s %5.1f%%   ", stage.c_str(), percent);
  std::fflush(stderr);
  open_ = true;
}

void TerminalProgress::finish() {
  if (!open_) return;
  std::fprintf(stderr, "\r%60s\r", "");
  std::fflush(stderr);
  open_ = false;
}

}  // namespace furrow::cli
