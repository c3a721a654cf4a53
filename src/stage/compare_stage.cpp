#include "stage/compare_stage.hpp"

#include "geometry/closest_point.hpp"

namespace furrow {

void scale_registration_to_tolerance(CompareOptions& options) {
  options.registration.loss_scale = options.tolerance.width / 2;
  options.registration.outlier_floor = options.tolerance.width / 2;
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
