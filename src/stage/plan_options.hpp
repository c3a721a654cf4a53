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

// How a caller names the head and the options it conflicts with in its
// messages: `furrow plan`'s flags or a job's members.
struct HeadOptionNames {
  std::string head;    // "--head" or "plan.head"
  std::string stylus;  // the stylus options, listed
  std::string tips_auto;  // how to ask for the planner's tips
};
extern const HeadOptionNames kHeadFlags, kHeadJobMembers;
// Whether the stylus options differ from the planner's defaults.
bool stylus_changed(const PlannerOptions& options);
// Plans with the indexable head in `path` (docs/formats.md "Probe head"):
// refused (InputError) when stylus options were given too (`stylus_given`),
// which the head gives; read and checked up front (errors name the file and
// field); refused when it lists no qualified tip and the tips are not the
// planner's.
void use_head_file(PlannerOptions& options, const std::string& path, bool stylus_given, const HeadOptionNames& names);

}  // namespace furrow
