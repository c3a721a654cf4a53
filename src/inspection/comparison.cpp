#include "inspection/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "base/number_text.hpp"
#include "base/numbers.hpp"
#include "base/error.hpp"
#include "inspection/fixed_alignment.hpp"

namespace furrow {

const char* to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass:
      return "PASS";
    case Verdict::fail:
      return "FAIL";
    case Verdict::inconclusive:
      return "INCONCLUSIVE";
  }
  return "?";
}

Verdict parse_verdict(const std::string& text, const std::string& where) {
  for (Verdict v : {Verdict::pass, Verdict::fail, Verdict::inconclusive})
    if (text == to_string(v)) return v;
  throw InputError(where + ": unknown verdict \"" + text + "\" (valid: PASS, FAIL, INCONCLUSIVE)");
}

const char* to_string(AlignMethod method) {
  switch (method) {
    case AlignMethod::bestfit:
      return "bestfit";
    case AlignMethod::cmm:
      return "cmm";
    case AlignMethod::datums:
      return "datums";
    case AlignMethod::rps:
      return "rps";
  }
  return "?";
}

AlignMethod parse_align_method(const std::string& text, const std::string& where) {
  for (AlignMethod m : {AlignMethod::bestfit, AlignMethod::cmm, AlignMethod::datums, AlignMethod::rps})
    if (text == to_string(m)) return m;
  throw InputError(where + ": \"" + text + "\" is not an alignment (bestfit, cmm, datums, rps)");
}

namespace {

std::string micrometres(double mm) { return fixed(mm * 1000, 1) + " um"; }

// What was not shown to be good (the header's INCONCLUSIVE rules).
std::vector<InconclusiveReason> open_questions(const Comparison& c) {
  std::vector<InconclusiveReason> out;
  const std::vector<RegisteredPoint>& pts = c.registration.points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const RegisteredPoint& p = pts[i];
    if (p.outlier != OutlierReason::blunder || c.tolerance.contains(p.deviation)) continue;
    const std::string id = i < c.point_ids.size() ? c.point_ids[i] : std::to_string(i + 1);
    out.push_back({"suspected_blunder", id,
                   "re-measure point " + id + ": its deviation " + micrometres(p.deviation) +
                       " is outside the zone, but the outlier rule suspects a blunder (" + p.outlier_detail + ")"});
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const RegisteredPoint& p = pts[i];
    if (!p.in_fit || !p.evaluated || !(p.redundancy < kCheckedRedundancy)) continue;
    const std::string id = i < c.point_ids.size() ? c.point_ids[i] : std::to_string(i + 1);
    const double reach = std::max(c.tolerance.upper(), -c.tolerance.lower());
    const std::string hidden =
        p.redundancy * 1e6 < reach ? "no deviation there would show"
                                   : "a deviation of up to " + fixed(reach / p.redundancy, 3) +
                                         " mm there would still read inside the zone";
    out.push_back({"point_not_checked", id,
                   "point " + id + " is not checked by the best fit: it fixes the alignment instead, only " +
                       fixed(100 * p.redundancy, 1) + " % of a deviation there shows in its reading and " + hidden +
                       "; measure more points around it (furrow remeasure), or align on datums"});
  }
  for (const UnmeasuredPoint& u : c.not_measured)
    out.push_back({"point_not_measured", u.id,
                   "point " + u.id + " was not measured (" + u.reason + "): measure it again"});
  if (c.gouges)
    for (const GougeSiteCheck& site : c.gouges->sites)
      if (site.status == GougeSiteStatus::not_measured)
        out.push_back({"gouge_not_measured", site.id,
                       "predicted gouge " + site.id +
                           (site.predicted_depth ? " (" + micrometres(*site.predicted_depth) + " deep)" : std::string()) +
                           " on face " + site.face + " was not measured: probe its site"});
  if (!c.region_minimum.empty()) {
    std::map<int, std::size_t> evaluated;
    for (std::size_t i = 0; i < pts.size() && i < c.region.size(); ++i)
      if (pts[i].evaluated && c.region[i]) ++evaluated[*c.region[i]];
    for (const auto& [region, minimum] : c.region_minimum) {
      const std::size_t n = evaluated[region];
      if (n >= minimum) continue;
      const std::string name = "region " + std::to_string(region);
      out.push_back({"region_below_minimum", name,
                     name + " has " + std::to_string(n) + " evaluated point" + (n == 1 ? "" : "s") +
                         ", fewer than the plan's minimum of " + std::to_string(minimum) +
                         ": measure more points there"});
    }
  }
  const std::string& covariance = c.registration.covariance_status;
  if (covariance.find("rank deficient") != std::string::npos)
    out.push_back({"alignment_undetermined", "",
                   "the measured points do not determine the part's position (" + covariance +
                       "): measure more points spread over the part, or lock the free motions with --dof"});
  return out;
}

// The points evaluated by both orientations of an ambiguous fit that one
// puts inside the zone and the other outside.
std::vector<std::size_t> orientation_dependent(const Comparison& c) {
  std::vector<std::size_t> out;
  const RegistrationResult& r = c.registration;
  if (!r.coarse.ambiguous || !r.other_orientation) return out;
  for (std::size_t i = 0; i < r.points.size() && i < r.other_orientation->deviation.size(); ++i) {
    const std::optional<double>& other = r.other_orientation->deviation[i];
    if (r.points[i].evaluated && other && c.tolerance.contains(r.points[i].deviation) != c.tolerance.contains(*other))
      out.push_back(i);
  }
  return out;
}

// The alignment's state (the header's rule).
std::string alignment_status(const Comparison& c) {
  const RegistrationResult& r = c.registration;
  if (r.outcome == FitOutcome::too_few_points) return "too_few_points";
  if (!r.converged) return "not_converged";
  if (!r.ambiguous_outliers.empty()) return "ambiguous_outliers";
  for (const WeakDirection& d : r.observability.weak)
    if (d.from_points) return "weakly_constrained";
  if (!orientation_dependent(c).empty()) return "ambiguous_orientation";
  return "ok";
}

std::string point_list(const std::vector<std::size_t>& points, const std::vector<std::string>& ids) {
  std::string s;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = points[k];
    s += (k == 0 ? "" : k + 1 == points.size() ? " and " : ", ") + (i < ids.size() ? ids[i] : std::to_string(i + 1));
  }
  return s;
}

// What went wrong and how to constrain it, for people.
std::string alignment_advice(const Comparison& c, const std::string& status) {
  const RegistrationResult& r = c.registration;
  const std::vector<std::string>& ids = c.point_ids;
  if (status == "ambiguous_outliers")
    return "the points cannot tell which of points " + point_list(r.ambiguous_outliers, ids) +
           " are blunders: fits that flag different ones of them explain the others equally well; "
           "re-measure them, or measure more points";
  if (status == "ambiguous_orientation") {
    const double turn = Eigen::AngleAxisd(r.transform.linear() * r.other_orientation->transform.linear().transpose())
                            .angle();
    std::vector<std::size_t> points = orientation_dependent(c);
    const std::size_t more = points.size() > 10 ? points.size() - 10 : 0;
    points.resize(points.size() - more);
    return "the points cannot tell the part's orientation: another one, turned " + fixed(degrees(turn), 1) +
           " degrees from this, explains them as well, and it puts point" + (points.size() + more == 1 ? " " : "s ") +
           point_list(points, ids) + (more ? " and " + std::to_string(more) + " more" : "") +
           " on the other side of the zone; measure with the plan's ids (--plan), or align on datums";
  }
  if (status == "weakly_constrained") {
    std::string s = "the alignment is weakly constrained: the measured points do not fix the ";
    bool first = true;
    for (const WeakDirection& d : r.observability.weak)
      if (d.from_points) {
        s += (first ? "" : "; nor the ") + d.describe();
        first = false;
      }
    return s + ", which the measured faces would; measure more points spread over them, add a datum, or "
               "lock it with --dof";
  }
  return "the alignment did not succeed (" + r.status +
         "): check the units and the part, measure more points on it, or lock motions with --dof";
}

}  // namespace

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
  s.not_measured = c.not_measured.size();
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
  // An alignment that did not succeed cannot certify anything, good or bad.
  s.alignment = alignment_status(c);
  if (s.alignment != "ok") {
    s.inconclusive = {{"alignment_failed", "", alignment_advice(c, s.alignment)}};
    s.verdict = Verdict::inconclusive;
  } else {
    const bool failed = s.evaluated == 0 || s.out_of_tolerance > 0 || s.confirmed_gouges > 0;
    if (!failed) s.inconclusive = open_questions(c);
    s.verdict = failed ? Verdict::fail : s.inconclusive.empty() ? Verdict::pass : Verdict::inconclusive;
  }
  s.pass = s.verdict == Verdict::pass;
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

std::map<int, std::size_t> region_minimums(const InspectionPlan& plan) {
  std::map<int, std::size_t> planned;
  for (const PlannedPoint& p : plan.points)
    if (p.region) ++planned[*p.region];
  for (auto& [region, n] : planned) n = std::min(n, kRegionMinimumPoints);
  // A region the plan could not cover needs the minimum the planner asked
  // for, even with no point in the plan: it was never shown to be good.
  for (const UncoveredRegion& u : plan.uncovered_regions)
    planned[u.region] = static_cast<std::size_t>(u.required);
  return planned;
}

Comparison compare_measurements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                const InspectionPlan* plan, const CompareOptions& options) {
  Comparison c;
  c.tolerance = options.tolerance;
  for (const MeasuredPoint& p : set.points) c.point_ids.push_back(p.id);
  c.not_measured = set.not_measured;
  c.align = options.align;
  if (options.align == AlignMethod::bestfit) {
    c.registration = register_measurements(finder, set, plan, options.registration);
  } else {
    if (options.align == AlignMethod::datums || options.align == AlignMethod::rps) {
      if (!options.datum_frame) throw std::logic_error("compare_measurements: datums without a datum frame");
      c.datum_frame = options.datum_frame;
      c.registration = evaluate_at_transform(finder, set, c.datum_frame->transform, options.registration,
                                             options.align == AlignMethod::rps
                                                 ? "RPS frame: evaluated as aligned by the reference points, no fit"
                                                 : "datum frame: evaluated as aligned by the datums, no fit");
    } else {
      c.registration = evaluate_at_transform(finder, set, Eigen::Isometry3d::Identity(), options.registration,
                                             "cmm frame: evaluated as measured, no fit");
    }
    // The best fit of the same points: form alone, for comparison.
    RegistrationOptions quiet = options.registration;
    quiet.compute_covariance = false;
    // From the datum or RPS frame: the best fit then needs no search (a
    // part without ids, or a nearly flat one, could be found upside down).
    if (c.datum_frame) quiet.start = c.datum_frame->transform;
    c.bestfit = register_measurements(finder, set, plan, quiet);
    double max_abs = 0;
    for (const RegisteredPoint& p : c.bestfit->points)
      if (p.evaluated) max_abs = std::max(max_abs, std::abs(p.deviation));
    c.bestfit_profile = 2 * max_abs;
  }
  c.region.assign(set.points.size(), std::nullopt);
  // The regions of the points are known by id here; with generated ids only
  // a partition can tell them (compare_stage), else the rule cannot apply.
  if (plan && set.ids_from_file) {
    c.region_minimum = region_minimums(*plan);
    const auto index = plan->index_by_id();
    for (std::size_t i = 0; i < set.points.size(); ++i)
      if (const auto k = index.find(set.points[i].id); k != index.end())
        c.region[i] = plan->points[k->second].region;
  }
  summarize(c);
  return c;
}

}  // namespace furrow
