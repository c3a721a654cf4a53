#include "inspection/setup_merge.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/error.hpp"

namespace furrow {

MeasurementSet measurements_in_part_frame(MeasurementSet set, const std::optional<PlanSetupRecord>& setup) {
  if (!setup) return set;
  const Eigen::Matrix3d back = setup->rotation.transpose();
  for (MeasuredPoint& p : set.points) {
    p.xyz = setup->to_part(p.xyz);
    if (p.ijk) p.ijk = back * *p.ijk;
    if (p.nominal) p.nominal = setup->to_part(*p.nominal);
    if (p.nominal_ijk) p.nominal_ijk = back * *p.nominal_ijk;
  }
  for (UnmeasuredPoint& u : set.not_measured)
    if (u.nominal) u.nominal = setup->to_part(*u.nominal);
  return set;
}

InspectionPlan merge_setup_plans(const std::vector<InspectionPlan>& plans, const std::vector<std::string>& names) {
  if (plans.empty()) throw InputError("no plan to merge");
  InspectionPlan out;
  out.part = plans.front().part;
  out.probe = plans.front().probe;
  std::map<std::string, std::size_t> owner;
  int order = 0;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const InspectionPlan& plan = plans[k];
    if (std::abs(plan.probe.diameter - out.probe.diameter) > 1e-9)
      throw InputError(names[k] + ": probe diameter " + std::to_string(plan.probe.diameter) + " mm, but " + names[0] +
                       " has " + std::to_string(out.probe.diameter) + " mm: the setups are compared with one probe");
    std::vector<PlannedPoint> points = plan.points;
    std::sort(points.begin(), points.end(), [](const PlannedPoint& a, const PlannedPoint& b) { return a.order < b.order; });
    for (PlannedPoint p : points) {
      if (const auto [it, fresh] = owner.emplace(p.id, k); !fresh)
        throw InputError(names[k] + ": point id \"" + p.id + "\" is also in " + names[it->second] +
                         ": the setups' plans must name their points apart");
      if (plan.setup) {
        const Eigen::Matrix3d back = plan.setup->rotation.transpose();
        p.xyz = plan.setup->to_part(p.xyz);
        p.approach = plan.setup->to_part(p.approach);
        p.retract = plan.setup->to_part(p.retract);
        p.ijk = back * p.ijk;
      }
      p.order = ++order;
      p.tip.reset();
      out.points.push_back(std::move(p));
    }
  }
  // Short regions: still short over all setups?
  std::map<int, int> held;
  for (const PlannedPoint& p : out.points)
    if (p.region) ++held[*p.region];
  std::map<int, UncoveredRegion> short_regions;
  for (const InspectionPlan& plan : plans)
    for (const UncoveredRegion& u : plan.uncovered_regions) short_regions[u.region] = u;
  for (auto& [region, u] : short_regions) {
    u.planned = held[region];
    if (u.planned < u.required) out.uncovered_regions.push_back(u);
  }
  return out;
}

}  // namespace furrow
