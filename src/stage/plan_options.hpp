#pragma once
// The options of the plan stage (`furrow plan`, a job's "plan" section),
// described once (base/option_table.hpp): what `furrow plan --help`, the
// job reader and writer, the man page and docs/options.md are made from.
// `furrow remeasure` takes the probe, move and program ones of them
// (kProbeMotionKeys, kProgramKeys).
//
// Reading checks each value on its own (a number, positive, one of the
// strategies); validate(PlannerOptions) then checks them together (a shaft
// no wider than the ball, ...).
#include <string>
#include <vector>

#include "base/option_table.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

const OptionTable<PlannerOptions>& plan_option_table();

// The stylus and move options a re-measuring plan takes too.
extern const std::vector<std::string> kProbeMotionKeys;
// What the CMM programs state about the part (revision, date, head length).
extern const std::vector<std::string> kProgramKeys;

}  // namespace furrow
