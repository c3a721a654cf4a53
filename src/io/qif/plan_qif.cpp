#include "io/qif/plan_qif.hpp"

#include "io/qif/qif_document.hpp"

#include <algorithm>
#include <vector>

namespace furrow {

std::string plan_to_qif(const InspectionPlan& plan, const std::string& part_name, double tolerance,
                        double outside) {
  QifDocumentData d;
  d.part_name = part_name;
  d.description = std::string("Furrow ") + FURROW_VERSION + ": inspection plan, " +
                  std::to_string(plan.points.size()) + " points" +
                  (plan.alignment ? " after " + std::to_string(plan.alignment->points().size()) + " alignment points"
                                  : std::string()) +
                  ", probe " + plan.probe.name;
  // In execution order: the document's plan measures them in this order.
  std::vector<const PlannedPoint*> ordered;
  for (const PlannedPoint& p : plan.points) ordered.push_back(&p);
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const PlannedPoint* a, const PlannedPoint* b) { return a->order < b->order; });
  // The part alignment's points come first, as the programs measure them
  // (docs/cmm.md "Part alignment"); the profile does not evaluate them.
  if (plan.alignment)
    for (const PlannedPoint& p : plan.alignment->points()) {
      QifPoint q;
      q.id = p.id;
      q.nominal = p.xyz;
      q.normal = p.ijk;
      q.profiled = false;
      d.points.push_back(std::move(q));
    }
  for (const PlannedPoint* pp : ordered) {
    const PlannedPoint& p = *pp;
    QifPoint q;
    q.id = p.id;
    q.nominal = p.xyz;
    q.normal = p.ijk;
    d.points.push_back(std::move(q));
  }
  QifProfile profile;
  profile.tolerance = tolerance;
  if (outside != tolerance / 2) profile.outer_disposition = outside;
  d.profile = profile;
  return qif_plan_text(d);
}

}  // namespace furrow
