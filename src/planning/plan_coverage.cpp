#include "planning/plan_coverage.hpp"

#include <algorithm>
#include <map>

namespace furrow {

namespace {

std::string plural(int n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

// Why region `s` holds fewer than `required` points, from the plan's issues.
std::string shortfall_reason(const RegionPlanSummary& s, const std::vector<PlanIssue>& issues) {
  std::vector<std::string> parts;
  std::map<AccessProblem, int> drops;
  for (const PlanIssue& i : issues) {
    if (i.region != s.region) continue;
    if (i.kind == PlanIssue::Kind::region_skipped) parts.push_back(i.reason);
    if (i.kind == PlanIssue::Kind::dropped) ++drops[i.problem];
  }
  if (s.samplable && s.sampled < s.allocated)
    parts.push_back("only " + std::to_string(s.sampled) + " of " + std::to_string(s.allocated) +
                    (s.contact_rule ? " allocated points fit where the ball measures the region alone (ball contact rule)"
                                    : " allocated points fit inside the region at the border clearance"));
  if (!drops.empty()) {
    std::string d = plural(s.dropped, "point") + " dropped, the probe cannot reach them (";
    bool first = true;
    for (const auto& [problem, count] : drops) {
      d += (first ? "" : "; ") + std::to_string(count) + ": " + to_string(problem);
      first = false;
    }
    parts.push_back(d + ")");
  }
  if (parts.empty() && s.allocated < 1) parts.push_back("the allocation gave it no point");
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
  return out;
}

// The state of a short region: too narrow for any ball position (the
// planner skipped it), else unreachable when the points dropped for access
// are what left it short (it would hold its minimum with them, or no point
// of it is reachable), else reachable but not planned. `access` gets the most frequent problem.
CoverageState shortfall_state(const RegionPlanSummary& s, int required, const std::vector<PlanIssue>& issues,
                              AccessProblem& access) {
  std::map<AccessProblem, int> drops;
  bool skipped = false;
  for (const PlanIssue& i : issues) {
    if (i.region != s.region) continue;
    if (i.kind == PlanIssue::Kind::region_skipped) skipped = true;
    if (i.kind == PlanIssue::Kind::dropped) ++drops[i.problem];
  }
  if (skipped || !s.samplable) return CoverageState::unreachable_narrow;
  if (s.dropped > 0 && (s.planned + s.dropped >= required || s.planned == 0)) {
    int most = 0;
    for (const auto& [problem, count] : drops)
      if (count > most) {  // ties: the first in AccessProblem order
        most = count;
        access = problem;
      }
    return CoverageState::unreachable_access;
  }
  return CoverageState::reachable_unplanned;
}

void add_area(CoverageArea& a, const RegionCoverage& r) {
  a.total += r.area;
  switch (r.state) {
    case CoverageState::covered: a.covered += r.area; break;
    case CoverageState::reachable_unplanned: a.reachable_unplanned += r.area; break;
    case CoverageState::unreachable_narrow: a.unreachable_narrow += r.area; break;
    case CoverageState::unreachable_access: {
      a.unreachable_access += r.area;
      auto& list = a.by_access_problem;
      auto it = std::find_if(list.begin(), list.end(), [&](const auto& e) { return e.first == r.access; });
      if (it == list.end()) list.emplace_back(r.access, r.area);
      else it->second += r.area;
      break;
    }
  }
}

}  // namespace

const char* to_string(CoverageState state) {
  switch (state) {
    case CoverageState::covered: return "covered";
    case CoverageState::reachable_unplanned: return "reachable_unplanned";
    case CoverageState::unreachable_narrow: return "unreachable_narrow";
    case CoverageState::unreachable_access: return "unreachable_access";
  }
  return "?";
}

PlanCoverage plan_coverage(const PlanResult& result, int min_per_region) {
  PlanCoverage c;
  std::map<int, FaceCoverage> faces;
  for (const RegionPlanSummary& s : result.regions) {
    if (s.elsewhere) continue;  // measured in another setup: counted there
    RegionCoverage r;
    r.region = s.region;
    r.face = s.face;
    r.required = min_per_region;
    r.allocated = s.allocated;
    r.planned = s.planned;
    r.dropped = s.dropped;
    r.covered = s.planned >= r.required;
    r.area = s.area;
    if (!r.covered) {
      r.reason = shortfall_reason(s, result.issues);
      r.state = shortfall_state(s, r.required, result.issues, r.access);
    }
    add_area(c.area, r);
    FaceCoverage& f = faces[s.face];
    f.face = s.face;
    ++f.regions;
    f.regions_covered += r.covered;
    f.allocated += s.allocated;
    f.planned += s.planned;
    f.dropped += s.dropped;
    c.regions_covered += r.covered;
    c.allocated += s.allocated;
    c.planned += s.planned;
    c.dropped += s.dropped;
    c.regions.push_back(std::move(r));
  }
  for (auto& [face, f] : faces) c.faces.push_back(f);
  std::sort(c.area.by_access_problem.begin(), c.area.by_access_problem.end());
  return c;
}

std::vector<RegionCoverage> PlanCoverage::uncovered() const {
  std::vector<RegionCoverage> out;
  for (const RegionCoverage& r : regions)
    if (!r.covered) out.push_back(r);
  return out;
}

std::string PlanCoverage::describe_uncovered(std::size_t max_lines) const {
  const std::vector<RegionCoverage> short_regions = uncovered();
  std::string out;
  for (std::size_t k = 0; k < short_regions.size() && k < max_lines; ++k) {
    const RegionCoverage& r = short_regions[k];
    out += "  region " + std::to_string(r.region) + " (face " + std::to_string(r.face) + "): " +
           std::to_string(r.planned) + " of " + std::to_string(r.required) + " points: " + r.reason + "\n";
  }
  if (short_regions.size() > max_lines)
    out += "  ... and " + std::to_string(short_regions.size() - max_lines) + " more (report.json \"coverage\")\n";
  return out;
}

PlanCoverage combine_coverage(const std::vector<PlanCoverage>& setups) {
  PlanCoverage c;
  std::map<int, RegionCoverage> latest;
  for (std::size_t k = 0; k < setups.size(); ++k) {
    for (RegionCoverage r : setups[k].regions) {
      r.setup = static_cast<int>(k) + 1;
      if (!r.reason.empty() && setups.size() > 1) r.reason = "setup " + std::to_string(k + 1) + ": " + r.reason;
      latest[r.region] = std::move(r);
    }
    c.allocated += setups[k].allocated;
    c.planned += setups[k].planned;
    c.dropped += setups[k].dropped;
  }
  std::map<int, FaceCoverage> faces;
  for (auto& [id, r] : latest) {
    add_area(c.area, r);
    c.regions_covered += r.covered;
    FaceCoverage& f = faces[r.face];
    f.face = r.face;
    ++f.regions;
    f.regions_covered += r.covered;
    c.regions.push_back(std::move(r));
  }
  // Points per face over every setup.
  for (const PlanCoverage& s : setups)
    for (const FaceCoverage& g : s.faces) {
      FaceCoverage& f = faces[g.face];
      f.allocated += g.allocated;
      f.planned += g.planned;
      f.dropped += g.dropped;
    }
  for (auto& [face, f] : faces) c.faces.push_back(f);
  std::sort(c.area.by_access_problem.begin(), c.area.by_access_problem.end());
  return c;
}

}  // namespace furrow
