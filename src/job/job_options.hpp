#pragma once
// Every option of a job with the library defaults filled in, as a JSON
// object in the job file's member names (docs/formats.md "Job file"): what
// the report records under options.job, so a reader sees the values each
// stage ran with, not only those the job file spelled out. null stands for
// a default the stage derives from the data (the partition's grid and eps
// per face, the z-map resolution from the tool). Deterministic text.
#include <string>

#include "job/job.hpp"

namespace furrow {

std::string job_options_json(const Job& job);

}  // namespace furrow
