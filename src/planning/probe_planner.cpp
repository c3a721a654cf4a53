#include "planning/probe_planner.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "base/error.hpp"
#include "planning/alignment_moves.hpp"
#include "planning/plan_steps.hpp"

namespace furrow {

const char* to_string(PlanIssue::Kind kind) {
  switch (kind) {
    case PlanIssue::Kind::moved: return "moved";
    case PlanIssue::Kind::dropped: return "dropped";
    case PlanIssue::Kind::region_short: return "region_short";
    case PlanIssue::Kind::region_skipped: return "region_skipped";
    case PlanIssue::Kind::gouge_site: return "gouge_site";
    case PlanIssue::Kind::budget_raised: return "budget_raised";
    case PlanIssue::Kind::face_facing_down: return "face_facing_down";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

PlanResult plan_probe_points(const Part& part, const RegionMap& map, const PlannerOptions& options,
                             const RiskMap* risk, const PlanProgress& progress) {
  validate(options);
  if (map.faces.size() != part.faces.size()) throw InputError("the regions do not belong to the part");
  if (needs_risk(options.strategy) && !risk)
    throw InputError(std::string("--strategy ") + to_string(options.strategy) + " needs a machining prediction");
  // The steps and what each reads and sets: plan_steps.hpp.
  PlanState s(part, map, options, risk, progress);
  start_plan(s);
  auto t0 = Clock::now();
  measure_regions(s);
  s.result.timing.regions_seconds = seconds_since(t0);
  allocate(s);
  t0 = Clock::now();
  sample(s);
  s.result.timing.sampling_seconds = seconds_since(t0);
  t0 = Clock::now();
  check_reach(s);
  s.result.timing.access_seconds = seconds_since(t0);
  t0 = Clock::now();
  order(s);
  s.result.timing.tour_seconds = seconds_since(t0);
  t0 = Clock::now();
  emit_points(s);
  s.result.timing.moves_seconds = seconds_since(t0);
  return std::move(s.result);
}

ProbeProgram make_probe_program(const PlanResult& result, const std::string& name, const PlannerOptions& options) {
  ProbeProgram program;
  program.name = name;
  program.part = result.plan.part;
  program.revision = options.program.revision;
  program.date = options.program.date;
  program.probe = result.plan.probe;
  program.stylus_length = options.stylus_length;
  program.head_length = options.head ? options.head->reach() : options.program.head_length.value_or(options.stylus_length);
  program.move_speed = options.motion.move_speed;
  program.measure_speed = options.motion.touch_speed;
  program.tolerance = options.program.tolerance;
  program.approach = result.approach;
  program.retract = result.retract;
  program.search = result.search;
  for (std::size_t k = 0; k < result.plan.points.size(); ++k)
    program.steps.push_back({result.plan.points[k], result.moves[k].waypoints});
  program.final_moves = result.final_moves;
  if (result.plan.alignment) add_alignment_moves(program, *result.plan.alignment, result.clearance_z, result.start);
  if (options.head) {
    // The alignment is measured with the vertical tip (validate() makes sure
    // there is one), the steps with theirs; sensors in order of first use.
    if (program.alignment)
      for (const TipAngles& t : options.head->qualified)
        if (t.a == 0) {
          program.start_tip = t;
          break;
        }
    if (!program.start_tip && !program.steps.empty()) program.start_tip = program.steps.front().point.tip;
    if (program.start_tip) program.tips.push_back(*program.start_tip);
    for (const ProgramStep& step : program.steps)
      if (step.point.tip && std::find(program.tips.begin(), program.tips.end(), *step.point.tip) == program.tips.end())
        program.tips.push_back(*step.point.tip);
  }
  return program;
}

}  // namespace furrow
