#include "inspection/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace furrow {

DeviationStatistics deviation_statistics(const std::vector<double>& values) {
  DeviationStatistics s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0;
  s.min = s.max = values[0];
  for (double v : values) {
    sum += v;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  }
  s.mean = sum / static_cast<double>(values.size());
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sigma = values.size() > 1 ? std::sqrt(squares / static_cast<double>(values.size() - 1)) : 0;
  return s;
}

void summarize(Comparison& c) {
  const std::vector<RegisteredPoint>& pts = c.registration.points;
  ComparisonSummary s;
  s.points = pts.size();
  c.in_tolerance.assign(pts.size(), false);
  std::vector<double> evaluated;
  std::map<int, std::vector<double>> by_region;
  std::map<int, std::size_t> region_out;
  double max_abs = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const RegisteredPoint& p = pts[i];
    s.in_fit += p.in_fit;
    s.outliers += p.outlier != OutlierReason::none;
    if (!p.evaluated) continue;
    ++s.evaluated;
    evaluated.push_back(p.deviation);
    max_abs = std::max(max_abs, std::abs(p.deviation));
    c.in_tolerance[i] = c.tolerance.contains(p.deviation);
    (c.in_tolerance[i] ? s.in_tolerance : s.out_of_tolerance)++;
    if (i < c.region.size() && c.region[i]) {
      by_region[*c.region[i]].push_back(p.deviation);
      region_out[*c.region[i]] += !c.in_tolerance[i];
    }
  }
  s.deviations = deviation_statistics(evaluated);
  s.profile = 2 * max_abs;
  if (c.gouges) {
    s.confirmed_gouges = c.gouges->confirmed();
    s.unexplained_overcuts = c.gouges->unexplained.size();
  }
  // An alignment that did not converge cannot certify anything.
  s.pass = c.registration.converged && s.evaluated > 0 && s.out_of_tolerance == 0 &&
           s.confirmed_gouges == 0;
  for (const auto& [region, values] : by_region)
    s.regions.push_back({region, deviation_statistics(values), region_out[region]});
  c.summary = s;
}

void assign_regions(Comparison& c, const RegionMap& regions) {
  const std::vector<RegisteredPoint>& pts = c.registration.points;
  c.region.assign(pts.size(), std::nullopt);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].outlier == OutlierReason::no_foot_point) continue;
    const ClosestPoint& f = pts[i].foot;
    c.region[i] = regions.region_at(static_cast<int>(f.face), f.uv.x(), f.uv.y());
  }
}

void verify_prediction(Comparison& c, const Part& part, double probe_radius,
                       const Prediction& prediction, const CompareOptions& options) {
  auto compare = [&] {
    return compare_with_prediction(c.registration, c.region, part, probe_radius,
                                   options.registration.dof, prediction, options.prediction);
  };
  c.prediction = compare();
  // Newly evaluated points join the statistics (the fit, hence the
  // alignment, is unchanged).
  if (admit_predicted_deviations(c.registration, *c.prediction, options.prediction) > 0)
    c.prediction = compare();
  c.gouges = confirm_gouges(c.registration, part, c.tolerance, prediction, *c.prediction,
                            options.prediction, options.gouges);
  summarize(c);
}

Comparison compare_measurements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                const InspectionPlan* plan, const CompareOptions& options) {
  Comparison c;
  c.tolerance = options.tolerance;
  c.registration = register_measurements(finder, set, plan, options.registration);
  c.region.assign(set.points.size(), std::nullopt);
  if (plan && set.ids_from_file) {
    const auto index = plan->index_by_id();
    for (std::size_t i = 0; i < set.points.size(); ++i)
      if (const auto k = index.find(set.points[i].id); k != index.end())
        c.region[i] = plan->points[k->second].region;
  }
  summarize(c);
  return c;
}

}  // namespace furrow
