#pragma once
// The options of the curvature partition (`furrow partition`, a job's
// "partition" section), described once (base/option_table.hpp).
#include "base/option_table.hpp"
#include "partition/partition.hpp"

namespace furrow {

const OptionTable<PartitionOptions>& partition_option_table();

// "NUxNV" or "N" (N x N), counts 1 to 100000; InputError naming `where`.
GridSize parse_grid_size(const std::string& text, const std::string& where);

// After reading: grid and spacing exclude each other (InputError naming `where`).
void check_partition_options(const PartitionOptions& options, const std::string& where);

}  // namespace furrow
