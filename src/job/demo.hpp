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

// The exit status of `furrow demo` given the job's (0 ok, 1 fail, 2 bad
// input, 3 the computation did not succeed, 4 inconclusive). The demo part
// fails by design - its gouge - so a FAIL (1) is the planned outcome and
// the demo exits 0; every other status comes out as it is, since a 3 or a
// 4 means the demo did not show what it is there to show.
constexpr int kDemoPlannedFail = 1;
int demo_exit_status(int job_status);

}  // namespace furrow
