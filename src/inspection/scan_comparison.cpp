// A scan compared with the part (contract in scan_comparison.hpp).
#include "inspection/scan_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace furrow {

const char* to_string(ScanPointStatus status) {
  switch (status) {
    case ScanPointStatus::evaluated: return "evaluated";
    case ScanPointStatus::spray_far: return "spray_far";
    case ScanPointStatus::spray_near: return "spray_near";
    case ScanPointStatus::off_part: return "off_part";
    case ScanPointStatus::grazing: return "grazing";
  }
  return "?";
}

namespace {

// Points projected per task: each task hints its searches along the
// cloud's order (ClosestPointFinder::project_in_order); the split is fixed,
// so the answer does not depend on the thread count.
constexpr std::size_t kProjectionChunk = 4096;

// The alignment's state, as comparison.hpp rules it for probe points; a
// scan has no plan ids and no few-point ambiguity.
std::string alignment_status(const RegistrationResult& r) {
  if (r.outcome == FitOutcome::too_few_points) return "too_few_points";
  if (!r.converged) return "not_converged";
  for (const WeakDirection& d : r.observability.weak)
    if (d.from_points) return "weakly_constrained";
  return "ok";
}

}  // namespace

ScanComparison compare_scan(const ClosestPointFinder& finder, const ScanCloud& cloud, const ScanPreprocessed& pre,
                            const ScanPreprocessOptions& preprocessing, const RegionMap* regions,
                            const CompareOptions& options) {
  ScanComparison c;
  c.scan = cloud.file;
  c.preprocessing = preprocessing;
  c.pre = pre;
  c.read = cloud.read;
  c.not_finite = cloud.not_finite;
  c.points = cloud.points.size();
  c.normals = pre.normals_estimated ? "estimated" : "file";
  c.tolerance = options.tolerance;

  // The fit subset, relative to the local origin, as contact points.
  MeasurementSet fit;
  fit.source = cloud.file;
  fit.kind = ProbePointKind::contact;
  fit.probe_radius = 0;
  fit.points.reserve(pre.fit.size());
  for (std::size_t k = 0; k < pre.fit.size(); ++k) {
    const std::size_t i = pre.fit[k];
    MeasuredPoint p;
    p.id = "S" + std::to_string(i);
    p.xyz = cloud.points[i] - pre.origin;
    if (!pre.fit_weights.empty()) p.weight = pre.fit_weights[k];
    fit.points.push_back(std::move(p));
  }
  ScanRegistration registered = register_scan(finder, fit, pre.fit_normals, pre.normals_estimated,
                                              preprocessing.voxel, preprocessing.start, options.registration);
  c.registration = std::move(registered.registration);
  c.start = std::move(registered.record);
  c.transform = c.registration.transform * Eigen::Translation3d(-pre.origin);

  // Every point that is neither spray nor grazing, projected exactly; with
  // a partition the others too, for the region they were removed from
  // (never compared).
  const std::size_t n = cloud.points.size();
  c.status.assign(n, ScanPointStatus::evaluated);
  c.deviation.assign(n, 0.0f);
  c.region.assign(n, -1);
  c.foot_face.assign(n, -1);
  c.foot_uv.assign(n, Eigen::Vector2d::Zero());
  c.foot_normal.assign(n, Eigen::Vector3f::Zero());
  std::vector<std::size_t> to_project;
  to_project.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!pre.grazing.empty() && pre.grazing[i]) c.status[i] = ScanPointStatus::grazing;
    else if (pre.spray[i] == kSprayFar) c.status[i] = ScanPointStatus::spray_far;
    else if (pre.spray[i] == kSprayNear) c.status[i] = ScanPointStatus::spray_near;
    if (c.status[i] == ScanPointStatus::evaluated || regions) to_project.push_back(i);
  }
  std::vector<double> value(n, 0.0);
  const long chunks = static_cast<long>((to_project.size() + kProjectionChunk - 1) / kProjectionChunk);
  const double edge = options.registration.edge_tolerance;
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < chunks; ++k) {
    const std::size_t begin = static_cast<std::size_t>(k) * kProjectionChunk;
    const std::size_t end = std::min(to_project.size(), begin + kProjectionChunk);
    std::vector<Eigen::Vector3d> xs;
    xs.reserve(end - begin);
    for (std::size_t m = begin; m < end; ++m)
      xs.push_back(c.registration.transform * (cloud.points[to_project[m]] - pre.origin));
    const std::vector<ClosestPoint> feet = finder.project_in_order(xs);
    for (std::size_t m = begin; m < end; ++m) {
      const std::size_t i = to_project[m];
      const ClosestPoint& f = feet[m - begin];
      if (regions && f.converged)
        if (const std::optional<int> id = regions->region_at(static_cast<int>(f.face), f.uv.x(), f.uv.y()))
          c.region[i] = *id;
      if (c.status[i] != ScanPointStatus::evaluated) continue;  // spray, grazing: its region only
      const Eigen::Vector3d r = xs[m - begin] - f.point;
      const double along = r.dot(f.normal);
      const bool boundary = f.location != FootLocation::interior;
      if (!f.converged || (boundary && (r - along * f.normal).norm() > edge)) {
        c.status[i] = ScanPointStatus::off_part;
        continue;
      }
      // On a boundary the bounded surface's signed distance, as for a probe
      // point (registration.hpp).
      value[i] = boundary ? f.signed_distance : along;
      c.deviation[i] = static_cast<float>(value[i]);
      c.foot_face[i] = static_cast<std::int32_t>(f.face);
      c.foot_uv[i] = f.uv;
      c.foot_normal[i] = f.normal.cast<float>();
    }
  }

  // Statistics in index order (deterministic), overall and per region.
  ComparisonSummary& s = c.summary;
  std::vector<double> evaluated;
  std::map<int, std::vector<double>> by_region;
  std::map<int, std::size_t> region_out;
  double max_abs = 0;
  std::map<int, ScanRemovedInRegion> removed;
  for (std::size_t i = 0; i < n; ++i) {
    if (c.status[i] == ScanPointStatus::off_part) ++c.off_part;
    if (c.status[i] == ScanPointStatus::grazing) ++c.grazing;
    if (c.status[i] != ScanPointStatus::evaluated) {
      if (!regions) continue;
      ScanRemovedInRegion& r = removed[c.region[i]];
      r.region = c.region[i];
      ++(c.status[i] == ScanPointStatus::spray_far    ? r.spray_far
         : c.status[i] == ScanPointStatus::spray_near ? r.spray_near
         : c.status[i] == ScanPointStatus::grazing    ? r.grazing
                                                      : r.off_part);
      continue;
    }
    evaluated.push_back(value[i]);
    max_abs = std::max(max_abs, std::abs(value[i]));
    const bool in = c.tolerance.contains(value[i]);
    (in ? s.in_tolerance : s.out_of_tolerance)++;
    if (c.region[i] >= 0) {
      by_region[c.region[i]].push_back(value[i]);
      region_out[c.region[i]] += !in;
    }
  }
  c.evaluated = evaluated.size();
  s.points = c.evaluated + c.off_part;
  s.evaluated = c.evaluated;
  s.outliers = c.off_part;
  s.in_fit = c.registration.in_fit_count();
  s.deviations = deviation_statistics(evaluated);
  s.profile = 2 * max_abs;
  for (const auto& [region, values] : by_region)
    s.regions.push_back({region, deviation_statistics(values), region_out[region]});
  for (const auto& [region, r] : removed) c.removed_by_region.push_back(r);
  s.alignment = alignment_status(c.registration);
  decide_scan_verdict(c);
  return c;
}

void decide_scan_verdict(ScanComparison& c) {
  ComparisonSummary& s = c.summary;
  s.inconclusive.clear();
  s.confirmed_gouges = c.verification ? c.verification->confirmed() : 0;
  s.unexplained_overcuts = c.verification ? c.verification->unexplained.size() : 0;
  if (s.alignment != "ok") {
    s.verdict = Verdict::inconclusive;
    s.inconclusive = {{"alignment_failed", "",
                       "the scan's registration did not succeed (" + s.alignment + ": " + c.registration.status +
                           "); nothing is certified"}};
  } else if (s.evaluated == 0 || s.out_of_tolerance > 0 || s.confirmed_gouges > 0) {
    s.verdict = Verdict::fail;
  } else {
    if (c.verification)
      for (const ScanGougeSite& site : c.verification->sites)
        if (site.check.status == GougeSiteStatus::not_measured)
          s.inconclusive.push_back({"gouge_not_measured", site.check.id,
                                    "predicted gouge " + site.check.id + " on face " + site.check.face +
                                        " was not seen by the scan: scan its site"});
    s.verdict = s.inconclusive.empty() ? Verdict::pass : Verdict::inconclusive;
  }
  s.pass = s.verdict == Verdict::pass;
}

}  // namespace furrow
