#pragma once
// Pre-processing of a scan before it is compared with the part
// (docs/scan.md "Pre-processing"), done with PCL in the scan module:
//
// 1. a local origin: the centroid of the cloud, in double. Every PCL type
//    holds floats, whose step 200 mm from the origin is 15 um; relative to
//    the centroid of a part-sized cloud it is below 0.01 um, so nothing
//    below is lost to floats. The file's doubles stay in ScanCloud and are
//    what the deviations are computed from.
// 2. spray, flagged and never dropped (the comparison counts each point and
//    writes it with its flag). A point is spray when it lies off the
//    surface its neighbours describe and stands out from them:
//    a. off their surface: farther than `spray_sigmas` robust standard
//       deviations (1.4826 x the median of that distance over the cloud:
//       the scan's noise) from the quadric height surface fitted to its
//       `normal_neighbours` nearest neighbours, itself left out, in the
//       frame of their plane (PCL's covariance and eigen solver; neighbours
//       more than 3 times the median off that plane dropped first, so a
//       spray point among them does not tilt it). A quadric, not the plane:
//       on a 5 mm fillet sampled 0.4 mm apart the plane lies 0.08 mm off
//       the surface, far above the noise, and flagged most of the fillet;
//    b. standing out: farther than 3 times the median of the same distance
//       over those neighbours. At a sharp edge no smooth surface fits, so
//       every neighbour near it is as far off as the point; a point thrown
//       off the surface has neighbours that fit theirs.
//    The statistical rule of pcl::StatisticalOutlierRemoval (a point whose
//    mean distance to its `outlier_neighbours` nearest neighbours exceeds
//    the cloud's mean of that figure by more than `outlier_sigmas` standard
//    deviations; computed as the class computes it, with PCL's search, in
//    one parallel pass: the class itself searches serially) is recorded
//    per point in `statistical` and names the kind: spray it flags is far
//    spray, the rest near spray. It does not flag on its own: it cannot see
//    a point 0.3 mm off a surface sampled 0.3 mm apart (a third of such
//    spray passes at any setting that keeps 99 % of the good points), and
//    it fires on good points where the neighbours are one-sided - the
//    scan's borders and silhouettes.
//    Where it fires, (a) and (b) are taken against the nearest points it
//    did not fire on: far spray at a fine pitch is dense enough to be its
//    own neighbourhood, and lies on the surface other spray describes.
//    Real form errors wider than a neighbourhood (a dent, a step of the
//    surface along a line) lie on their neighbours' surface and are kept.
// 3. the fit subset: a voxel grid of edge `voxel` mm (pcl::VoxelGrid) over
//    the points that are not spray; each occupied voxel is stood for by the
//    real point nearest its centroid, not by the centroid, because on a
//    curved surface a centroid lies inside the curve (by about
//    voxel^2 / (8 R)) and would bias the fit.
// 4. normals at the fit points: the file's where it has them, else
//    estimated by PCL's NormalEstimationOMP from the `normal_neighbours`
//    nearest points of the whole cloud (spray excluded). Their sign is the
//    file's, or arbitrary when estimated.
// 5. with a line of sight (docs/scan.md "Line of sight"): the view is
//    `viewpoint` (the scanner's position, scan frame, FILE units: scaled by
//    cloud.mm_per_unit; every point seen along the line to it, PCL's
//    convention), else `view_direction` (a parallel scanner looking along
//    it), else the file's viewpoint (a PCD's VIEWPOINT, ScanCloud::viewpoint);
//    none of them: no view, and nothing of this step is done (recorded as
//    view "none"). With a view, normals are had at EVERY point (the file's,
//    or NormalEstimationOMP over the whole cloud, spray excluded from the
//    neighbours), and a point's incidence is the angle between its normal
//    and its line of sight, sign-free (an estimated normal has no side).
//    Beyond `max_incidence_deg` the point is grazing: out of the spray
//    count (a point seen at grazing is grazing whatever else, spray is
//    judged among the rest), out of the fit subset and, in the comparison,
//    out of the evaluation - reported, never dropped. With
//    `incidence_weights` (off by default), each fit point's weight is
//    cos(incidence), the noise model of docs/scan.md "Weights": 1 where the
//    point has no normal.
//    Before the voxel grid, so the subset stands for the points kept.
//
// Deterministic: the same cloud and options give the same result on any
// thread count. Failures: InputError naming the scan for options out of
// range, a voxel so fine the grid would have more cells than PCL indexes
// (2^31), or fewer points than outlier_neighbours + 1; RuntimeModuleError
// when the module cannot be loaded.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/scan/scan_cloud.hpp"
#include "io/scan/scan_feature_start.hpp"

namespace furrow {

inline constexpr std::uint8_t kSprayFar = 1;
inline constexpr std::uint8_t kSprayNear = 2;

struct ScanPreprocessOptions {
  double voxel = 1.0;           // [mm] edge of the fit subset's voxels
  int outlier_neighbours = 16;  // k of the statistical outlier removal
  double outlier_sigmas = 3.0;  // standard deviations above the mean that make spray
  double spray_sigmas = 6.0;    // robust standard deviations off the local plane that make near spray
  bool remove_spray = true;     // false: no point is flagged as spray
  int normal_neighbours = 16;   // k of the normal estimation
  // Not pre-processing, but read with the scan's options (one table, one
  // job section): the registration's coarse start (scan_registration.hpp).
  ScanStart start = ScanStart::best;
  // The line of sight (step 5 above); at most one of the two.
  std::optional<Eigen::Vector3d> viewpoint;       // scanner position, scan frame [file units]
  std::optional<Eigen::Vector3d> view_direction;  // parallel scanner's direction, scan frame (any length)
  // Largest incidence kept, (0, 90) degrees. 75: a triangulating scanner's
  // noise at 75 degrees is already four times its noise at normal incidence
  // under the model of docs/scan.md "Weights", and scanner makers quote
  // their accuracy for surfaces within 60-70 degrees of the view.
  double max_incidence_deg = 75;
  // Weight the fit by cos(incidence) when a view is known. Off by default:
  // on the oblique test scans it did not bring the fit nearer the planted
  // placement and needed about 50 outer iterations where the unweighted fit
  // needs fewer (docs/scan.md "Weights").
  bool incidence_weights = false;
};

// The line of sight a scan was pre-processed with.
enum class ScanViewKind { none, viewpoint, direction };
const char* to_string(ScanViewKind kind);  // "none", "viewpoint", "direction"

struct ScanPreprocessed {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // local origin: the cloud's centroid [mm, file frame]
  // Per point of the cloud: 0 not spray, kSprayFar (spray the statistical
  // rule also flags) or kSprayNear (spray it does not).
  std::vector<std::uint8_t> spray;
  std::size_t spray_count = 0;  // both rules
  std::size_t spray_far = 0, spray_near = 0;
  // Per point: pcl::StatisticalOutlierRemoval's rule fired (rule 2's kind,
  // not a flag on its own), and how many.
  std::vector<bool> statistical;
  std::size_t statistical_count = 0;
  double local_plane_sigma = 0;  // [mm] the robust sigma of the near-spray rule (the scan's noise, about)
  std::vector<std::size_t> fit;              // indices of the fit subset's points, increasing
  std::vector<Eigen::Vector3f> fit_normals;  // unit normal per fit point; zero where none could be had
  bool normals_estimated = false;            // false: the file's normals
  // The line of sight (step 5), and where it came from: "option", "file"
  // (a PCD's VIEWPOINT), or "" without a view.
  ScanViewKind view = ScanViewKind::none;
  std::string view_source;
  Eigen::Vector3d view_vector = Eigen::Vector3d::Zero();  // viewpoint [mm, file frame] or unit direction
  // With a view, per point: the incidence [deg], NaN where the point has no
  // normal (kept, weight 1, counted in `no_normal`); empty without a view.
  std::vector<float> incidence;
  std::vector<bool> grazing;  // per point with a view (beyond max_incidence_deg); empty without
  std::size_t grazing_count = 0, no_normal = 0;
  // Per fit point: its weight in the registration (cos(incidence)); empty
  // when every weight is 1 (no view, or incidence_weights off).
  std::vector<double> fit_weights;
};

ScanPreprocessed preprocess_scan(const ScanCloud& cloud, const ScanPreprocessOptions& options);

}  // namespace furrow
