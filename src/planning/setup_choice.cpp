#include "planning/setup_choice.hpp"

#include <algorithm>

#include "planning/plan_steps.hpp"
#include "planning/tip_grid.hpp"

namespace furrow {

SetupScore score_setup(const Part& part, const RegionMap& map, const PlannerOptions& options,
                       const RestingFace& face, const std::vector<char>& wanted) {
  SetupScore score;
  score.face = face;
  const PartSetup setup = resting_setup(face, 2, false);
  const Part moved = moved_part(part, setup.to_setup);
  PlannerOptions o = options;
  o.access.fixture_z = setup.fixture_z;
  // The planner's own start: clearance plane, access options, tips (it
  // reads the part and options only; the map is the caller's, whose uv the
  // interior points below are in).
  PlanState s(moved, map, o, nullptr, {});
  start_plan(s);
  std::vector<ProbeGeometry> probes = s.tips;
  if (probes.empty() && o.head && o.tips == TipChoice::automatic) {
    for (const TipAngles& t : tip_grid(*o.head)) {
      ProbeGeometry g = s.result.probe;
      g.axis = -tip_direction(t);
      probes.push_back(g);
    }
  }
  if (probes.empty()) probes.push_back(s.result.probe);
  for (const Region& r : map.regions) {
    if (static_cast<std::size_t>(r.id) >= wanted.size() || !wanted[static_cast<std::size_t>(r.id)]) continue;
    const DifferentialGeometry g =
        moved.faces[static_cast<std::size_t>(r.face)].geometry(r.interior_uv.x(), r.interior_uv.y());
    if (g.degenerate) continue;
    for (const ProbeGeometry& probe : probes)
      if (check_access(s.finder, g.point, g.normal, probe, s.access).ok()) {
        score.reachable_area += r.area;
        ++score.reachable_regions;
        break;
      }
  }
  return score;
}

std::optional<SetupScore> best_next_setup(const Part& part, const RegionMap& map, const PlannerOptions& options,
                                          const std::vector<char>& wanted, const std::vector<int>& used,
                                          std::vector<SetupScore>* scores) {
  std::optional<SetupScore> best;
  for (const RestingFace& f : resting_candidates(part, map)) {
    if (std::find(used.begin(), used.end(), f.face) != used.end()) continue;
    SetupScore s = score_setup(part, map, options, f, wanted);
    if (scores) scores->push_back(s);
    if (s.reachable_area > 0 && (!best || s.reachable_area > best->reachable_area)) best = s;
  }
  return best;
}

}  // namespace furrow
