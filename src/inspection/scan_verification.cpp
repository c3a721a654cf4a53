// A scan against a machining prediction (contract in scan_verification.hpp).
#include "inspection/scan_verification.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "geometry/point_search.hpp"
#include "inspection/distance_clusters.hpp"
#include "inspection/scan_comparison.hpp"

namespace furrow {

std::size_t ScanVerification::confirmed() const {
  return static_cast<std::size_t>(std::count_if(sites.begin(), sites.end(), [](const ScanGougeSite& s) {
    return s.check.status == GougeSiteStatus::confirmed;
  }));
}

namespace {

// [mm] How far a sparse scan's local mean may reach for its
// kScanReadPoints points when fewer lie within kScanReadRadius: a raster up
// to about 2 mm (scan_verification.hpp, "Unexplained overcuts").
constexpr double kScanSparseReach = 3.0;

// The points of one site hashed on a grid of kScanReadRadius cells, for
// the local means and the anchors' views (a site holds up to a few
// thousand points of a million). Cells keep their points in index order,
// so every sum runs in the same order on every run.
class SiteGrid {
 public:
  SiteGrid(const std::vector<std::size_t>& points, const std::vector<Eigen::Vector3d>& x, double cell)
      : x_(x), cell_(cell) {
    for (const std::size_t i : points) cells_[key(x[i])].push_back(i);
  }
  // Whether some point lies within `radius` (<= cell) of `at`.
  bool any_near(const Eigen::Vector3d& at, double radius) const {
    return !visit(at, radius, [](std::size_t) { return false; });
  }
  // Calls f(j) for every point within `radius` (<= cell) of `at`.
  template <class F>
  void near(const Eigen::Vector3d& at, double radius, F&& f) const {
    visit(at, radius, [&f](std::size_t j) {
      f(j);
      return true;
    });
  }

 private:
  // Calls f(j) for the points within `radius` (<= cell) of `at` until f
  // returns false; returns false when it stopped so.
  template <class F>
  bool visit(const Eigen::Vector3d& at, double radius, F&& f) const {
    const std::array<long, 3> k = key(at);
    for (long a = -1; a <= 1; ++a)
      for (long b = -1; b <= 1; ++b)
        for (long c = -1; c <= 1; ++c) {
          const auto it = cells_.find({k[0] + a, k[1] + b, k[2] + c});
          if (it == cells_.end()) continue;
          for (const std::size_t j : it->second)
            if ((x_[j] - at).squaredNorm() <= radius * radius && !f(j)) return false;
        }
    return true;
  }
  std::array<long, 3> key(const Eigen::Vector3d& p) const {
    return {static_cast<long>(std::floor(p.x() / cell_)), static_cast<long>(std::floor(p.y() / cell_)),
            static_cast<long>(std::floor(p.z() / cell_))};
  }
  const std::vector<Eigen::Vector3d>& x_;
  double cell_;
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells_;
};

}  // namespace

void verify_scan_prediction(ScanComparison& c, const ScanCloud& cloud, const Part& part,
                            const Prediction& prediction, const CompareOptions& options) {
  const PredictionComparisonOptions& po = options.prediction;
  ScanVerification v;
  v.options = po;
  v.gouge_options = options.gouges;
  // The re-fit to the predicted surface, on the fit subset (its residual
  // statistics over the subset are not kept: every point's are below).
  v.compared = compare_with_prediction(c.registration, {}, part, 0.0, options.registration.dof, prediction, po);
  v.compared.points.clear();
  v.noise = std::max(c.pre.local_plane_sigma, po.probe_sigma);
  const PredictionAlignment& a = v.compared.alignment;
  const Eigen::Vector3d rotation = a.parameters.head<3>();
  const Eigen::Matrix3d turn = rotation.norm() > 0
                                   ? Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).toRotationMatrix()
                                   : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d shift = a.parameters.tail<3>();

  // Every evaluated point: part-frame position, prediction, aligned
  // measurement, residual sigma.
  const std::size_t n = c.status.size();
  std::vector<Eigen::Vector3d> x(n, Eigen::Vector3d::Zero());
  std::vector<PredictedError> predicted(n);
  std::vector<double> measured(n, 0.0), sigma(n, 0.0);
  struct Series {
    std::vector<double> predicted, measured, sigma;
  };
  Series all;
  std::map<int, Series> by_region;
  for (std::size_t i = 0; i < n; ++i) {
    if (c.status[i] != ScanPointStatus::evaluated) continue;
    x[i] = c.transform * cloud.points[i];
    const std::string& face = part.faces[static_cast<std::size_t>(c.foot_face[i])].name();
    if (!prediction.find_face(face)) {
      ++v.compared.uncompared.face_not_predicted;
      continue;
    }
    const PredictedError& e = predicted[i] = prediction.predicted_error_at(face, c.foot_uv[i].x(), c.foot_uv[i].y());
    switch (e.status) {
      case ErrorCellStatus::reached: break;
      case ErrorCellStatus::not_reached: ++v.compared.uncompared.not_reached; continue;
      case ErrorCellStatus::outside: ++v.compared.uncompared.outside; continue;
      case ErrorCellStatus::not_machinable: ++v.compared.uncompared.not_machinable; continue;
    }
    const Eigen::Vector3d normal = c.foot_normal[i].cast<double>();
    measured[i] = c.deviation[i] + (a.applied ? normal.dot(turn * x[i] + shift - x[i]) : 0.0);
    const double resolution = (e.max_undercut - e.max_overcut) / std::sqrt(12.0);
    sigma[i] = std::hypot(v.noise, resolution);
    for (Series* s : {&all, c.region[i] >= 0 ? &by_region[c.region[i]] : nullptr}) {
      if (!s) continue;
      s->predicted.push_back(e.value);
      s->measured.push_back(measured[i]);
      s->sigma.push_back(sigma[i]);
    }
  }
  v.compared.overall = residual_statistics(all.predicted, all.measured, all.sigma, po);
  v.compared.regions.clear();
  for (const auto& [id, s] : by_region)
    v.compared.regions.push_back({id, residual_statistics(s.predicted, s.measured, s.sigma, po)});

  // The sites.
  std::vector<bool> on_any(n, false);
  for (GougeSiteCheck& site : predicted_gouge_sites(part, prediction, options.gouges)) {
    ScanGougeSite g;
    g.check = std::move(site);
    GougeSiteCheck& s = g.check;
    for (std::size_t i = 0; i < n; ++i)
      if (c.status[i] == ScanPointStatus::evaluated && c.foot_face[i] == s.face_index &&
          s.search_box.contains(c.foot_uv[i]))
        s.points.push_back(i);
    g.on_site = s.points.size();
    for (const std::size_t i : s.points) on_any[i] = true;
    const SiteGrid grid(s.points, x, kScanReadRadius);
    for (const Eigen::Vector3d& anchor : s.anchors) {
      std::size_t seen = 0;
      grid.near(anchor, kScanReadRadius, [&](std::size_t) { ++seen; });
      g.anchors_seen += seen >= kScanReadPoints;
    }
    const bool covered = !s.anchors.empty() && g.anchors_seen == s.anchors.size();
    // The deepest local mean (first in index order on a tie).
    double deepest = 0;
    for (const std::size_t i : s.points) {
      double sum = 0;
      std::size_t count = 0;
      grid.near(x[i], kScanReadRadius, [&](std::size_t j) {
        sum += c.deviation[j];
        ++count;
      });
      if (count < kScanReadPoints) continue;
      const double mean = sum / static_cast<double>(count);
      if (!s.deepest || mean < deepest) {
        deepest = mean;
        s.deepest = i;
        g.read_points = count;
      }
    }
    if (!s.deepest) {
      s.status = GougeSiteStatus::not_measured;
      v.sites.push_back(std::move(g));
      continue;
    }
    s.measured_depth = -deepest;
    s.uncertainty = v.noise / std::sqrt(static_cast<double>(g.read_points));
    s.threshold = overcut_threshold(*s.uncertainty, 0.0, c.tolerance, options.gouges);
    s.status = *s.measured_depth > *s.threshold ? GougeSiteStatus::confirmed
               : covered                         ? GougeSiteStatus::not_confirmed
                                                 : GougeSiteStatus::not_measured;
    // The depth against the prediction where the prediction puts it: the
    // aligned local mean at the anchor predicted deepest (not at the
    // deepest spot measured, which the noise picks).
    std::optional<double> deepest_predicted;
    for (const Eigen::Vector3d& anchor : s.anchors) {
      double sum_measured = 0, sum_predicted = 0, sum_resolution = 0;
      std::size_t count = 0;
      grid.near(anchor, kScanReadRadius, [&](std::size_t k) {
        if (!predicted[k].reached()) return;
        sum_measured += measured[k];
        sum_predicted += predicted[k].value;
        sum_resolution += (predicted[k].max_undercut - predicted[k].max_overcut) / std::sqrt(12.0);
        ++count;
      });
      if (count < kScanReadPoints) continue;
      const double m = static_cast<double>(count);
      if (deepest_predicted && sum_predicted / m >= *deepest_predicted) continue;
      deepest_predicted = sum_predicted / m;
      s.predicted_error = sum_predicted / m;
      s.depth_consistent = std::abs(sum_measured / m - sum_predicted / m) <=
                           po.within_sigmas * std::hypot(v.noise / std::sqrt(m), sum_resolution / m);
    }
    v.sites.push_back(std::move(g));
  }
  // Unexplained overcuts: evaluated points below the lower limit, on no
  // site, whose depth the prediction does not account for at the point.
  std::vector<std::size_t> loose;
  std::vector<Eigen::Vector3d> feet;
  const double lower = c.tolerance.lower();
  for (std::size_t i = 0; i < n; ++i) {
    if (c.status[i] != ScanPointStatus::evaluated || !(c.deviation[i] < lower) || on_any[i]) continue;
    if (predicted[i].reached() && std::abs(measured[i] - predicted[i].value) <= po.within_sigmas * sigma[i]) continue;
    loose.push_back(i);
    feet.push_back(x[i] - c.deviation[i] * c.foot_normal[i].cast<double>());
  }
  if (!loose.empty()) {
    // The evaluated points within kScanSparseReach of an overcut (a cell
    // map of the overcuts decides which), searched exactly for the local
    // means of the clusters' points.
    const SiteGrid overcuts(loose, x, kScanSparseReach);
    std::vector<std::size_t> nearby;
    std::vector<Eigen::Vector3d> nearby_x;
    for (std::size_t j = 0; j < n; ++j)
      if (c.status[j] == ScanPointStatus::evaluated && overcuts.any_near(x[j], kScanSparseReach)) {
        nearby.push_back(j);
        nearby_x.push_back(x[j]);
      }
    const PointSearch search(nearby_x);
    for (const std::vector<std::size_t>& members : distance_clusters(feet, options.gouges.overcut_cluster_distance)) {
      ScanOvercutCluster u;
      OvercutCluster& k = u.cluster;
      u.points = members.size();
      u.extent_min = u.extent_max = feet[members.front()];
      double deepest = 0;
      bool read = false;
      for (const std::size_t m : members) {
        const std::size_t i = loose[m];
        k.points.push_back(i);
        k.centroid += feet[m];
        u.extent_min = u.extent_min.cwiseMin(feet[m]);
        u.extent_max = u.extent_max.cwiseMax(feet[m]);
        // The points within the read radius; in a sparse scan, where fewer
        // lie that close, the kScanReadPoints nearest within reach.
        std::vector<PointNeighbour> found = search.within(x[i], kScanReadRadius);
        if (found.size() < kScanReadPoints) {
          found = search.nearest(x[i], kScanReadPoints);
          if (found.size() < kScanReadPoints || found.back().distance > kScanSparseReach) continue;
        }
        double sum = 0;
        for (const PointNeighbour& p : found) sum += c.deviation[nearby[p.index]];
        const double mean = sum / static_cast<double>(found.size());
        if (!read || mean < deepest) {
          read = true;
          deepest = mean;
          k.deepest = i;
          u.read_points = found.size();
        }
      }
      k.centroid /= static_cast<double>(members.size());
      if (!read) continue;  // too sparse to be read: a stray point, not a dent
      k.uncertainty = v.noise / std::sqrt(static_cast<double>(u.read_points));
      k.threshold = overcut_threshold(k.uncertainty, 0.0, c.tolerance, options.gouges);
      // The local mean, not one noisy point, must lie beyond the lower
      // limit and the threshold.
      if (!(deepest < std::min(lower, -k.threshold))) continue;
      k.depth = -deepest;
      k.face_index = c.foot_face[k.deepest];
      k.face = part.faces[static_cast<std::size_t>(k.face_index)].name();
      k.uv = c.foot_uv[k.deepest];
      k.xyz = x[k.deepest] - c.deviation[k.deepest] * c.foot_normal[k.deepest].cast<double>();
      v.unexplained.push_back(std::move(u));
    }
    std::stable_sort(v.unexplained.begin(), v.unexplained.end(), [](const ScanOvercutCluster& a, const ScanOvercutCluster& b) {
      return a.cluster.depth > b.cluster.depth;
    });
    for (std::size_t k = 0; k < v.unexplained.size(); ++k) v.unexplained[k].cluster.id = "U" + std::to_string(k + 1);
  }
  c.verification = std::move(v);
  decide_scan_verdict(c);
}

}  // namespace furrow
