#include "job/demo.hpp"

#include <filesystem>

#include "base/error.hpp"

namespace furrow {

namespace fs = std::filesystem;

std::string find_demo_job() {
  std::error_code ec;
  std::string looked = fs::absolute(kDemoJob, ec).string();
  if (fs::is_regular_file(kDemoJob, ec)) return kDemoJob;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // build/furrow, or an install's bin/furrow next to share/furrow is not
    // supported: the examples live in the source tree.
    for (fs::path dir = exe.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
      const fs::path candidate = dir / kDemoJob;
      if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
      looked += ", " + candidate.string();
      if (looked.size() > 600) break;
    }
  }
  throw InputError(std::string("furrow demo: cannot find the bundled ") + kDemoJob + " (looked at " + looked +
                   "); run it from the Furrow source tree");
}

Job demo_job(const std::string& output) {
  Job job = read_job(find_demo_job());
  job.output = output;
  return job;
}

int demo_exit_status(int job_status) { return job_status == kDemoPlannedFail ? 0 : job_status; }

}  // namespace furrow
