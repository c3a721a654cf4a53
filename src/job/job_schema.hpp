#pragma once
// The JSON Schema (draft 2020-12) of a job file, docs/job.schema.json
// (`furrow help --job-schema`): the stage sections are written from the
// stages' option tables (base/option_table.hpp), the rest follows what
// job.cpp reads. Editors and CI scripts can check a job file with it before
// `furrow run`; furrow itself reads with its own checks, which say more
// (paths, files, how members relate), and a test keeps the two in step.
#include <string>

namespace furrow {

std::string job_schema_json();

}  // namespace furrow
