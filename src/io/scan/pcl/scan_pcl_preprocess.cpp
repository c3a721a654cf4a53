// Pre-processing a scan with PCL inside the scan module (contract in
// io/scan/scan_preprocess.hpp): local origin, spray, normals and grazing
// points with a line of sight, voxel-grid subset, normals at the fit points.
#include <pcl/common/centroid.h>
#include <pcl/common/eigen.h>
#include <pcl/exceptions.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <optional>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "io/scan/pcl/scan_pcl_entry.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow::scan {

namespace {

// Distance of point `i`, along the plane's normal, from the quadric
// height h = a u^2 + b uv + c v^2 + d u + e v + f over the plane fitted to
// `neighbours` (in the plane's frame, u and v across it, relative to the
// point): a curved surface lies on its neighbours' quadric where it lies
// off their plane by its sag, r^2 / (2 R) - 0.08 mm on a 5 mm fillet sampled
// 0.4 mm apart, far above the noise the rule is scaled to. Nullopt with
// fewer than 9 neighbours or a degenerate spread (then the plane decides).
std::optional<double> off_local_quadric(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::size_t i,
                                        const pcl::Indices& neighbours, const Eigen::Vector3f& normal) {
  if (neighbours.size() < 9) return std::nullopt;
  const Eigen::Vector3d n = normal.cast<double>().normalized();
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d e1 = n.cross(Eigen::Vector3d::Unit(axis)).normalized(), e2 = n.cross(e1);
  const Eigen::Vector3d p = cloud[i].getVector3fMap().cast<double>();
  double spread = 0;
  for (const auto j : neighbours) {
    const Eigen::Vector3d q = cloud[j].getVector3fMap().cast<double>() - p;
    spread = std::max(spread, std::abs(e1.dot(q)) + std::abs(e2.dot(q)));
  }
  if (!(spread > 0)) return std::nullopt;
  // Normal equations of the least-squares fit, fixed size (no allocation
  // per point), with u and v scaled by the spread so they are well posed.
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Vector6 right = Vector6::Zero();
  for (const auto j : neighbours) {
    const Eigen::Vector3d q = cloud[j].getVector3fMap().cast<double>() - p;
    const double u = e1.dot(q) / spread, v = e2.dot(q) / spread;
    Vector6 row;
    row << u * u, u * v, v * v, u, v, 1;
    normal_matrix.selfadjointView<Eigen::Lower>().rankUpdate(row);
    right += row * n.dot(q);
  }
  const Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>> lu(normal_matrix.selfadjointView<Eigen::Lower>().toDenseMatrix());
  if (lu.rank() < 6) return std::nullopt;
  const Vector6 coefficients = lu.solve(right);
  return std::abs(coefficients(5));  // the quadric's height at the point (u = v = 0)
}

// Distance of point `i` from the quadric (else the plane) of `neighbours`
// (its nearest points, itself left out); the plane is fitted twice, the
// second time without the neighbours more than 3 times the median off the
// first, and the quadric over the ones kept (scan_preprocess.hpp, rule b).
float off_local_surface(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::size_t i, pcl::Indices neighbours) {
  const Eigen::Vector3f p = cloud[i].getVector3fMap();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ(), centre = p;
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Matrix3f covariance;
    Eigen::Vector4f mean;
    if (neighbours.size() < 3 || pcl::computeMeanAndCovarianceMatrix(cloud, neighbours, covariance, mean) < 3)
      return 0;
    float smallest = 0;
    pcl::eigen33(covariance, smallest, normal);
    centre = mean.head<3>();
    if (pass == 1) break;
    std::vector<float> off;
    for (const auto j : neighbours) off.push_back(std::abs(normal.dot(cloud[j].getVector3fMap() - centre)));
    std::vector<float> sorted = off;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const float limit = 3 * sorted[sorted.size() / 2];
    pcl::Indices near;
    for (std::size_t m = 0; m < neighbours.size(); ++m)
      if (off[m] <= limit) near.push_back(neighbours[m]);
    neighbours.swap(near);
  }
  if (const std::optional<double> off = off_local_quadric(cloud, i, neighbours, normal)) return static_cast<float>(*off);
  return std::abs(normal.dot(p - centre));
}

// How many times its neighbours' median distance from their surfaces a
// point must lie off its own to be spray (scan_preprocess.hpp, rule b).
constexpr float kStandOut = 3.0f;

// Both spray rules over the whole cloud in one parallel pass of neighbour
// searches. The far rule is pcl::StatisticalOutlierRemoval's, computed as
// it computes it (the same search class, unsorted; the mean distance to
// the k results after the first; the threshold from the sums in double),
// so it flags the same points (tests/io/scan/test_scan_preprocess.cpp
// checks that against the class itself): the class searches serially,
// 8 s of a million-point scan's 19 on two cores.
void flag_spray(const pcl::PointCloud<pcl::PointXYZ>::Ptr& local, const ScanPreprocessOptions& options,
                ScanPreprocessed& result) {
  const std::size_t n = local->size();
  pcl::search::KdTree<pcl::PointXYZ> search(false);
  search.setInputCloud(local);
  const int k_far = options.outlier_neighbours, k_near = options.normal_neighbours;
  std::vector<float> mean_distance(n, 0.0f), off(n, 0.0f);
  const long count = static_cast<long>(n);
#pragma omp parallel
  {
    pcl::Indices found, neighbours;
    std::vector<float> squared;
#pragma omp for schedule(static)
    for (long q = 0; q < count; ++q) {
      const std::size_t i = static_cast<std::size_t>(q);
      if (search.nearestKSearch((*local)[i], k_far + 1, found, squared) == 0) continue;
      double sum = 0;
      for (int k = 1; k < k_far + 1 && k < static_cast<int>(squared.size()); ++k) sum += std::sqrt(squared[k]);
      mean_distance[i] = static_cast<float>(sum / k_far);
      if (k_near != k_far && search.nearestKSearch((*local)[i], k_near + 1, found, squared) == 0) continue;
      neighbours.clear();
      for (const auto j : found)
        if (static_cast<std::size_t>(j) != i) neighbours.push_back(j);
      off[i] = off_local_surface(*local, i, neighbours);
    }
  }
  double sum = 0, sq_sum = 0;
  for (const float d : mean_distance) {
    sum += d;
    sq_sum += d * d;  // a float product, as the class sums it
  }
  const double mean = sum / static_cast<double>(n);
  const double variance = (sq_sum - sum * sum / static_cast<double>(n)) / (static_cast<double>(n) - 1);
  const double far_limit = mean + options.outlier_sigmas * std::sqrt(variance);
  result.statistical.assign(n, false);
  std::vector<float> kept_off;
  kept_off.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (mean_distance[i] > far_limit) {
      result.statistical[i] = true;
      ++result.statistical_count;
    } else {
      kept_off.push_back(off[i]);
    }
  }
  if (kept_off.empty()) return;
  // Where the statistical rule fired, the surface is the one the points it
  // did not fire on describe: at a fine pitch far spray is dense enough
  // that a spray point's nearest neighbours are other spray points (0.5 %
  // spray 0.3-3 mm off a scan 0.1 mm apart puts some 20 of them within
  // 3 mm of each other), whose quadric passes through it and whose own
  // distances are as large as its own, so neither part of the rule could
  // see it. Refitted to its nearest clean points, a spray point lies off
  // their surface and stands out from them; a point on the scan's border,
  // where the rule also fires, lies on their surface carried on.
  pcl::IndicesPtr clean_indices(new pcl::Indices);
  clean_indices->reserve(n - result.statistical_count);
  for (std::size_t i = 0; i < n; ++i)
    if (!result.statistical[i]) clean_indices->push_back(static_cast<pcl::index_t>(i));
  pcl::search::KdTree<pcl::PointXYZ> clean(false);
  const bool refit = result.statistical_count > 0 && clean_indices->size() > static_cast<std::size_t>(k_near);
  if (refit) clean.setInputCloud(local, clean_indices);
  const auto clean_neighbours = [&](std::size_t i, pcl::Indices& found, std::vector<float>& squared) {
    return clean.nearestKSearch((*local)[i], k_near, found, squared) > 0;
  };
  if (refit) {
    std::vector<std::size_t> statistical;
    for (std::size_t i = 0; i < n; ++i)
      if (result.statistical[i]) statistical.push_back(i);
    const long statistical_count = static_cast<long>(statistical.size());
#pragma omp parallel
    {
      pcl::Indices found;
      std::vector<float> squared;
#pragma omp for schedule(static)
      for (long s = 0; s < statistical_count; ++s) {
        const std::size_t i = statistical[static_cast<std::size_t>(s)];
        off[i] = clean_neighbours(i, found, squared) ? off_local_surface(*local, i, found) : 0.0f;
      }
    }
  }
  std::nth_element(kept_off.begin(), kept_off.begin() + kept_off.size() / 2, kept_off.end());
  result.local_plane_sigma = 1.4826 * kept_off[kept_off.size() / 2];
  const double near_limit = options.spray_sigmas * result.local_plane_sigma;
  // A point off its neighbours' surface is spray only when it stands out
  // from them too: at a sharp edge every neighbour's own fit straddles the
  // edge and is as far off as the point (their median), while the
  // neighbours of a point thrown off the surface fit theirs.
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < n; ++i)
    if (off[i] > near_limit) candidates.push_back(i);
  std::vector<char> spray(candidates.size(), 0);
  const long candidate_count = static_cast<long>(candidates.size());
#pragma omp parallel
  {
    pcl::Indices found;
    std::vector<float> squared, around;
#pragma omp for schedule(static)
    for (long c = 0; c < candidate_count; ++c) {
      const std::size_t i = candidates[static_cast<std::size_t>(c)];
      const bool found_any = refit && result.statistical[i] ? clean_neighbours(i, found, squared)
                                                            : search.nearestKSearch((*local)[i], k_near + 1, found, squared) > 0;
      if (!found_any) continue;
      around.clear();
      for (const auto j : found)
        if (static_cast<std::size_t>(j) != i) around.push_back(off[static_cast<std::size_t>(j)]);
      if (around.empty()) continue;
      std::nth_element(around.begin(), around.begin() + around.size() / 2, around.end());
      spray[static_cast<std::size_t>(c)] = off[i] > kStandOut * around[around.size() / 2];
    }
  }
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!spray[c]) continue;
    const std::size_t i = candidates[c];
    if (result.statistical[i]) {
      result.spray[i] = kSprayFar;
      ++result.spray_far;
    } else {
      result.spray[i] = kSprayNear;
      ++result.spray_near;
    }
  }
}

// Unit normals estimated by PCL's NormalEstimationOMP at the points of
// `at` from their `k` nearest points of `surface` (zero where none could be
// had). Each point's normal depends on its neighbours alone: the same on
// any thread count.
std::vector<Eigen::Vector3f> estimate_normals(const pcl::PointCloud<pcl::PointXYZ>::Ptr& at,
                                              const pcl::PointCloud<pcl::PointXYZ>::Ptr& surface, int k) {
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(at);
  estimation.setSearchSurface(surface);
  estimation.setKSearch(k);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  std::vector<Eigen::Vector3f> out;
  out.reserve(normals.size());
  for (const pcl::Normal& m : normals) {
    const Eigen::Vector3f v(m.normal_x, m.normal_y, m.normal_z);
    out.push_back(v.allFinite() && v.norm() > 0 ? Eigen::Vector3f(v.normalized()) : Eigen::Vector3f::Zero());
  }
  return out;
}

// Step 5 of scan_preprocess.hpp: the incidence of every point and the
// grazing ones, from `normals` (one per point) and the view of `options`
// (resolved by preprocess_scan: the viewpoint in mm, the direction unit).
// Grazing points are spray no more (grazing is decided from geometry
// alone; spray among the rest).
void mark_grazing(const ScanCloud& cloud, const std::vector<Eigen::Vector3f>& normals,
                  const ScanPreprocessOptions& options, ScanPreprocessed& result) {
  const std::size_t n = cloud.points.size();
  result.incidence.assign(n, std::numeric_limits<float>::quiet_NaN());
  result.grazing.assign(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d m = normals[i].cast<double>();
    // The line of sight from the point to the scanner, in double: the
    // viewpoint may lie a metre off, where floats step by 60 um.
    const Eigen::Vector3d sight = options.viewpoint ? Eigen::Vector3d(*options.viewpoint - cloud.points[i])
                                                    : *options.view_direction;
    const double length = m.norm() * sight.norm();
    if (!(length > 0)) {
      ++result.no_normal;
      continue;
    }
    const double angle = degrees(std::acos(std::min(1.0, std::abs(m.dot(sight)) / length)));
    result.incidence[i] = static_cast<float>(angle);
    if (angle > options.max_incidence_deg) {
      result.grazing[i] = true;
      ++result.grazing_count;
      if (result.spray[i] == kSprayFar) --result.spray_far;
      if (result.spray[i] == kSprayNear) --result.spray_near;
      result.spray[i] = 0;
    }
  }
}

}  // namespace

ScanPreprocessed preprocess_with_pcl(const ScanCloud& cloud, const ScanPreprocessOptions& options) {
  ScanPreprocessed result;
  const std::size_t n = cloud.points.size();
  // The centroid in double, summed in index order (deterministic); every
  // float below is relative to it.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : cloud.points) sum += p;
  result.origin = sum / static_cast<double>(n);
  pcl::PointCloud<pcl::PointXYZ>::Ptr local(new pcl::PointCloud<pcl::PointXYZ>);
  local->resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = cloud.points[i] - result.origin;
    (*local)[i] = pcl::PointXYZ(static_cast<float>(d.x()), static_cast<float>(d.y()), static_cast<float>(d.z()));
  }

  // Spray: flagged by the statistical filter, never dropped from the cloud.
  result.spray.assign(n, 0);
  if (options.remove_spray) flag_spray(local, options, result);
  // The points that are not spray: the surface normals are estimated from.
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface(new pcl::PointCloud<pcl::PointXYZ>);
  const auto not_spray = [&] {
    surface->clear();
    surface->reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      if (!result.spray[i]) surface->push_back((*local)[i]);
  };

  // With a line of sight: normals at every point, the incidence, grazing.
  std::vector<Eigen::Vector3f> estimated;  // at every point, when estimated for the view
  if (options.viewpoint || options.view_direction) {
    result.view = options.viewpoint ? ScanViewKind::viewpoint : ScanViewKind::direction;
    result.view_vector = options.viewpoint ? *options.viewpoint : *options.view_direction;
    if (cloud.normals.empty()) {
      not_spray();
      if (surface->size() <= static_cast<std::size_t>(options.normal_neighbours))
        throw InputError(cloud.file + ": only " + std::to_string(surface->size()) + " of " + std::to_string(n) +
                         " points are not spray, too few to compare");
      estimated = estimate_normals(local, surface, options.normal_neighbours);
      result.normals_estimated = true;
    }
    mark_grazing(cloud, cloud.normals.empty() ? estimated : cloud.normals, options, result);
  }
  result.spray_count = result.spray_far + result.spray_near;
  pcl::IndicesPtr kept(new pcl::Indices);
  for (std::size_t i = 0; i < n; ++i)
    if (!result.spray[i] && (result.grazing.empty() || !result.grazing[i])) kept->push_back(static_cast<pcl::index_t>(i));
  if (kept->size() <= static_cast<std::size_t>(options.normal_neighbours))
    throw InputError(cloud.file + ": only " + std::to_string(kept->size()) + " of " + std::to_string(n) +
                     (result.grazing.empty() ? " points are not spray"
                                             : " points are neither spray nor seen at grazing incidence") +
                     ", too few to compare");

  // The fit subset: per occupied voxel, the real point nearest its centroid.
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(local);
  grid.setIndices(kept);
  const float leaf = static_cast<float>(options.voxel);
  grid.setLeafSize(leaf, leaf, leaf);
  pcl::PointCloud<pcl::PointXYZ> centroids;
  grid.filter(centroids);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(local, kept);
  pcl::Indices nearest(1);
  std::vector<float> distance(1);
  result.fit.reserve(centroids.size());
  for (const pcl::PointXYZ& c : centroids)
    if (tree.nearestKSearch(c, 1, nearest, distance) == 1) result.fit.push_back(static_cast<std::size_t>(nearest[0]));
  std::sort(result.fit.begin(), result.fit.end());
  result.fit.erase(std::unique(result.fit.begin(), result.fit.end()), result.fit.end());

  // Normals at the fit points: the file's, those estimated for the view,
  // or estimated now from the points that are not spray around them.
  if (!cloud.normals.empty()) {
    for (const std::size_t i : result.fit) result.fit_normals.push_back(cloud.normals[i]);
  } else if (!estimated.empty()) {
    for (const std::size_t i : result.fit) result.fit_normals.push_back(estimated[i]);
  } else {
    result.normals_estimated = true;
    not_spray();
    pcl::PointCloud<pcl::PointXYZ>::Ptr at(new pcl::PointCloud<pcl::PointXYZ>);
    for (const std::size_t i : result.fit) at->push_back((*local)[i]);
    result.fit_normals = estimate_normals(at, surface, options.normal_neighbours);
  }
  // The fit's weights, cos(incidence) (docs/scan.md "Weights").
  if (!result.incidence.empty() && options.incidence_weights) {
    result.fit_weights.reserve(result.fit.size());
    for (const std::size_t i : result.fit) {
      const float angle = result.incidence[i];
      result.fit_weights.push_back(std::isnan(angle) ? 1.0 : std::cos(radians(static_cast<double>(angle))));
    }
  }
  return result;
}

}  // namespace furrow::scan

extern "C" __attribute__((visibility("default"))) int furrow_scan_preprocess(
    const furrow::ScanCloud* cloud, const furrow::ScanPreprocessOptions* options, furrow::ScanPreprocessed* result,
    std::string* message) {
  using furrow::scan::ScanModuleOutcome;
  return furrow::scan::guarded_entry(cloud->file, "the scan pre-processing", ScanModuleOutcome::failure,
                                     "PCL failed on the scan", message,
                                     [&] { *result = furrow::scan::preprocess_with_pcl(*cloud, *options); });
}
