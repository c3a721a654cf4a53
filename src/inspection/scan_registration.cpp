// A scan's registration from one or two starts (contract in
// scan_registration.hpp).
#include "inspection/scan_registration.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "inspection/surface_sampling.hpp"

namespace furrow {

namespace {

// Samples of the part the feature start matches the scan against, before
// the module thins them to its spacing: as many as the global search's.
constexpr std::size_t kPartSamples = 20000;
// Relative difference of two costs below which both fits found the same
// minimum (a tie, to the global search).
constexpr double kTie = 1e-6;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The comparison's "ok" alignment (scan_comparison.hpp): converged, and no
// direction left weak by where the points are.
bool succeeded(const RegistrationResult& r) {
  if (r.outcome != FitOutcome::converged || !r.converged) return false;
  for (const WeakDirection& d : r.observability.weak)
    if (d.from_points) return false;
  return true;
}

// The measure of scan_registration.hpp over every point of the fit subset.
double robust_cost(const RegistrationResult& r, double scale, double part_size) {
  const double c2 = scale * scale;
  double sum = 0;
  for (const RegisteredPoint& p : r.points) {
    const double d = p.outlier == OutlierReason::no_foot_point || !std::isfinite(p.deviation)
                         ? part_size
                         : std::min(std::abs(p.deviation), part_size);
    sum += c2 * std::log1p(d * d / c2);
  }
  return sum;
}

ScanStartFit figures(const RegistrationResult& r, double scale, double part_size, double seconds) {
  ScanStartFit f;
  f.ran = true;
  f.status = r.status;
  f.ok = succeeded(r);
  f.cost = robust_cost(r, scale, part_size);
  f.rms = r.rms_after;
  f.outer_iterations = r.outer_iterations;
  f.solver_iterations = r.solver_iterations;
  f.seconds = seconds;
  f.start = r.coarse.transform;
  f.transform = r.transform;
  return f;
}

// The feature start from the fit subset and a sampling of the part.
FeatureStart features_of(const ClosestPointFinder& finder, const MeasurementSet& fit,
                         const std::vector<Eigen::Vector3f>& fit_normals, bool normals_estimated, double voxel,
                         double& part_size) {
  FeatureStartInput in;
  in.scan = fit.source;
  in.scan_normals_estimated = normals_estimated;
  in.voxel = voxel;
  for (std::size_t i = 0; i < fit.points.size(); ++i) {
    in.scan_points.push_back(fit.points[i].xyz);
    in.scan_normals.push_back(i < fit_normals.size() ? fit_normals[i] : Eigen::Vector3f::Zero());
  }
  Eigen::AlignedBox3d box;
  for (const SurfaceSample& s : sample_part_surface(finder.part(), kPartSamples)) {
    in.part_points.push_back(s.point);
    in.part_normals.push_back(s.normal);
    box.extend(s.point);
  }
  part_size = box.isEmpty() ? 0 : box.diagonal().norm();
  in.part_size = part_size;
  if (in.part_points.empty() || !(part_size > 0)) {
    FeatureStart none;
    none.status = "the part's surface gave no samples";
    return none;
  }
  return feature_start(in, FeatureStartOptions{});
}

}  // namespace

ScanRegistration register_scan(const ClosestPointFinder& finder, const MeasurementSet& fit,
                               const std::vector<Eigen::Vector3f>& fit_normals, bool normals_estimated,
                               double voxel, ScanStart mode, const RegistrationOptions& options) {
  ScanRegistration result;
  ScanStartRecord& out = result.record;
  out.mode = mode;
  double part_size = finder.part().control_box().diagonal().norm();
  std::optional<RegistrationResult> from_features;
  if (mode != ScanStart::global && options.dof.all_free()) {
    auto t = std::chrono::steady_clock::now();
    out.feature = features_of(finder, fit, fit_normals, normals_estimated, voxel, part_size);
    out.feature_seconds = seconds_since(t);
    if (out.feature.found) {
      RegistrationOptions o = options;
      o.start = out.feature.transform;
      from_features = register_measurements(finder, fit, nullptr, o);
      from_features->coarse.method = CoarseMethod::features;
      out.features = figures(*from_features, options.loss_scale, part_size, seconds_since(t));
    } else {
      out.features.status = "no feature start: " + out.feature.status;
    }
  } else {
    out.features.status = mode == ScanStart::global ? "not run (--scan-start global)"
                                                    : "not run: the fit does not free all six degrees of freedom";
  }

  // The global search: always with best, and whenever the feature start
  // gave nothing.
  std::optional<RegistrationResult> from_global;
  if (mode != ScanStart::features || !from_features) {
    const auto t = std::chrono::steady_clock::now();
    from_global = register_measurements(finder, fit, nullptr, options);
    out.global = figures(*from_global, options.loss_scale, part_size, seconds_since(t));
  } else {
    out.global.status = "not run (--scan-start features)";
  }

  if (!from_features) {
    out.chosen = "global";
    out.why = mode == ScanStart::global ? "the global search's start, as asked"
                                        : "the feature start found no placement; the global search's start is used";
    result.registration = std::move(*from_global);
  } else if (!from_global) {
    out.chosen = "features";
    out.why = "the feature start, as asked";
    result.registration = std::move(*from_features);
  } else {
    const ScanStartFit& g = out.global;
    const ScanStartFit& f = out.features;
    const bool tie = std::abs(f.cost - g.cost) <= kTie * std::max(g.cost, std::numeric_limits<double>::min());
    const bool features_better = f.ok != g.ok ? f.ok : (!tie && f.cost < g.cost);
    out.chosen = features_better ? "features" : "global";
    out.why = f.ok != g.ok ? std::string("only the ") + (f.ok ? "feature start's" : "global search's") +
                                 " fit succeeded"
              : tie        ? "both fits reached the same cost; a tie goes to the global search"
                           : std::string("its fit has the lower robust cost over the fit subset");
    result.registration = std::move(features_better ? *from_features : *from_global);
  }
  if (out.feature.found) {
    const Eigen::Isometry3d d = result.registration.transform.inverse() * out.feature.transform;
    out.feature_rotation_error = Eigen::AngleAxisd(d.linear()).angle();
    out.feature_translation_error = d.translation().norm();
  }
  return result;
}

}  // namespace furrow
