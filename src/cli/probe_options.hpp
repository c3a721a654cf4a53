#pragma once
// The probe and move options shared by `furrow plan` and `furrow remeasure`
// (docs/cmm.md "Collision model"), and what both say about the CMM
// programs they write (docs/cmm.md "What the programs say"), read in one
// place so both commands take them with the same names and defaults.
#include "cli/args.hpp"
#include "planning/probe_planner.hpp"

namespace furrow::cli {

// --stylus-length, --stylus-diameter, --approach, --retract, --search,
// --clearance, --max-tilt; absent options keep o's values.
void read_probe_motion_options(Args& args, PlannerOptions& o);

// --revision TEXT, --program-date YYYY-MM-DD, --head-length MM into
// o.program (checked later by validate(PlannerOptions)). The date is never
// taken from the clock: without --program-date the programs state none, so
// the same plan gives the same bytes on any day.
void read_program_options(Args& args, PlannerOptions& o);

// --datums auto|FACE,FACE,FACE into o.datums (furrow plan only: a
// re-measuring plan runs on the first plan's alignment).
void read_datum_option(Args& args, PlannerOptions& o);

// The help lines of read_program_options, for the commands' usage texts
// (a literal, because usage texts are literals).
#define FURROW_PROGRAM_OPTIONS_HELP                                                   \
  "  --revision TEXT      part revision stated in the DMIS program (PARTRV)\n"         \
  "  --program-date DATE  date YYYY-MM-DD stated in the DMIS header; never taken\n"    \
  "                       from the clock (default: none stated)\n"                     \
  "  --head-length MM     probe head's centre of rotation to the ball centre, the\n"   \
  "                       DMIS SNSDEF length (default: the stylus length)\n"

}  // namespace furrow::cli
