#pragma once
// `furrow demo`: the bundled example job (examples/jobs/demo.json) run end
// to end - the mould part, a 24 mm ball too large for the mould's dimple,
// a generated finishing path, the prediction with its gouge site, a
// risk-weighted plan, CMM measurements simulated from the predicted surface
// (misaligned, noisy, two blunders), the comparison with gouge confirmation
// and the QA report. See docs/report.md.
#include <string>

#include "job/job.hpp"

namespace furrow {

constexpr const char* kDemoJob = "examples/jobs/demo.json";

// The demo job file: examples/jobs/demo.json relative to the current
// directory, else next to the running executable (build/furrow ->
// build/../examples/...). Throws InputError saying where it looked.
std::string find_demo_job();

// The demo job with its output folder replaced by `output` (relative to the
// current directory, not to the job file).
Job demo_job(const std::string& output);

}  // namespace furrow
