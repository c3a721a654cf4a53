#pragma once
// The steps of plan_probe_points (probe_planner.hpp), in the order it runs
// them, each a function of one PlanState that the step reads and extends
// (docs/cmm.md "How the points are chosen" says what each decides):
//
//   start_plan       resolved probe, tips of an indexable head, clearance
//                    plane and access options; the result's fixed members
//   measure_regions  a domain per region, its statistics, whether it can
//                    hold a point; gouge sites mapped to their regions
//   allocate         the point budget shared over the regions
//   sample           candidate points, the gouge sites' first
//   check_reach      access per candidate (and per tip), relocation of the
//                    blocked ones, the tip per point
//   order            drops reported, the kept points' tour
//   emit_points      plan points in execution order, moves, cycle time
//
// Why one state and not seven signatures: the steps share a dozen
// intermediate arrays (domains, demands, candidates, kept indices) that
// only exist while a plan is made; passing them one by one hid which step
// wrote what. Each step's comment says what it reads and what it sets.
// Errors: InputError (bad options, nothing plannable), as plan_probe_points.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "planning/allocation.hpp"
#include "planning/probe_planner.hpp"
#include "planning/region_domain.hpp"

namespace furrow {

// A point before ordering.
struct PlanCandidate {
  int region = 0;
  std::string site;  // gouge site id, or ""
  Eigen::AlignedBox2d site_box;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  // Outcome of the access check.
  bool kept = false;
  bool moved = false;
  Eigen::Vector3d original = Eigen::Vector3d::Zero();
  double moved_by = 0;
  AccessResult access;
  // With an indexable head: which of the plan's tips reach the point, the tip
  // nearest the normal (whose access result `access` is when none reaches)
  // and the tip chosen.
  std::vector<char> reach;
  int nearest_tip = -1;
  int tip = -1;
};

// A gouge site that reserves points in the region holding its centre.
struct PlanSiteRequest {
  const RiskSite* site;
  int region;
};

struct PlanState {
  PlanState(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
            const PlanProgress& progress);

  // Inputs (kept by reference: they outlive the plan).
  const Part& part;
  const RegionMap& map;
  const PlannerOptions& options;
  const RiskMap* risk;  // may be null
  const PlanProgress& progress;
  const ClosestPointFinder finder;

  PlanResult result;
  // With a head: the tips the plan may use (the qualified ones, or those
  // the planner chose: auto_tips.hpp) and their angles; empty without one.
  std::vector<ProbeGeometry> tips;
  std::vector<TipAngles> tip_angles;
  AccessOptions access;
  std::vector<RegionDomain> domains;         // per region
  std::vector<RegionDemand> demands;         // per region
  double kappa_ref = 0;                      // area-weighted mean |k|max over the regions [1/mm]
  std::vector<PlanSiteRequest> sites;
  std::vector<PlanCandidate> candidates;
  std::vector<double> spacing;               // per region: mean point spacing [mm]
  std::vector<std::size_t> kept;             // indices into candidates, sampling order
  std::vector<Eigen::Vector3d> centres;      // probe centres of `kept`
  std::vector<int> kept_tips;                // tip of each of `kept`

  void report(const char* stage, std::size_t done, std::size_t total) const {
    if (progress) progress(stage, done, total);
  }
};

// Sets result.border, search, approach, retract, probe, clearance_z; tips
// and access. Reads options only (validated by the caller).
void start_plan(PlanState& s);
// Sets domains, demands, kappa_ref, sites, result.regions (statistics and
// samplable) and their issues.
void measure_regions(PlanState& s);
// Sets result.allocation (and the budget_raised issue). Throws InputError
// when the budget is out of limits or no point can be planned.
void allocate(PlanState& s);
// Sets candidates and result.regions' weight, allocated, gouge_points and
// sampled (with region_short / gouge_site issues).
void sample(PlanState& s);
// Sets each candidate's normal, access, kept/moved (relocating blocked ones
// without a head) and tip; spacing.
void check_reach(PlanState& s);
// Reports dropped points (and faces facing down), sets kept, centres,
// kept_tips, result.tour and tip_changes. Throws InputError when no point
// is accessible.
void order(PlanState& s);
// Sets result.plan's points in tour order (moved-point issues), moves,
// start, final_moves and cycle.
void emit_points(PlanState& s);

}  // namespace furrow
