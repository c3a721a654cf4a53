#pragma once
// The options of the comparison stage (`furrow compare`, a job's
// "comparison" section), described once (base/option_table.hpp): what
// `furrow compare --help`, the job reader and writer, the man page and
// docs/options.md are made from.
//
// The tolerance zone is not among them: `furrow compare` takes it as
// --tolerance/--outside and a job as its top-level "tolerance", and the
// registration's loss scale follows it (scale_registration_to_tolerance).
#include "base/option_table.hpp"
#include "inspection/comparison.hpp"

namespace furrow {

const OptionTable<CompareOptions>& compare_option_table();

}  // namespace furrow
