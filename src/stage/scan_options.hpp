#pragma once
// The scan pre-processing options of `furrow compare --scan` (docs/scan.md),
// described once (base/option_table.hpp): the command line, help, the man
// page and docs/options.md are made from this table; in a job they are
// members of "measurements": {"scan": {...}} (docs/formats.md "Job file").
#include "base/option_table.hpp"
#include "io/scan/scan_preprocess.hpp"

namespace furrow {

const OptionTable<ScanPreprocessOptions>& scan_option_table();

}  // namespace furrow
