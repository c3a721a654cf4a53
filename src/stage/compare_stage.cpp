#include "stage/compare_stage.hpp"

#include <set>

#include "base/error.hpp"
#include "geometry/closest_point.hpp"
#include "inspection/rps_alignment.hpp"

namespace furrow {

void scale_registration_to_tolerance(CompareOptions& options) {
  options.registration.loss_scale = options.tolerance.width / 2;
  options.registration.outlier_floor = options.tolerance.width / 2;
}

MeasurementSet prepare_alignment(CompareOptions& options, const MeasurementSet& set, const InspectionPlan* plan,
                                 const std::string& plan_name) {
  options.datum_frame.reset();
  if (options.align == AlignMethod::rps) {
    if (!options.rps) throw InputError("--align rps needs the reference point system (--rps FILE)");
    options.datum_frame = fit_rps_alignment(*options.rps, set);
    return without_reference_points(set, *options.rps);
  }
  if (options.align != AlignMethod::datums) return set;
  if (!plan || !plan->alignment || plan->alignment->method != PartAlignment::Method::datums)
    throw InputError((plan ? plan_name + ": the plan has no datums alignment" : std::string("no plan given")) +
                     ": --align datums needs a plan whose alignment measures datums (furrow plan --datums)");
  options.datum_frame = fit_datum_frame(*plan->alignment, set, plan_name);
  return without_datum_points(set, *plan->alignment);
}

void restrict_to(MergedMeasurements& merged, const MeasurementSet& compared) {
  std::set<std::string> keep;
  for (const MeasuredPoint& p : compared.points) keep.insert(p.id);
  std::vector<MeasuredPoint> points;
  std::vector<std::size_t> origin;
  for (std::size_t i = 0; i < merged.set.points.size(); ++i)
    if (keep.count(merged.set.points[i].id)) {
      points.push_back(merged.set.points[i]);
      if (i < merged.origin.size()) origin.push_back(merged.origin[i]);
    }
  merged.set.points = std::move(points);
  if (!merged.origin.empty()) merged.origin = std::move(origin);
}

Comparison compare_stage(const Part& part, const MeasurementSet& set, const InspectionPlan* plan,
                         const RegionMap* regions, const Prediction* prediction, const CompareOptions& options) {
  const ClosestPointFinder finder(part);
  Comparison c = compare_measurements(finder, set, plan, options);
  if (regions) {
    assign_regions(c, *regions);
    if (plan) c.region_minimum = region_minimums(*plan);
    summarize(c);
  }
  if (prediction) verify_prediction(c, part, set.probe_radius, *prediction, options);
  return c;
}

}  // namespace furrow
