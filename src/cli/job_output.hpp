#pragma once
// Shared by `furrow run` and `furrow demo`: run a job with progress on the
// terminal, write its folder, print what happened, return the exit status
// (0 pass or plan only, 1 fail).
#include <ostream>

#include "job/pipeline.hpp"

namespace furrow::cli {

int run_and_report(const Job& job, std::ostream& out, const ProcessLookup& process = {});

}  // namespace furrow::cli
