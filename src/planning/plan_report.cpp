#include "planning/plan_report.hpp"

#include "base/json_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

json coverage_json(const PlanCoverage& coverage) {
  json cov;
  cov["complete"] = coverage.complete();
  cov["regions"] = coverage.regions.size();
  cov["regions_covered"] = coverage.regions_covered;
  cov["allocated"] = coverage.allocated;
  cov["planned"] = coverage.planned;
  cov["dropped"] = coverage.dropped;
  const CoverageArea& a = coverage.area;
  json by_problem = json::object();
  for (const auto& [problem, area] : a.by_access_problem) by_problem[to_string(problem)] = area;
  cov["area"] = {{"total", a.total},
                 {"covered", a.covered},
                 {"reachable_unplanned", a.reachable_unplanned},
                 {"unreachable_narrow", a.unreachable_narrow},
                 {"unreachable_access", a.unreachable_access},
                 {"unreachable_by_access_problem", std::move(by_problem)}};
  json faces = json::array();
  for (const FaceCoverage& f : coverage.faces)
    faces.push_back({{"face", f.face},
                     {"regions", f.regions},
                     {"regions_covered", f.regions_covered},
                     {"allocated", f.allocated},
                     {"planned", f.planned},
                     {"dropped", f.dropped}});
  cov["faces"] = std::move(faces);
  json short_regions = json::array();
  for (const RegionCoverage& c : coverage.uncovered()) {
    short_regions.push_back({{"region", c.region},
                             {"face", c.face},
                             {"required", c.required},
                             {"allocated", c.allocated},
                             {"planned", c.planned},
                             {"dropped", c.dropped},
                             {"area", c.area},
                             {"state", to_string(c.state)},
                             {"reason", c.reason}});
    if (c.setup > 0) short_regions.back()["setup"] = c.setup;
  }
  cov["uncovered_regions"] = std::move(short_regions);
  return cov;
}

std::string plan_report_json(const PlanResult& r, const PlanCoverage& coverage, const PlannerOptions& o, const std::string& part_path,
                             const std::string& regions_path, const std::string& prediction_path) {
  json doc;
  doc["format"] = "furrow-plan-report";
  doc["version"] = 1;
  doc["units"] = "mm";
  doc["part"] = part_path;
  doc["regions_file"] = regions_path;
  if (!prediction_path.empty()) doc["prediction_file"] = prediction_path;
  json opt;
  if (o.points) opt["points"] = *o.points;
  else opt["density_per_cm2"] = jf::finite(o.density.value_or(kDefaultDensity), "density");
  opt["min_per_region"] = o.min_per_region;
  opt["strategy"] = to_string(o.strategy);
  opt["seed"] = o.seed;
  opt["border_mm"] = jf::finite(r.border, "border");
  // The ball-contact rule of narrow regions applies without an explicit border.
  if (!o.border) opt["contact_shift_mm"] = jf::finite(o.contact.shift, "contact shift");
  opt["probe"] = {{"name", o.probe_name},
                  {"ball_diameter", jf::finite(o.probe_diameter, "probe diameter")},
                  {"stylus_diameter", jf::finite(o.stylus_diameter, "stylus diameter")},
                  {"stylus_length", jf::finite(o.stylus_length, "stylus length")}};
  opt["approach_mm"] = jf::finite(o.approach, "approach");
  opt["retract_mm"] = jf::finite(o.retract, "retract");
  opt["search_mm"] = jf::finite(r.search, "search");
  opt["clearance_mm"] = jf::finite(o.clearance, "clearance");
  opt["clearance_plane_z"] = jf::finite(r.clearance_z, "clearance plane");
  opt["max_tilt_deg"] = jf::finite(o.max_tilt_degrees, "max tilt");
  opt["move_speed_mm_s"] = jf::finite(o.motion.move_speed, "move speed");
  opt["touch_speed_mm_s"] = jf::finite(o.motion.touch_speed, "touch speed");
  opt["acceleration_mm_s2"] = jf::finite(o.motion.acceleration, "acceleration");
  opt["dwell_s"] = jf::finite(o.motion.dwell, "dwell");
  opt["gouge_points"] = o.gouge_points;
  if (o.head) {
    json tips = json::array();
    for (const TipAngles& t : o.head->qualified) tips.push_back(tip_name(t));
    opt["head"] = {{"type", o.head->type},
                   {"head_to_ball_mm", jf::finite(o.head->reach(), "head reach")},
                   {"qualified", std::move(tips)},
                   {"tips", to_string(o.tips)}};
  }
  doc["options"] = std::move(opt);
  // The tips the operator must have qualified, in the order the program
  // uses them (docs/cmm.md "Tips chosen by the planner").
  if (o.head) {
    json order = json::array();
    int fresh = 0;
    for (const PlanTip& t : r.plan.tips) {
      int points = 0;
      for (const PlannedPoint& p : r.plan.points) points += p.tip && *p.tip == t.angles;
      order.push_back({{"name", tip_name(t.angles)},
                       {"a", jf::finite(t.angles.a, "tip a")},
                       {"b", jf::finite(t.angles.b, "tip b")},
                       {"qualified", t.qualified},
                       {"points", points}});
      fresh += !t.qualified;
    }
    json jt;
    jt["choice"] = to_string(o.tips);
    jt["order"] = std::move(order);
    jt["to_qualify"] = fresh;
    if (r.tip_choice.automatic) {
      const TipCover& c = r.tip_choice.cover;
      jt["orientations"] = r.tip_choice.orientations;
      jt["pairs_within_tilt"] = r.tip_choice.pairs;
      jt["pairs_checked"] = c.tests;
      jt["method"] = c.exact ? "exact" : "greedy";
      jt["optimal"] = c.optimal;
      jt["search_nodes"] = c.nodes;
      jt["greedy_bound_n"] = c.bound_n;
      jt["greedy_bound"] = jf::finite(c.bound, "greedy bound");
      jt["unreachable_points"] = c.uncoverable.size();
    }
    doc["tips"] = std::move(jt);
  }

  json alloc;
  alloc["budget"] = r.allocation.budget;
  alloc["total"] = r.allocation.total;
  alloc["floors_exceed_budget"] = r.allocation.floors_exceed_budget;
  doc["allocation"] = std::move(alloc);
  json regions = json::array();
  for (const RegionPlanSummary& s : r.regions) {
    if (s.elsewhere) continue;  // measured in another setup, reported there
    regions.push_back({{"region", s.region},
                       {"face", s.face},
                       {"class", to_string(s.curvature_class)},
                       {"area_mm2", jf::finite(s.area, "area")},
                       {"curvature_spread", jf::finite(s.curvature_spread, "curvature spread")},
                       {"mean_risk_mm", jf::finite(s.mean_risk, "risk")},
                       {"weight", jf::finite(s.weight, "weight")},
                       {"samplable", s.samplable},
                       {"contact_rule", s.contact_rule},
                       {"allocated", s.allocated},
                       {"gouge_points", s.gouge_points},
                       {"sampled", s.sampled},
                       {"moved", s.moved},
                       {"dropped", s.dropped},
                       {"planned", s.planned}});
  }
  doc["regions"] = std::move(regions);
  doc["coverage"] = coverage_json(coverage);
  json issues = json::array();
  for (const PlanIssue& i : r.issues) {
    json ji;
    ji["kind"] = to_string(i.kind);
    if (!i.point.empty()) ji["point"] = i.point;
    if (i.region >= 0) ji["region"] = i.region;
    if (i.face >= 0) ji["face"] = i.face;
    if (!i.gouge_site.empty()) ji["gouge_site"] = i.gouge_site;
    if (i.problem != AccessProblem::none) {
      ji["problem"] = to_string(i.problem);
      ji["where"] = jf::vector_json(i.where);
    }
    if (i.kind == PlanIssue::Kind::moved) ji["moved_mm"] = jf::finite(i.distance, "moved");
    if (i.kind == PlanIssue::Kind::region_skipped && i.largest_ball_diameter > 0)
      ji["largest_ball_diameter_mm"] = jf::finite(i.largest_ball_diameter, "largest ball");
    ji["reason"] = i.reason;
    issues.push_back(std::move(ji));
  }
  doc["issues"] = std::move(issues);
  json on_sites = json::array();
  for (std::size_t k = 0; k < r.point_sites.size(); ++k)
    if (!r.point_sites[k].empty()) on_sites.push_back({{"point", r.plan.points[k].id}, {"gouge_site", r.point_sites[k]}});
  doc["gouge_site_points"] = std::move(on_sites);
  // What the programs measure before the free-form points (docs/cmm.md
  // "Part alignment"): the method, why, and the points of each feature.
  if (const auto& a = r.plan.alignment) {
    json ja;
    ja["method"] = to_string(a->method);
    ja["reason"] = a->reason;
    json features = json::array();
    for (const DatumFeature& d : a->datums) {
      json ids = json::array();
      for (const PlannedPoint& p : d.points) ids.push_back(p.id);
      features.push_back({{"label", d.label}, {"kind", to_string(d.kind)}, {"face", d.face}, {"points", ids}});
    }
    ja["datums"] = std::move(features);
    json manual = json::array();
    for (const PlannedPoint& p : a->manual) manual.push_back(p.id);
    ja["manual"] = std::move(manual);
    ja["points"] = a->points().size();
    doc["alignment"] = std::move(ja);
  }
  doc["points"] = r.plan.points.size();
  doc["tour"] = {{"nearest_neighbour_mm", jf::finite(r.tour.nearest_neighbour_length, "tour")},
                 {"optimised_mm", jf::finite(r.tour.length, "tour")},
                 {"passes", r.tour.passes},
                 {"converged", r.tour.converged}};
  if (o.head) doc["tour"]["tip_changes"] = r.tip_changes;
  doc["cycle"] = {{"positioning_mm", jf::finite(r.cycle.positioning_length, "positioning")},
                  {"touch_mm", jf::finite(r.cycle.touch_length, "touch")},
                  {"straight_moves", r.cycle.straight_moves},
                  {"clearance_plane_moves", r.cycle.plane_moves},
                  {"seconds", jf::finite(r.cycle.seconds, "cycle time")}};
  return jf::to_text(doc);
}

std::string setups_report_json(const std::vector<SetupSummary>& setups, const PlanCoverage& combined,
                               const std::string& part_path, const std::string& regions_path, const std::string& note) {
  json doc;
  doc["format"] = "furrow-plan-setups-report";
  doc["version"] = 1;
  doc["units"] = "mm";
  doc["part"] = part_path;
  doc["regions_file"] = regions_path;
  json list = json::array();
  for (const SetupSummary& s : setups) {
    json js;
    js["index"] = s.index;
    js["folder"] = s.folder;
    if (s.resting_face) {
      js["resting_face"] = *s.resting_face;
      js["resting_face_name"] = s.resting_face_name;
      js["resting_face_named"] = s.named;
      js["estimated_reachable_area_mm2"] = jf::finite(s.estimated_area, "estimated area");
    }
    json rows = json::array();
    for (Eigen::Index i = 0; i < 3; ++i) rows.push_back(jf::vector_json(Eigen::Vector3d(s.to_setup.linear().row(i).transpose())));
    js["part_to_setup"] = {{"rotation", std::move(rows)}, {"translation", jf::vector_json(Eigen::Vector3d(s.to_setup.translation()))}};
    js["points"] = s.points;
    json tips = json::array();
    for (const PlanTip& t : s.tips) tips.push_back(tip_name(t.angles));
    js["tips"] = std::move(tips);
    js["coverage"] = coverage_json(*s.coverage);
    list.push_back(std::move(js));
  }
  doc["setups"] = std::move(list);
  json c = coverage_json(combined);
  json covered_by = json::array();
  for (const RegionCoverage& r : combined.regions)
    covered_by.push_back({{"region", r.region}, {"setup", r.setup}, {"state", to_string(r.state)}});
  c["region_setups"] = std::move(covered_by);
  doc["combined"] = std::move(c);
  if (!note.empty()) doc["note"] = note;
  return jf::to_text(doc);
}

}  // namespace furrow
