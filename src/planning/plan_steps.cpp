#include "planning/plan_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/numbers.hpp"
#include "planning/auto_tips.hpp"
#include "planning/face_orientation_hint.hpp"
#include "planning/narrow_region.hpp"
#include "planning/relocation.hpp"
#include "planning/tip_groups.hpp"
#include "planning/tip_grid.hpp"

namespace furrow {

namespace {

std::string mm(double v) { return fixed(v, 3); }

std::string at_text(const Eigen::Vector3d& p) { return "(" + mm(p.x()) + ", " + mm(p.y()) + ", " + mm(p.z()) + ")"; }

std::string problem_text(const AccessResult& a, const ProbeGeometry& probe) {
  std::string s = to_string(a.problem);
  if (a.problem == AccessProblem::tilt) return s + " (" + mm(degrees(a.tilt)) + " degrees)";
  if (a.problem == AccessProblem::fixture)
    return s + " (at " + at_text(a.where) + ", " + mm(a.distance) + " mm above the plane)";
  const double allowed = a.problem == AccessProblem::stylus ? probe.stylus_radius : probe.ball_radius;
  if (a.step_cap) return s + " (the clearance march hit its step cap near " + at_text(a.where) + ")";
  // The head's assembly: capsules of several radii, swept (accessibility.hpp).
  if (probe.articulated() && a.problem != AccessProblem::ball && a.problem != AccessProblem::approach_path)
    return s + " (part " + mm(a.distance) + " mm from the probe's axis at " + at_text(a.where) + ")";
  return s + " (part " + mm(a.distance) + " mm from " + (a.problem == AccessProblem::stylus ? "the shaft axis" : "the ball centre") +
         " at " + at_text(a.where) + ", needs " + mm(allowed) + ")";
}



// Probe geometry per tip: the axis runs from the ball towards the head.
std::vector<ProbeGeometry> tip_probes(const ProbeGeometry& probe, const std::vector<TipAngles>& angles) {
  std::vector<ProbeGeometry> out;
  for (const TipAngles& t : angles) {
    ProbeGeometry g = probe;
    g.axis = -tip_direction(t);
    out.push_back(g);
  }
  return out;
}

// The tip whose axis is nearest `n` among those with `allowed` (all when null); ties: the first.
int nearest_tip(const std::vector<ProbeGeometry>& tips, const Eigen::Vector3d& n, const std::vector<char>* allowed) {
  int best = -1;
  for (std::size_t t = 0; t < tips.size(); ++t) {
    if (allowed && !(*allowed)[t]) continue;
    if (best < 0 || n.dot(tips[t].axis) > n.dot(tips[static_cast<std::size_t>(best)].axis)) best = static_cast<int>(t);
  }
  return best;
}

// With a head, the tips nearest the normal that relocation tries in turn
// for a point no tip reaches (each over the relocation's rings): a tilted
// wall is reached by the tips leaning towards its normal, and trying all of
// a 21-tip head would cost 21 relocations per point.
constexpr std::size_t kRelocationTips = 3;

// A point the probe (no tip of the head) cannot take, moved to the nearest
// place in its region that it (one of the tips nearest its normal) can;
// with a head, which tips reach it there is recomputed.
void relocate_candidate(PlanCandidate& c, const PlanState& s, const RegionDomain& domain, double spacing) {
  const PlannerOptions& options = s.options;
  const RelocationOptions ro{options.max_move_fraction * spacing, options.relocation_rings,
                             options.relocation_directions};
  std::function<bool(const Eigen::Vector2d&)> keep;
  if (!c.site.empty()) keep = [&c](const Eigen::Vector2d& uv) { return c.site_box.contains(uv); };
  std::vector<const ProbeGeometry*> probes;
  if (s.tips.empty()) {
    probes.push_back(&s.result.probe);
  } else {
    std::vector<std::size_t> order(s.tips.size());
    for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return c.normal.dot(s.tips[a].axis) > c.normal.dot(s.tips[b].axis);
    });
    for (std::size_t k = 0; k < std::min(kRelocationTips, order.size()); ++k) probes.push_back(&s.tips[order[k]]);
  }
  for (const ProbeGeometry* probe : probes) {
    const std::optional<Relocated> moved =
        relocate(domain, s.finder, c.uv, *probe, s.access, ro, !c.site.empty(), keep);
    if (!moved) continue;
    c.kept = c.moved = true;
    c.uv = moved->uv;
    c.xyz = moved->xyz;
    c.normal = moved->normal;
    c.moved_by = moved->distance;
    if (!s.tips.empty()) {
      for (std::size_t t = 0; t < s.tips.size(); ++t)
        c.reach[t] = check_access(s.finder, c.xyz, c.normal, s.tips[t], s.access).ok();
      c.nearest_tip = nearest_tip(s.tips, c.normal, nullptr);
      c.access = check_access(s.finder, c.xyz, c.normal, s.tips[static_cast<std::size_t>(c.nearest_tip)], s.access);
    }
    return;
  }
}

bool samplable(const RegionDomain& domain) {
  for (const DomainCell& c : domain.cells())
    if (c.inside && domain.admissible(c.uv)) return true;
  SamplingOptions probe;
  probe.min_candidates = 4096;
  return sample_region(domain, SamplingStrategy::halton, 1, 0, 1, probe).points.size() == 1;
}

}  // namespace

PlanState::PlanState(const Part& part_, const RegionMap& map_, const PlannerOptions& options_, const RiskMap* risk_,
                     const PlanProgress& progress_)
    : part(part_), map(map_), options(options_), risk(risk_), progress(progress_), finder(part_) {}

void start_plan(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  const Part& part = s.part;
  std::vector<ProbeGeometry>& tips = s.tips;
  AccessOptions& access = s.access;
  result.border = border_clearance(options);
  result.search = search_distance(options);
  result.approach = options.approach;
  result.retract = options.retract;
  result.probe = planner_probe(options);
  result.clearance_z = clearance_plane(part, result.probe.ball_radius, options.clearance);
  if (options.head) {
    // Raised so that the assembly clears the part over any tilt up to the
    // largest A the plan may use (qualified, or of the grid when the
    // planner chooses): the head turns on this plane.
    const bool automatic = options.tips == TipChoice::automatic;
    const std::vector<TipAngles> grid = automatic ? tip_grid(*options.head) : std::vector<TipAngles>{};
    double max_a = 0;
    for (const TipAngles& t : automatic ? grid : options.head->qualified) max_a = std::max(max_a, t.a);
    result.clearance_z += assembly_drop(result.probe, max_a) - result.probe.ball_radius;
    if (automatic) {
      if (const auto v = vertical_orientation(grid)) result.vertical_tip = grid[*v];
    } else {
      s.tip_angles = options.head->qualified;
      tips = tip_probes(result.probe, s.tip_angles);
      for (const TipAngles& t : options.head->qualified)
        if (t.a == 0 && !result.vertical_tip) result.vertical_tip = t;
    }
  }
  access = options.access;
  access.approach = options.approach;
  access.retract = options.retract;
  access.max_tilt = options.max_tilt_degrees * kPi / 180;
  access.clearance_z = result.clearance_z;
}

void measure_regions(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  const Part& part = s.part;
  const RegionMap& map = s.map;
  const RiskMap* risk = s.risk;
  std::vector<RegionDomain>& domains = s.domains;
  std::vector<RegionDemand>& demands = s.demands;
  std::vector<PlanSiteRequest>& sites = s.sites;
  const ClosestPointFinder& s_finder = s.finder;
  RegionDomainOptions domain_options = options.domain;
  domain_options.border = result.border;
  const std::size_t region_count = map.regions.size();
  // A region measured in another setup is never sampled: its domain only
  // holds its place, on the coarsest grid.
  RegionDomainOptions elsewhere_options = domain_options;
  elsewhere_options.min_cells = elsewhere_options.max_cells = 1;
  for (std::size_t r = 0; r < region_count; ++r) {
    const bool elsewhere = r < options.planned_elsewhere.size() && options.planned_elsewhere[r];
    domains.emplace_back(part, map, static_cast<int>(r), elsewhere ? elsewhere_options : domain_options, risk);
    s.report("regions", r + 1, region_count);
  }
  demands.assign(region_count, RegionDemand{});
  double kappa_area = 0, area_all = 0;
  for (std::size_t r = 0; r < region_count; ++r) {
    const Region& region = map.regions[r];
    const DomainStatistics& s = domains[r].statistics();
    RegionPlanSummary summary;
    summary.region = region.id;
    summary.face = region.face;
    summary.curvature_class = region.curvature_class;
    summary.area = region.area;
    summary.curvature_spread = s.curvature_spread;
    summary.mean_risk = s.mean_risk;
    // Measured in another setup (docs/cmm.md "Setups"): no points here, no issue.
    summary.elsewhere = r < options.planned_elsewhere.size() && options.planned_elsewhere[r];
    summary.samplable = !summary.elsewhere && region.area > 0 && samplable(domains[r]);
    PlanIssue issue;
    issue.kind = PlanIssue::Kind::region_skipped;
    issue.region = region.id;
    issue.reason = "no point of the region is " + mm(result.border) + " mm from its edges (border clearance)";
    if (!summary.samplable && !summary.elsewhere && region.area > 0 && !options.border) {
      // Too narrow for the default border: the ball-contact rule
      // (docs/cmm.md "Narrow regions").
      const double radius = result.probe.ball_radius;
      RegionDomain narrow =
          contact_rule_domain(part, map, static_cast<int>(r), domain_options, risk, s_finder, radius, options.contact);
      if (samplable(narrow)) {
        domains[r] = std::move(narrow);
        summary.samplable = summary.contact_rule = true;
      } else {
        const double fits = largest_ball_in_region(narrow, map, s_finder, radius, options.contact);
        issue.largest_ball_diameter = 2 * fits;
        issue.reason = "no position of the " + mm(2 * radius) + " mm ball measures the region alone with its contact " +
                       "staying in it when the ball is " + mm(options.contact.shift) + " mm off (ball contact rule); " +
                       (fits > 0 ? "the largest ball that would: " + mm(2 * fits) + " mm"
                                 : "no ball down to " + mm(0.01) + " mm would");
      }
    }
    result.regions.push_back(summary);
    demands[r] = {region.area, s.curvature_spread, s.mean_risk, 0, summary.samplable};
    kappa_area += s.mean_kappa * s.area;
    area_all += s.area;
    if (!summary.samplable && !summary.elsewhere) result.issues.push_back(issue);
  }
  s.kappa_ref = area_all > 0 ? kappa_area / area_all : 0;

  // Gouge sites reserve points in the region holding their centre.
  if (risk) {
    for (const RiskSite& site : risk->gouge_sites()) {
      const std::optional<int> region = map.region_at(site.face, site.uv_centre.x(), site.uv_centre.y());
      if (!region || !result.regions[static_cast<std::size_t>(*region)].samplable) {
        PlanIssue issue;
        issue.kind = PlanIssue::Kind::gouge_site;
        issue.gouge_site = site.id;
        issue.reason = region ? "the gouge site lies in a region that cannot hold points" : "the gouge site is in no region";
        result.issues.push_back(issue);
        continue;
      }
      sites.push_back({&site, *region});
      demands[static_cast<std::size_t>(*region)].gouge_points += options.gouge_points;
    }
  }
}

void allocate(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  std::vector<RegionDemand>& demands = s.demands;
  const std::size_t region_count = s.map.regions.size();
  double samplable_area = 0;
  for (std::size_t r = 0; r < region_count; ++r)
    if (demands[r].samplable) samplable_area += demands[r].area;
  // A density describes the regions wide enough for the border clearance:
  // the floors of regions planned by the contact rule (fillets, strips,
  // small faces) come on top of it instead of being taken from their
  // neighbours (docs/cmm.md "Narrow regions").
  double narrow_floors = 0;
  for (const RegionPlanSummary& r : result.regions)
    if (r.contact_rule) narrow_floors += options.min_per_region;
  // Counted in double first: a huge density must not overflow (docs/formats.md "Limits").
  const double wanted = options.points ? static_cast<double>(*options.points)
                                       : options.density.value_or(kDefaultDensity) * samplable_area / 100.0 +
                                             narrow_floors;
  if (!(wanted <= static_cast<double>(limits::kMaxPlanPoints))) {
    std::ostringstream text;
    text << "--density " << options.density.value_or(kDefaultDensity) << " points per cm^2 over " << samplable_area
      << " mm^2 asks for " << wanted << " points, more than the limit of " << limits::kMaxPlanPoints
      << " (docs/formats.md \"Limits\")";
    throw InputError(text.str());
  }
  const long budget = std::lround(wanted);
  result.allocation = allocate_points(demands, budget, options.min_per_region, options.weights);
  if (result.allocation.total == 0)
    throw InputError(samplable_area > 0 ? "the plan would have no points: raise --density or --points"
                                        : "no region can hold a probe point " + mm(result.border) +
                                              " mm from its edges: lower --border or use a smaller probe");
  if (result.allocation.floors_exceed_budget) {
    PlanIssue issue;
    issue.kind = PlanIssue::Kind::budget_raised;
    issue.reason = "the budget of " + std::to_string(budget) + " points is below the minimum per region; planned " +
                   std::to_string(result.allocation.total);
    result.issues.push_back(issue);
  }
}

// Region by region, each gouge site's points first.
void sample(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  const std::vector<RegionDomain>& domains = s.domains;
  std::vector<RegionDemand>& demands = s.demands;
  std::vector<PlanSiteRequest>& sites = s.sites;
  std::vector<PlanCandidate>& candidates = s.candidates;
  const std::size_t region_count = s.map.regions.size();
  for (std::size_t r = 0; r < region_count; ++r) {
    RegionPlanSummary& summary = result.regions[r];
    summary.weight = result.allocation.weights[r];
    summary.allocated = result.allocation.counts[r];
    summary.gouge_points = demands[r].gouge_points;
    if (!summary.samplable || summary.allocated == 0) continue;
    const std::size_t first = candidates.size();
    for (std::size_t s = 0; s < sites.size(); ++s) {
      if (sites[s].region != static_cast<int>(r)) continue;
      const RiskSite& site = *sites[s].site;
      const RegionSample got = sample_site(domains[r], site.uv_box, site.uv_centre,
                                           static_cast<std::size_t>(options.gouge_points),
                                           region_seed(options.seed, static_cast<int>(region_count + s)), options.sampling);
      for (const SampledPoint& p : got.points) {
        PlanCandidate c;
        c.region = static_cast<int>(r);
        c.site = site.id;
        c.site_box = site.uv_box;
        c.uv = p.uv;
        c.xyz = p.xyz;
        candidates.push_back(c);
      }
      if (got.short_by > 0) {
        PlanIssue issue;
        issue.kind = PlanIssue::Kind::gouge_site;
        issue.gouge_site = site.id;
        issue.region = static_cast<int>(r);
        issue.reason = std::to_string(got.points.size()) + " of " + std::to_string(options.gouge_points) +
                       " points fit on the site: the rest of it is within " + mm(result.border) +
                       " mm of the face's edges (border clearance)";
        result.issues.push_back(issue);
      }
    }
    const std::size_t want = static_cast<std::size_t>(summary.allocated) - (candidates.size() - first);
    const RegionSample got = sample_region(domains[r], options.strategy, want, region_seed(options.seed, static_cast<int>(r)),
                                           s.kappa_ref, options.sampling);
    for (const SampledPoint& p : got.points) {
      PlanCandidate c;
      c.region = static_cast<int>(r);
      c.uv = p.uv;
      c.xyz = p.xyz;
      candidates.push_back(c);
    }
    summary.sampled = static_cast<int>(candidates.size() - first);
    if (summary.sampled < summary.allocated) {
      PlanIssue issue;
      issue.kind = PlanIssue::Kind::region_short;
      issue.region = summary.region;
      issue.reason = "only " + std::to_string(summary.sampled) + " of " + std::to_string(summary.allocated) +
                     (summary.contact_rule ? " points fit where the ball measures the region alone (ball contact rule)"
                                           : " points fit " + mm(result.border) + " mm from the region's edges");
      result.issues.push_back(issue);
    }
    s.report("sampling", r + 1, region_count);
  }
}

// In parallel, each candidate into its own slot.
void check_reach(PlanState& s) {
  PlanResult& result = s.result;
  const RegionMap& map = s.map;
  const std::vector<ProbeGeometry>& tips = s.tips;
  const AccessOptions& access = s.access;
  const std::vector<RegionDomain>& domains = s.domains;
  std::vector<PlanCandidate>& candidates = s.candidates;
  std::vector<double>& spacing = s.spacing;
  const ClosestPointFinder& finder = s.finder;
  const std::size_t region_count = s.map.regions.size();
  const long n_candidates = static_cast<long>(candidates.size());
  spacing.assign(region_count, 1.0);
  for (std::size_t r = 0; r < region_count; ++r)
    if (result.regions[r].sampled > 0) spacing[r] = std::sqrt(map.regions[r].area / result.regions[r].sampled);
  std::size_t checked = 0;
  if (s.options.head && s.options.tips == TipChoice::automatic) {
    // The planner chooses the tips; then the points none of them reaches
    // are relocated as below.
    choose_auto_tips(s);
#pragma omp parallel for schedule(dynamic, 16)
    for (long k = 0; k < n_candidates; ++k) {
      PlanCandidate& c = candidates[static_cast<std::size_t>(k)];
      if (c.kept) continue;
      relocate_candidate(c, s, domains[static_cast<std::size_t>(c.region)], spacing[static_cast<std::size_t>(c.region)]);
    }
  } else {
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < n_candidates; ++k) {
    PlanCandidate& c = candidates[static_cast<std::size_t>(k)];
    const RegionDomain& domain = domains[static_cast<std::size_t>(c.region)];
    const DifferentialGeometry g = domain.face().geometry(c.uv.x(), c.uv.y());
    c.original = c.xyz;
    c.normal = g.normal;
    if (!tips.empty()) {
      c.reach.assign(tips.size(), 0);
      c.nearest_tip = nearest_tip(tips, c.normal, nullptr);
      c.access = AccessResult{AccessProblem::tilt};
      for (std::size_t t = 0; t < tips.size() && !g.degenerate; ++t) {
        const AccessResult a = check_access(finder, c.xyz, c.normal, tips[t], access);
        c.reach[t] = a.ok();
        if (static_cast<int>(t) == c.nearest_tip) c.access = a;
      }
      c.kept = std::find(c.reach.begin(), c.reach.end(), 1) != c.reach.end();
    } else {
      c.access = g.degenerate ? AccessResult{AccessProblem::tilt} : check_access(finder, c.xyz, c.normal, result.probe, access);
      c.kept = !g.degenerate && c.access.ok();
    }
    if (!c.kept) relocate_candidate(c, s, domain, spacing[static_cast<std::size_t>(c.region)]);
#pragma omp critical(plan_progress)
    {
      ++checked;
      if (s.progress && (checked % 64 == 0 || checked == candidates.size())) s.progress("access", checked, candidates.size());
    }
  }
  }
  // The tip per point, in sampling order: keep the previous point's tip
  // while it reaches, else the reaching tip nearest the normal.
  if (!tips.empty()) {
    int current = -1;
    for (PlanCandidate& c : candidates) {
      if (!c.kept) continue;
      if (current < 0 || !c.reach[static_cast<std::size_t>(current)]) current = nearest_tip(tips, c.normal, &c.reach);
      c.tip = current;
    }
  }
}

void order(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  const Part& part = s.part;
  const std::vector<ProbeGeometry>& tips = s.tips;
  const std::vector<RegionDomain>& domains = s.domains;
  std::vector<PlanCandidate>& candidates = s.candidates;
  std::vector<double>& spacing = s.spacing;
  std::vector<std::size_t>& kept = s.kept;
  std::vector<Eigen::Vector3d>& centres = s.centres;
  std::vector<int>& kept_tips = s.kept_tips;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    PlanCandidate& c = candidates[k];
    RegionPlanSummary& summary = result.regions[static_cast<std::size_t>(c.region)];
    if (!c.kept) {
      ++summary.dropped;
      PlanIssue issue;
      issue.kind = PlanIssue::Kind::dropped;
      issue.region = summary.region;
      issue.gouge_site = c.site;
      issue.problem = c.access.problem;
      issue.where = c.original;
      if (!tips.empty())
        issue.reason = std::string(options.tips == TipChoice::automatic
                                       ? "no orientation of the head's grid reaches the point; of the chosen tips "
                                         "the one nearest its normal, "
                                       : "no qualified tip reaches the point; the tip nearest its normal, ") +
                       tip_name(s.tip_angles[static_cast<std::size_t>(c.nearest_tip)]) + ": " +
                       problem_text(c.access, tips[static_cast<std::size_t>(c.nearest_tip)]);
      else
        issue.reason = problem_text(c.access, result.probe) + "; no accessible point within " +
                       mm(options.max_move_fraction * spacing[static_cast<std::size_t>(c.region)]) + " mm";
      result.issues.push_back(issue);
      continue;
    }
    if (c.moved) ++summary.moved;
    ++summary.planned;
    kept.push_back(k);
    centres.push_back(probe_centre(c.xyz, c.normal, result.probe));
    kept_tips.push_back(c.tip);
  }
  // Most points dropped: name the faces that face down, the usual cause
  // being normals into the material rather than the probe; faces whose
  // orientation the import established from topology are undersides
  // (docs/cmm.md "Faces that face down").
  std::string orientation_hint;
  if (2 * kept.size() < candidates.size()) {
    std::vector<OrientationSample> samples;
    samples.reserve(candidates.size());
    for (const PlanCandidate& c : candidates)
      samples.push_back({static_cast<std::size_t>(domains[static_cast<std::size_t>(c.region)].face_index()), c.normal, c.kept});
    for (const FaceFacingDown& f : faces_facing_down(samples, part.faces)) {
      PlanIssue issue;
      issue.kind = PlanIssue::Kind::face_facing_down;
      issue.face = static_cast<int>(f.face);
      issue.reason = describe(f) + "; " + kFacingDownHint;
      result.issues.push_back(issue);
      orientation_hint += (orientation_hint.empty() ? "; " : ", ") + describe(f);
    }
    if (!orientation_hint.empty()) orientation_hint += "; " + std::string(kFacingDownHint);
  }
  if (kept.empty())
    throw InputError("no planned point is accessible with this probe (" + std::to_string(candidates.size()) +
                     " candidates dropped" +
                     (orientation_hint.empty()
                          ? std::string("; see the reasons with a smaller probe, a longer stylus or a larger --max-tilt)")
                          : ")" + orientation_hint));
  if (tips.empty()) {
    result.tour = plan_tour(centres, options.tour);
  } else {
    result.tour = grouped_tour(centres, kept_tips, options.tour);
    result.tip_changes = group_changes(kept_tips, result.tour.order);
  }
}

void emit_points(PlanState& s) {
  PlanResult& result = s.result;
  const PlannerOptions& options = s.options;
  const Part& part = s.part;
  const RegionMap& map = s.map;
  const std::vector<ProbeGeometry>& tips = s.tips;
  const AccessOptions& access = s.access;
  const std::vector<RegionDomain>& domains = s.domains;
  std::vector<PlanCandidate>& candidates = s.candidates;
  std::vector<std::size_t>& kept = s.kept;
  const ClosestPointFinder& finder = s.finder;
  const std::size_t n = kept.size();
  const int width = std::max<int>(4, static_cast<int>(std::to_string(n).size()));
  result.plan.part = options.part_name;
  result.plan.probe = {options.probe_name, options.probe_diameter};
  std::vector<Eigen::Vector3d> retracts(n);
  for (std::size_t k = 0; k < n; ++k) {
    const PlanCandidate& c = candidates[kept[static_cast<std::size_t>(result.tour.order[k])]];
    PlannedPoint p;
    const std::string number = std::to_string(k + 1);
    p.id = "P" + std::string(static_cast<std::size_t>(width) - std::min<std::size_t>(number.size(), static_cast<std::size_t>(width)), '0') + number;
    p.order = static_cast<int>(k) + 1;
    p.face_index = static_cast<std::size_t>(domains[static_cast<std::size_t>(c.region)].face_index());
    p.face = part.faces[p.face_index].name();
    p.region = map.regions[static_cast<std::size_t>(c.region)].id;
    p.uv = c.uv;
    p.xyz = c.xyz;
    p.ijk = c.normal;
    p.approach = approach_point(c.xyz, c.normal, result.probe, access);
    p.retract = retract_point(c.xyz, c.normal, result.probe, access);
    if (!tips.empty()) p.tip = s.tip_angles[static_cast<std::size_t>(c.tip)];
    retracts[k] = p.retract;
    if (c.moved) {
      PlanIssue issue;
      issue.kind = PlanIssue::Kind::moved;
      issue.point = p.id;
      issue.region = *p.region;
      issue.gouge_site = c.site;
      issue.problem = c.access.problem;
      issue.where = c.original;
      issue.distance = c.moved_by;
      issue.reason = problem_text(c.access, result.probe) + "; moved " + mm(c.moved_by) + " mm";
      result.issues.push_back(issue);
    }
    result.plan.points.push_back(std::move(p));
    result.point_sites.push_back(c.site);
  }
  MoveOptions move_options;
  move_options.clearance = options.clearance;
  move_options.clearance_z = result.clearance_z;
  move_options.contact_tolerance = access.contact_tolerance;
  move_options.min_step = access.min_step;
  move_options.max_steps = access.max_steps;
  result.moves.resize(n);
  const PlannedPoint& first = result.plan.points.front();
  result.start = {first.approach.x(), first.approach.y(), std::max(result.clearance_z, first.approach.z())};
  result.moves[0].straight = false;
  result.moves[0].waypoints = {first.approach};
  result.moves[0].length = (first.approach - result.start).norm();
  // With a head: a straight move also needs the assembly clear along it
  // (as the ball, `clearance` from the part); a tip change goes over the plane.
  std::vector<int> point_tips(n, -1);
  for (std::size_t k = 0; k < n; ++k) point_tips[k] = candidates[kept[static_cast<std::size_t>(result.tour.order[k])]].tip;
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 1; k < static_cast<long>(n); ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const Eigen::Vector3d& from = result.plan.points[i - 1].retract;
    const Eigen::Vector3d& to = result.plan.points[i].approach;
    if (tips.empty()) {
      result.moves[i] = plan_move(finder, from, to, result.probe.ball_radius, move_options);
      continue;
    }
    Move m = point_tips[i] == point_tips[i - 1] ? plan_move(finder, from, to, result.probe.ball_radius, move_options)
                                                : plane_move(from, to, result.clearance_z);
    if (m.straight)
      for (const ProbeCapsule& cap : probe_capsules(from, tips[static_cast<std::size_t>(point_tips[i])]))
        if (swept_contact(finder, cap.a, cap.b, to - from, cap.radius + options.clearance, access.contact_tolerance,
                          access.min_step, access.max_steps)) {
          m = plane_move(from, to, result.clearance_z);
          break;
        }
    result.moves[i] = m;
  }
  const Eigen::Vector3d& last = result.plan.points.back().retract;
  if (last.z() < result.clearance_z) result.final_moves = {Eigen::Vector3d(last.x(), last.y(), result.clearance_z)};
  result.plan.tips = tips_in_use(result, options);
  result.cycle = estimate_cycle(result.start, result.moves, retracts, result.final_moves, options.approach,
                                options.retract, options.motion);
}

}  // namespace furrow
