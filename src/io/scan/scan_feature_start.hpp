#pragma once
// A coarse start for a scan's registration from local shape features, done
// with PCL in the scan module (docs/scan.md "Registration"): the scan's fit
// subset and a sampling of the part are described by PCL's FPFH
// (FPFHEstimationOMP: a 33-bin histogram of the angles between each point's
// normal and its neighbours'), matched in feature space, and a rigid
// transform is found by PCL's SampleConsensusPrerejective.
//
// Why Prerejective rather than SampleConsensusInitialAlignment (SAC-IA):
// both draw 3 scan points and a feature match for each and fit a rigid
// transform; SAC-IA scores every hypothesis over the whole scan subset (a
// k-d search per point, so a few hundred hypotheses at most), while
// Prerejective first rejects a hypothesis whose 3 scan points and 3 part
// points do not form the same triangle (edge lengths within 10 %) - almost
// all of the wrong ones - and scores only the rest, so it affords tens of
// thousands of hypotheses in the same time. Its score is the share of scan
// points within the inlier distance of the part (then their mean squared
// distance), the figure a start is judged by.
//
// Frames and units: the scan's points are relative to its local origin
// (ScanPreprocessed::origin), the part's in the part frame, both in mm. The
// transform maps the first onto the second.
//
// Parameters (FeatureStartOptions), all derived from the voxel and the
// part's size unless set: both clouds are thinned by one voxel grid of edge
// `spacing` (so their densities match: FPFH's histograms depend on it), the
// features read `feature_radius` around each point, and a scan point within
// `inlier_distance` of a part point is an inlier. Normals: the scan's
// (ScanPreprocessed::fit_normals: the file's or PCL's estimate), the part's
// exact ones; FPFH's angles change with a normal's sign, so estimated normals
// are turned towards the side of the cloud's thinnest principal axis that
// most of them face already, and the search is run with that side and its
// opposite (the scanner looked from one of them), the better kept.
//
// A plane's FPFH is one spike (every angle zero), the same at every point,
// and matches every plane of the part: hypotheses are drawn and scored
// over the scan's points whose feature is not plane-like (each of its three
// histograms holds less than 80 % of its mass in the middle bin), and the
// placement is then scored over all. A scan with fewer than 20 such points
// is refused as plane-like (`found` false): nothing to place it by.
//
// Deterministic: Prerejective draws from std::rand, seeded with `seed`
// before each search; FPFHEstimationOMP's features do not depend on the
// thread count.
//
// Failure is reported, never thrown for a scan it cannot place: `found`
// false with `status` saying why (too few points, a plane-like
// scan, no hypothesis with min_inlier_share of the scan on the part). InputError for options out of
// range; RuntimeModuleError when the module cannot be loaded.
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace furrow {

// Which coarse start a scan's registration takes (`--scan-start`,
// docs/scan.md "Registration"): the global search's, the feature start's
// (the global search's when it finds no placement), or both fitted and the
// better kept.
enum class ScanStart { global, features, best };
const char* to_string(ScanStart start);  // "global", "features", "best"
ScanStart parse_scan_start(const std::string& text, const std::string& where);

struct FeatureStartOptions {
  // [mm] 0: derived (feature_start_parameters()).
  double spacing = 0, feature_radius = 0, inlier_distance = 0;
  int iterations = 50000;         // hypotheses drawn
  int correspondences = 5;        // feature neighbours a scan point is matched to at random
  double similarity = 0.9;        // triangle edge ratio a hypothesis must keep
  double min_inlier_share = 0.5;  // of the scan's thinned points on the part for a placement
  std::uint32_t seed = 43;        // of std::rand before each search
};

struct FeatureStartInput {
  std::string scan;                             // the file, for messages
  std::vector<Eigen::Vector3d> scan_points;     // relative to the local origin [mm]
  std::vector<Eigen::Vector3f> scan_normals;    // unit, one per point; zero where none
  bool scan_normals_estimated = false;          // sign unknown: both sides tried
  std::vector<Eigen::Vector3d> part_points;     // part frame [mm]
  std::vector<Eigen::Vector3d> part_normals;    // unit, out of the material
  double voxel = 1;                             // [mm] of the fit subset
  double part_size = 0;                         // [mm] diagonal of the part's box
};

struct FeatureStart {
  bool found = false;
  std::string status;  // "found", or why not
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // scan local -> part
  double inlier_share = 0;     // of the scan's thinned points within inlier_distance of the part
  double inlier_rms = 0;       // [mm] their RMS distance to the nearest part point
  std::size_t scan_points = 0, part_points = 0;  // after thinning
  std::size_t shaped_points = 0;  // of scan_points, those whose feature is not a plane's
  int normal_side = 0;         // +1 or -1: the side estimated normals were turned to; 0: the file's
  FeatureStartOptions used;    // with the derived values filled in
};

// The derived parameters, as documented above: spacing = max(voxel, part
// size / 60) (a few thousand points on a part, enough for its features and
// cheap to score); feature radius 5 spacings; inlier distance 1.5 spacings
// (two samplings of one surface lie about half a spacing apart).
FeatureStartOptions feature_start_parameters(const FeatureStartOptions& options, double voxel, double part_size);

FeatureStart feature_start(const FeatureStartInput& input, const FeatureStartOptions& options);

}  // namespace furrow
