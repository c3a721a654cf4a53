#pragma once
// The options of tool-path generation (`furrow toolpath`, a job's
// "toolpath": {"generate": {...}}), described once (base/option_table.hpp).
#include "base/option_table.hpp"
#include "stage/toolpath_stage.hpp"

namespace furrow {

const OptionTable<ToolpathGeneration>& toolpath_option_table();

}  // namespace furrow
