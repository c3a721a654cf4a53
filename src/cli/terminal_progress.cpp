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
  // A stage that cannot count its work (total 0) shows its name only.
  if (total > 0)
    std::fprintf(stderr, "\r%-40s %5.1f%%   ", stage.c_str(), 100.0 * double(done) / double(total));
  else
    std::fprintf(stderr, "\r%-48s   ", stage.c_str());
  std::fflush(stderr);
  open_ = true;
}

void TerminalProgress::finish() {
  if (!open_) return;
  std::fprintf(stderr, "\r%72s\r", "");
  std::fflush(stderr);
  open_ = false;
}

}  // namespace furrow::cli
