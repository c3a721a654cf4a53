// The feature start of a scan with PCL inside the scan module (contract in
// io/scan/scan_feature_start.hpp): both clouds thinned by one voxel grid,
// FPFH features, SampleConsensusPrerejective.
//
// GCC 12 reports a false -Warray-bounds inside Eigen::umeyama (a packet load
// of a 3-float mean), which PCL's SVD transform estimation instantiates
// here; nothing of ours is involved.
#pragma GCC diagnostic ignored "-Warray-bounds"
#include <pcl/exceptions.h>
#include <pcl/features/fpfh_omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/sample_consensus_prerejective.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "base/number_text.hpp"
#include "io/scan/pcl/scan_pcl_entry.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow::scan {

namespace {

using Cloud = pcl::PointCloud<pcl::PointNormal>;
using Features = pcl::PointCloud<pcl::FPFHSignature33>;

// Fewer thinned points than this on either side describe too little shape
// to match three of them.
constexpr std::size_t kMinPoints = 20;
// Points Prerejective draws per hypothesis (a rigid transform needs 3).
constexpr int kSamples = 3;

pcl::PointNormal point_normal(const Eigen::Vector3d& p, const Eigen::Vector3f& n) {
  pcl::PointNormal q;
  q.getVector3fMap() = p.cast<float>();
  q.getNormalVector3fMap() = n;
  q.curvature = 0;
  return q;
}

// The points with a normal, thinned by a voxel grid of edge `spacing`: per
// occupied voxel the real point nearest its centroid (with its own normal),
// in increasing index order.
Cloud::Ptr thinned(const Cloud::Ptr& all, double spacing) {
  pcl::IndicesPtr with_normal(new pcl::Indices);
  for (std::size_t i = 0; i < all->size(); ++i)
    if ((*all)[i].getNormalVector3fMap().squaredNorm() > 0) with_normal->push_back(static_cast<pcl::index_t>(i));
  Cloud::Ptr out(new Cloud);
  if (with_normal->empty()) return out;
  pcl::VoxelGrid<pcl::PointNormal> grid;
  grid.setInputCloud(all);
  grid.setIndices(with_normal);
  const float leaf = static_cast<float>(spacing);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.setDownsampleAllData(false);
  Cloud centroids;
  grid.filter(centroids);
  pcl::KdTreeFLANN<pcl::PointNormal> tree;
  tree.setInputCloud(all, with_normal);
  pcl::Indices nearest(1);
  std::vector<float> distance(1);
  std::vector<pcl::index_t> picked;
  for (const pcl::PointNormal& c : centroids)
    if (tree.nearestKSearch(c, 1, nearest, distance) == 1) picked.push_back(nearest[0]);
  std::sort(picked.begin(), picked.end());
  picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  for (const pcl::index_t i : picked) out->push_back((*all)[static_cast<std::size_t>(i)]);
  return out;
}

// FPFH of every point of `cloud` over the cloud itself; points whose
// histogram is not finite (too few neighbours) are dropped from both.
Features::Ptr features(Cloud::Ptr& cloud, double radius) {
  pcl::FPFHEstimationOMP<pcl::PointNormal, pcl::PointNormal, pcl::FPFHSignature33> estimation;
  estimation.setInputCloud(cloud);
  estimation.setInputNormals(cloud);
  estimation.setRadiusSearch(radius);
  Features::Ptr all(new Features);
  estimation.compute(*all);
  Cloud::Ptr kept(new Cloud);
  Features::Ptr out(new Features);
  for (std::size_t i = 0; i < all->size(); ++i) {
    const float* h = (*all)[i].histogram;
    if (!std::all_of(h, h + 33, [](float x) { return std::isfinite(x); })) continue;
    kept->push_back((*cloud)[i]);
    out->push_back((*all)[i]);
  }
  cloud = kept;
  return out;
}

// Whether a point's FPFH is a plane's: on a plane every angle FPFH bins is
// zero, so each of its three 11-bin histograms (each summing to 100) holds
// its mass in the middle bin. A point with at least kPlaneShare of every
// histogram there describes no shape to match (scan_feature_start.hpp).
constexpr float kPlaneShare = 0.8f;
constexpr int kBins = 11;
bool plane_like(const pcl::FPFHSignature33& f) {
  for (int h = 0; h < 3; ++h)
    if (f.histogram[h * kBins + kBins / 2] < 100.0f * kPlaneShare) return false;
  return true;
}

struct Placement {
  bool found = false;
  Eigen::Matrix4f transform = Eigen::Matrix4f::Identity();
  double share = 0, rms = 0;
};

// The share of `scan`'s points within `inlier` of a point of the part
// after `t`, and their RMS distance.
void score(const Cloud& scan, const pcl::KdTreeFLANN<pcl::PointNormal>& part, double inlier, Placement& p) {
  pcl::Indices nearest(1);
  std::vector<float> squared(1);
  std::size_t in = 0;
  double sum = 0;
  for (const pcl::PointNormal& q : scan) {
    pcl::PointNormal moved = q;
    moved.getVector3fMap() = (p.transform * q.getVector4fMap()).head<3>();
    if (part.nearestKSearch(moved, 1, nearest, squared) != 1) continue;
    if (squared[0] <= inlier * inlier) {
      ++in;
      sum += squared[0];
    }
  }
  p.share = scan.empty() ? 0 : static_cast<double>(in) / static_cast<double>(scan.size());
  p.rms = in ? std::sqrt(sum / static_cast<double>(in)) : 0;
}

// One Prerejective search over the scan's points with a shape
// (`shaped`, their features), seeded, scored over all of `scan`.
Placement search(const Cloud& scan, const Cloud::Ptr& shaped, const Features::Ptr& shaped_features,
                 const Cloud::Ptr& part, const Features::Ptr& part_features,
                 const pcl::KdTreeFLANN<pcl::PointNormal>& part_tree, const FeatureStartOptions& o) {
  pcl::SampleConsensusPrerejective<pcl::PointNormal, pcl::PointNormal, pcl::FPFHSignature33> align;
  align.setInputSource(shaped);
  align.setSourceFeatures(shaped_features);
  align.setInputTarget(part);
  align.setTargetFeatures(part_features);
  align.setMaximumIterations(o.iterations);
  align.setNumberOfSamples(kSamples);
  align.setCorrespondenceRandomness(o.correspondences);
  align.setSimilarityThreshold(static_cast<float>(o.similarity));
  align.setMaxCorrespondenceDistance(o.inlier_distance);
  align.setInlierFraction(static_cast<float>(o.min_inlier_share));
  // Prerejective draws with std::rand(): one fixed seed, the same draws.
  std::srand(o.seed);
  Cloud moved;
  align.align(moved);
  Placement p;
  if (!align.hasConverged()) return p;
  p.transform = align.getFinalTransformation();
  score(scan, part_tree, o.inlier_distance, p);
  p.found = p.share >= o.min_inlier_share;
  return p;
}

// The thinnest principal axis of the points: a scan taken from one
// direction faces along it, one way or the other.
Eigen::Vector3f thinnest_axis(const Cloud& cloud) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const pcl::PointNormal& q : cloud) mean += q.getVector3fMap().cast<double>();
  mean /= static_cast<double>(std::max<std::size_t>(cloud.size(), 1));
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const pcl::PointNormal& q : cloud) {
    const Eigen::Vector3d d = q.getVector3fMap().cast<double>() - mean;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(covariance);
  return es.eigenvectors().col(0).cast<float>();
}

}  // namespace

FeatureStart feature_start_with_pcl(const FeatureStartInput& input, const FeatureStartOptions& o) {
  FeatureStart result;
  result.used = o;
  // The part relative to its centroid (in double), so its floats step as
  // finely as the scan's, which is relative to its own.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : input.part_points) centre += p;
  if (!input.part_points.empty()) centre /= static_cast<double>(input.part_points.size());
  Cloud::Ptr part_all(new Cloud), scan_all(new Cloud);
  for (std::size_t i = 0; i < input.part_points.size(); ++i)
    part_all->push_back(point_normal(input.part_points[i] - centre, input.part_normals[i].cast<float>()));
  for (std::size_t i = 0; i < input.scan_points.size(); ++i)
    scan_all->push_back(point_normal(input.scan_points[i], input.scan_normals[i]));
  Cloud::Ptr part = thinned(part_all, o.spacing), scan = thinned(scan_all, o.spacing);
  Features::Ptr part_features = features(part, o.feature_radius);
  result.part_points = part->size();
  if (part->size() < kMinPoints) {
    result.status = "the part's sampling gave " + std::to_string(part->size()) + " points with features, too few";
    return result;
  }
  pcl::KdTreeFLANN<pcl::PointNormal> part_tree;
  part_tree.setInputCloud(part);

  // The sides the scan's normals are tried with: the file's as they are; an
  // estimate's turned to one side of the thinnest axis, then the other.
  std::vector<int> sides = {0};
  if (input.scan_normals_estimated) {
    const Eigen::Vector3f axis = thinnest_axis(*scan);
    for (pcl::PointNormal& q : *scan)
      if (q.getNormalVector3fMap().dot(axis) < 0) q.getNormalVector3fMap() *= -1.0f;
    sides = {1, -1};
  }
  Placement best;
  for (const int side : sides) {
    Cloud::Ptr facing(new Cloud(*scan));
    if (side < 0)
      for (pcl::PointNormal& q : *facing) q.getNormalVector3fMap() *= -1.0f;
    Features::Ptr scan_features = features(facing, o.feature_radius);
    result.scan_points = std::max(result.scan_points, facing->size());
    // Only the points with a shape are drawn from and matched: a plane's
    // features are all alike and match any plane of the part.
    Cloud::Ptr shaped(new Cloud);
    Features::Ptr shaped_features(new Features);
    for (std::size_t i = 0; i < facing->size(); ++i)
      if (!plane_like((*scan_features)[i])) {
        shaped->push_back((*facing)[i]);
        shaped_features->push_back((*scan_features)[i]);
      }
    result.shaped_points = std::max(result.shaped_points, shaped->size());
    if (facing->size() < kMinPoints || shaped->size() < kMinPoints) continue;
    const Placement p = search(*facing, shaped, shaped_features, part, part_features, part_tree, o);
    // More of the scan on the part wins; equal shares, the closer fit.
    if (p.found && (!best.found || p.share > best.share || (p.share == best.share && p.rms < best.rms))) {
      best = p;
      result.normal_side = side;
    }
  }
  if (result.scan_points < kMinPoints) {
    result.status = "the scan's fit subset gave " + std::to_string(result.scan_points) +
                    " points with features, too few";
    return result;
  }
  if (result.shaped_points < kMinPoints) {
    result.status = "the scan is plane-like: " + std::to_string(result.shaped_points) + " of its " +
                    std::to_string(result.scan_points) + " thinned points have a feature unlike a plane's, too few to "
                    "place it";
    return result;
  }
  if (!best.found) {
    result.status = "no placement put " + general(o.min_inlier_share) + " of the scan's points within " +
                    general(o.inlier_distance, 3) + " mm of the part (" +
                    std::to_string(o.iterations) + " hypotheses)";
    return result;
  }
  result.found = true;
  result.status = "found";
  result.inlier_share = best.share;
  result.inlier_rms = best.rms;
  // PCL's float rotation made orthonormal in double.
  const Eigen::Matrix4d m = best.transform.cast<double>();
  const Eigen::Quaterniond rotation = Eigen::Quaterniond(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).normalized();
  result.transform = Eigen::Translation3d(centre + m.topRightCorner<3, 1>()) * rotation;
  return result;
}

}  // namespace furrow::scan

extern "C" __attribute__((visibility("default"))) int furrow_scan_feature_start(
    const furrow::FeatureStartInput* input, const furrow::FeatureStartOptions* options, furrow::FeatureStart* result,
    std::string* message) {
  using furrow::scan::ScanModuleOutcome;
  return furrow::scan::guarded_entry(input->scan, "the scan's feature start", ScanModuleOutcome::failure,
                                     "PCL failed on the scan's feature start", message,
                                     [&] { *result = furrow::scan::feature_start_with_pcl(*input, *options); });
}
