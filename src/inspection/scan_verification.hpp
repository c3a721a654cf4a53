#pragma once
// A scan against a machining prediction (`furrow compare PART --scan FILE
// --prediction P.json`, docs/scan.md "With a prediction"): predicted versus
// measured at every evaluated point, and every predicted gouge site
// CONFIRMED, NOT CONFIRMED or NOT MEASURED from the scan points on it. The
// rules follow the probe points' (prediction_comparison.hpp,
// gouge_confirmation.hpp, docs/verification.md); what differs is what a
// dense, noisy cloud allows and needs:
//
// Predicted versus measured. The placement is re-fitted to the predicted
// surface on the registration's fit subset (compare_with_prediction on it:
// the same Ceres problem as for probe points); the correction (r, t) is then
// applied to every evaluated point to first order with its foot held:
//   measured_i = d_i + n_i . (R(r) x_i + t - x_i)
// (x_i the point in the part frame, n_i the normal at its foot: the
// point-to-tangent-plane residual the fit minimises). Residual and
// statistics per point and per region as for probe points, with
//   sigma_i^2 = noise^2 + sigma_pred,i^2
// where `noise` is the scan's own (pre-processing's local_plane_sigma, the
// robust sigma of a point off its neighbours' surface), floored at
// --probe-sigma so that every z stays finite; the registration's share is
// left out (a fit of thousands of points moves a deviation by far less
// than the noise: docs/scan.md "Registration").
//
// Reading a site. A single scan point is as noisy as `noise`, and the
// deepest of the thousands on a site is several sigmas below its true
// depth, so a site is read through local means: every evaluated point on
// the site (foot on the site's face, inside its search box grown by
// --site-margin) stands for the mean deviation of the site's points within
// kScanReadRadius mm of it (at least kScanReadPoints of them); the deepest
// such mean is the site's measured depth, with 1-sigma uncertainty
// noise / sqrt(points in it), and its threshold is the probe points'
// rule with that uncertainty: max(overcut_sigmas * u, tolerance_fraction *
// |lower limit|) (overcut_threshold).
// The site is seen where the prediction puts the gouge (its anchors:
// a z-map site's deepest point, every contact of a local-gouge cluster)
// when kScanReadPoints evaluated points lie within kScanReadRadius mm of
// each anchor. Status:
//   CONFIRMED      the measured depth exceeds its threshold (the gouge
//                  happened, wherever on the site);
//   NOT CONFIRMED  otherwise, when every anchor is seen (the scan reads no
//                  gouge where one was predicted);
//   NOT MEASURED   otherwise (no point on the site, or its predicted
//                  deepest spot hidden or cropped): never a pass.
// depth_consistent, where an anchor is seen and the prediction reached it:
// at the anchor the prediction puts deepest, the local means of the
// aligned measurement and of the prediction (predicted_error) agree within
// within_sigmas * sqrt(noise^2 / points + sigma_pred^2). At the anchor, not
// at the deepest spot measured: that one the noise picks, and on an uncut
// site it lies where the prediction is shallowest.
//
// Unexplained overcuts. The probe points' rule (gouge_confirmation.hpp)
// with what a cloud changes: a point is an overcut when its deviation lies
// below the zone's lower limit (not one sigma-scaled threshold per point:
// a dent holds hundreds of points, and the noise of one is not the
// question), on no site (its foot outside every site's search box), and
// its depth is not what the prediction expects there (reached and
// |measured - predicted| <= within_sigmas sigma). Overcuts are clustered by
// single linkage of their feet within --overcut-cluster mm
// (distance_clusters.hpp; 5 mm by default: a dent's overcut points lie a
// raster pitch apart, two dents farther apart than that are two clusters).
// A cluster is read as a site is: the deepest local mean (kScanReadRadius,
// at least kScanReadPoints points, over every evaluated point) centred on
// one of its points - in a scan too sparse for that (a raster of 1 mm and
// more: fewer than kScanReadPoints within the radius), the mean of the
// kScanReadPoints nearest evaluated points, when they lie within 3 mm; it
// is listed when that mean lies below both the
// lower limit and -threshold (threshold = the sites' rule with the mean's
// uncertainty), so a stray noisy point or a lone spray remnant below the
// limit is no dent. Listed deepest first, ids "U<n>".
#include <cstddef>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/gouge_confirmation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow {

struct ScanComparison;
struct ScanCloud;
struct CompareOptions;

// [mm] radius of the local mean a site is read through: 0.5 mm holds about
// 20 points of a 0.2 mm raster and lets a 6 mm dent's floor read within 1 %
// of its depth.
inline constexpr double kScanReadRadius = 0.5;
// Fewest points a local mean, and the view of an anchor, need.
inline constexpr std::size_t kScanReadPoints = 5;

struct ScanGougeSite {
  // id, source, face, boxes, anchors, predicted depth, status; `points`
  // the indices (into the cloud's points) of the evaluated points on the
  // site; `deepest` the point whose local mean is deepest; measured_depth,
  // uncertainty, threshold, predicted_error (the local mean of the
  // prediction at the anchor predicted deepest) and depth_consistent as
  // the header says.
  GougeSiteCheck check;
  // Evaluated points on the site: check.points.size() when computed; read
  // back from comparison.json, which records the count, check.points is
  // empty and this holds it.
  std::size_t on_site = 0;
  std::size_t read_points = 0;   // points in the deepest local mean
  std::size_t anchors_seen = 0;  // of check.anchors
};

// An unexplained overcut of a scan (the header's "Unexplained overcuts"):
// `cluster` as the probe points' (id "U<n>", deepest first), with `deepest`
// the cloud index of the point whose local mean is deepest, face, uv and
// xyz its foot, depth = -that local mean, uncertainty noise / sqrt(points
// in it), threshold, centroid the mean foot of the cluster's points;
// `cluster.points` the cloud indices of the points below the lower limit
// that make the cluster (empty when read back: the count is kept).
struct ScanOvercutCluster {
  OvercutCluster cluster;
  std::size_t points = 0;       // points below the lower limit in it
  std::size_t read_points = 0;  // points in the deepest local mean
  Eigen::Vector3d extent_min = Eigen::Vector3d::Zero(), extent_max = Eigen::Vector3d::Zero();  // of the feet [mm]
};

struct ScanVerification {
  double noise = 0;        // [mm] the per-point sigma used
  double read_radius = kScanReadRadius;
  PredictionComparisonOptions options;  // as given
  GougeConfirmationOptions gouge_options;
  // alignment (from the fit subset), overall, regions and uncompared over
  // every evaluated point; `points` is left empty (no per-point record).
  PredictionComparison compared;
  std::vector<ScanGougeSite> sites;
  std::vector<ScanOvercutCluster> unexplained;  // deepest first
  std::size_t confirmed() const;
};

// Fills comparison.verification and decides the verdict again
// (decide_scan_verdict). `cloud` is the one compared; the prediction must
// belong to the part (check_prediction_against_part). Throws InputError
// for an option out of range.
void verify_scan_prediction(ScanComparison& comparison, const ScanCloud& cloud, const Part& part,
                            const Prediction& prediction, const CompareOptions& options);

}  // namespace furrow
