#pragma once
// The probe and move options shared by `furrow plan` and `furrow remeasure`
// (docs/cmm.md "Collision model"), read in one place so both commands take
// them with the same names and defaults.
#include "cli/args.hpp"
#include "planning/probe_planner.hpp"

namespace furrow::cli {

// --stylus-length, --stylus-diameter, --approach, --retract, --search,
// --clearance, --max-tilt; absent options keep o's values.
void read_probe_motion_options(Args& args, PlannerOptions& o);

}  // namespace furrow::cli
