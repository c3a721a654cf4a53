// Pre-processing a scan with PCL inside the scan module (contract in
// io/scan/scan_preprocess.hpp): local origin, spray, voxel-grid subset,
// normals.
#include <pcl/common/centroid.h>
#include <pcl/common/eigen.h>
#include <pcl/exceptions.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <string>

#include "base/error.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow::scan {

namespace {

// Distance of point `i` from the plane of its k nearest neighbours (itself
// left out), fitted twice: the second time without the neighbours more than
// 3 times the median off the first plane (scan_preprocess.hpp, rule b).
float off_local_plane(const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
                      std::size_t i, int k) {
  pcl::Indices found;
  std::vector<float> squared;
  if (tree.nearestKSearch(cloud[i], k + 1, found, squared) < 4) return 0;
  pcl::Indices neighbours;
  for (const auto j : found)
    if (static_cast<std::size_t>(j) != i) neighbours.push_back(j);
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
  return std::abs(normal.dot(p - centre));
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
  pcl::IndicesPtr kept(new pcl::Indices);
  if (options.remove_spray) {
    pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter(true);
    filter.setInputCloud(local);
    filter.setMeanK(options.outlier_neighbours);
    filter.setStddevMulThresh(options.outlier_sigmas);
    filter.filter(*kept);
    for (const auto i : *filter.getRemovedIndices()) {
      result.spray[static_cast<std::size_t>(i)] = kSprayFar;
      ++result.spray_far;
    }
    std::sort(kept->begin(), kept->end());
    // Near spray, among the points the statistical rule kept.
    if (kept->size() > static_cast<std::size_t>(options.normal_neighbours) + 1) {
      pcl::KdTreeFLANN<pcl::PointXYZ> tree;
      tree.setInputCloud(local, kept);
      std::vector<float> off(kept->size());
      const long m = static_cast<long>(kept->size());
#pragma omp parallel for schedule(static)
      for (long q = 0; q < m; ++q)
        off[static_cast<std::size_t>(q)] =
            off_local_plane(*local, tree, static_cast<std::size_t>((*kept)[static_cast<std::size_t>(q)]),
                            options.normal_neighbours);
      std::vector<float> sorted = off;
      std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
      result.local_plane_sigma = 1.4826 * sorted[sorted.size() / 2];
      const double limit = options.spray_sigmas * result.local_plane_sigma;
      pcl::IndicesPtr still(new pcl::Indices);
      for (std::size_t q = 0; q < kept->size(); ++q) {
        if (off[q] > limit) {
          result.spray[static_cast<std::size_t>((*kept)[q])] = kSprayNear;
          ++result.spray_near;
        } else {
          still->push_back((*kept)[q]);
        }
      }
      kept = still;
    }
    result.spray_count = result.spray_far + result.spray_near;
  } else {
    kept->resize(n);
    for (std::size_t i = 0; i < n; ++i) (*kept)[i] = static_cast<pcl::index_t>(i);
  }
  if (kept->size() <= static_cast<std::size_t>(options.normal_neighbours))
    throw InputError(cloud.file + ": only " + std::to_string(kept->size()) + " of " + std::to_string(n) +
                     " points are not spray, too few to compare");

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

  // Normals at the fit points: the file's, or estimated from the points
  // that are not spray around them.
  if (!cloud.normals.empty()) {
    for (const std::size_t i : result.fit) result.fit_normals.push_back(cloud.normals[i]);
    return result;
  }
  result.normals_estimated = true;
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface(new pcl::PointCloud<pcl::PointXYZ>);
  surface->reserve(kept->size());
  for (const auto i : *kept) surface->push_back((*local)[static_cast<std::size_t>(i)]);
  pcl::PointCloud<pcl::PointXYZ>::Ptr at(new pcl::PointCloud<pcl::PointXYZ>);
  for (const std::size_t i : result.fit) at->push_back((*local)[i]);
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(at);
  estimation.setSearchSurface(surface);
  estimation.setKSearch(options.normal_neighbours);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  result.fit_normals.reserve(result.fit.size());
  for (const pcl::Normal& m : normals) {
    const Eigen::Vector3f v(m.normal_x, m.normal_y, m.normal_z);
    result.fit_normals.push_back(v.allFinite() && v.norm() > 0 ? Eigen::Vector3f(v.normalized())
                                                               : Eigen::Vector3f::Zero());
  }
  return result;
}

}  // namespace furrow::scan

extern "C" __attribute__((visibility("default"))) int furrow_scan_preprocess(
    const furrow::ScanCloud* cloud, const furrow::ScanPreprocessOptions* options, furrow::ScanPreprocessed* result,
    std::string* message) {
  using furrow::scan::ScanModuleOutcome;
  try {
    *result = furrow::scan::preprocess_with_pcl(*cloud, *options);
    return static_cast<int>(ScanModuleOutcome::ok);
  } catch (const furrow::InputError& e) {
    *message = e.what();
    return static_cast<int>(ScanModuleOutcome::input_error);
  } catch (const std::bad_alloc&) {
    return static_cast<int>(ScanModuleOutcome::out_of_memory);
  } catch (const pcl::PCLException& e) {
    *message = cloud->file + ": PCL failed on the scan: " + e.detailedMessage();
    return static_cast<int>(ScanModuleOutcome::failure);
  } catch (const std::exception& e) {
    *message = cloud->file + ": the scan pre-processing failed: " + e.what();
    return static_cast<int>(ScanModuleOutcome::failure);
  } catch (...) {
    *message = cloud->file + ": the scan pre-processing failed with an unknown exception";
    return static_cast<int>(ScanModuleOutcome::failure);
  }
}
