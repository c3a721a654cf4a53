#include "planning/auto_tips.hpp"

#include <algorithm>
#include <cmath>

#include "planning/tip_grid.hpp"

namespace furrow {

void choose_auto_tips(PlanState& s) {
  const ProbeHead& head = *s.options.head;
  const ClosestPointFinder& finder = s.finder;
  const AccessOptions& access = s.access;
  std::vector<PlanCandidate>& candidates = s.candidates;
  const std::vector<TipAngles> grid = tip_grid(head);
  const std::size_t vertical = vertical_orientation(grid).value_or(0);  // validate() makes sure there is one
  std::vector<ProbeGeometry> probes(grid.size(), s.result.probe);
  for (std::size_t o = 0; o < grid.size(); ++o) probes[o].axis = -tip_direction(grid[o]);

  // What does not depend on the tip, once per point.
  const long n = static_cast<long>(candidates.size());
  std::vector<char> point_ok(candidates.size(), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < n; ++k) {
    PlanCandidate& c = candidates[static_cast<std::size_t>(k)];
    const DifferentialGeometry g = s.domains[static_cast<std::size_t>(c.region)].face().geometry(c.uv.x(), c.uv.y());
    c.original = c.xyz;
    c.normal = g.normal;
    if (g.degenerate) {
      c.access = AccessResult{AccessProblem::tilt};
      continue;
    }
    c.access = check_point_access(finder, c.xyz, c.normal, s.result.probe, access);
    point_ok[static_cast<std::size_t>(k)] = c.access.ok();
  }
  s.report("tips", 0, grid.size());

  // The tip cover: points are elements, orientations sets.
  TipCoverProblem problem;
  problem.elements = static_cast<int>(n);
  problem.maybe.resize(grid.size());
  problem.kinds.resize(grid.size());
  long pairs = 0;
  for (std::size_t o = 0; o < grid.size(); ++o) {
    const bool qualified = std::find(head.qualified.begin(), head.qualified.end(), grid[o]) != head.qualified.end();
    problem.kinds[o] = o == vertical ? TipKind::forced : qualified ? TipKind::qualified : TipKind::fresh;
    for (long k = 0; k < n; ++k) {
      if (!point_ok[static_cast<std::size_t>(k)]) continue;
      const double tilt = std::acos(std::clamp(candidates[static_cast<std::size_t>(k)].normal.dot(probes[o].axis), -1.0, 1.0));
      if (tilt <= access.max_tilt) problem.maybe[o].push_back(static_cast<int>(k));
    }
    pairs += static_cast<long>(problem.maybe[o].size());
    // The greedy tests the points most tilted from the axis first: the
    // likeliest to be blocked, so a tip that will not rank first is
    // found out with fewest checks.
    std::vector<int>& order = problem.test_order.emplace_back(problem.maybe[o].size());
    std::vector<double> cosine(problem.maybe[o].size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      order[i] = static_cast<int>(i);
      cosine[i] = candidates[static_cast<std::size_t>(problem.maybe[o][i])].normal.dot(probes[o].axis);
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return cosine[static_cast<std::size_t>(a)] < cosine[static_cast<std::size_t>(b)];
    });
  }
  problem.test = [&](int o, const std::vector<int>& list) {
    std::vector<char> out(list.size(), 0);
    const long m = static_cast<long>(list.size());
#pragma omp parallel for schedule(dynamic, 8)
    for (long i = 0; i < m; ++i) {
      const PlanCandidate& c = candidates[static_cast<std::size_t>(list[static_cast<std::size_t>(i)])];
      out[static_cast<std::size_t>(i)] =
          check_axis_access(finder, c.xyz, c.normal, probes[static_cast<std::size_t>(o)], access).ok();
    }
    return out;
  };
  TipCover cover = solve_tip_cover(problem, s.options.tip_cover);

  // The chosen tips: the vertical one first, then in grid order.
  std::vector<int> chosen = {static_cast<int>(vertical)};
  for (int o : cover.chosen)
    if (o != static_cast<int>(vertical)) chosen.push_back(o);
  s.tips.clear();
  s.tip_angles.clear();
  for (int o : chosen) {
    s.tips.push_back(probes[static_cast<std::size_t>(o)]);
    s.tip_angles.push_back(grid[static_cast<std::size_t>(o)]);
  }
  // Which chosen tips reach each point: known from the cover, or checked now.
  for (PlanCandidate& c : candidates) c.reach.assign(chosen.size(), 0);
  for (std::size_t t = 0; t < chosen.size(); ++t) {
    const int o = chosen[t];
    const std::vector<int>& maybe = problem.maybe[static_cast<std::size_t>(o)];
    const std::vector<signed char>& known = cover.known[static_cast<std::size_t>(o)];
    std::vector<int> untested;
    for (std::size_t i = 0; i < maybe.size(); ++i) {
      if (known[i] < 0) untested.push_back(maybe[i]);
      else candidates[static_cast<std::size_t>(maybe[i])].reach[t] = known[i];
    }
    if (untested.empty()) continue;
    const std::vector<char> got = problem.test(o, untested);
    for (std::size_t i = 0; i < untested.size(); ++i) candidates[static_cast<std::size_t>(untested[i])].reach[t] = got[i];
  }
  for (long k = 0; k < n; ++k) {
    PlanCandidate& c = candidates[static_cast<std::size_t>(k)];
    int nearest = 0;
    for (std::size_t t = 1; t < s.tips.size(); ++t)
      if (c.normal.dot(s.tips[t].axis) > c.normal.dot(s.tips[static_cast<std::size_t>(nearest)].axis))
        nearest = static_cast<int>(t);
    c.nearest_tip = nearest;
    c.kept = std::find(c.reach.begin(), c.reach.end(), 1) != c.reach.end();
  }
  // The reason for a point no chosen tip reaches, with the tip nearest its
  // normal (the tip-independent failure when there was one).
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < n; ++k) {
    PlanCandidate& c = candidates[static_cast<std::size_t>(k)];
    if (c.kept || !point_ok[static_cast<std::size_t>(k)]) continue;
    c.access = check_access(finder, c.xyz, c.normal, s.tips[static_cast<std::size_t>(c.nearest_tip)], access);
  }
  cover.known.clear();
  s.result.tip_choice.automatic = true;
  s.result.tip_choice.orientations = static_cast<int>(grid.size());
  s.result.tip_choice.pairs = pairs;
  s.result.tip_choice.cover = std::move(cover);
  s.report("tips", grid.size(), grid.size());
}

}  // namespace furrow
