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

const char* to_string(TipChoice choice) { return choice == TipChoice::automatic ? "auto" : "qualified"; }

TipChoice parse_tip_choice(const std::string& text, const std::string& where) {
  if (text == "qualified") return TipChoice::qualified;
  if (text == "auto") return TipChoice::automatic;
  throw InputError(where + ": \"" + text + "\" is not a tip choice: qualified (the head file's tips) or auto "
                   "(chosen by the planner)");
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
    // Sensors in the order the program selects them: the vertical tip
    // first when it measures the alignment (validate() makes sure there is
    // one), then the steps' tips in order of first use.
    for (const PlanTip& t : tips_in_use(result, options)) {
      program.tips.push_back(t.angles);
      if (!t.qualified) program.unqualified_tips.push_back(t.angles);
    }
    if (!program.tips.empty()) program.start_tip = program.tips.front();
  }
  return program;
}

std::vector<PlanTip> tips_in_use(const PlanResult& result, const PlannerOptions& options) {
  std::vector<PlanTip> out;
  if (!options.head) return out;
  auto add = [&](const TipAngles& t) {
    for (const PlanTip& u : out)
      if (u.angles == t) return;
    const std::vector<TipAngles>& q = options.head->qualified;
    out.push_back({t, std::find(q.begin(), q.end(), t) != q.end()});
  };
  if (result.plan.alignment && result.vertical_tip) add(*result.vertical_tip);
  for (const PlannedPoint& p : result.plan.points)
    if (p.tip) add(*p.tip);
  return out;
}

}  // namespace furrow
