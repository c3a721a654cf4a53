#pragma once
// Gouge confirmation (docs/architecture.md "Inspection"): did the gouges the machining
// prediction expects happen, and did anything cut into the part where
// nothing was expected? The rules are defended in docs/verification.md.
//
// Sites. Every predicted gouge site is checked:
//   zmap   the prediction's gouge_sites (error-map areas overcut beyond the
//          prediction's gouge threshold): id "G<n>" (the prediction's id),
//          its uv box (extended to hold its deepest point) and depth;
//   local  clusters of the prediction's local_gouges (contact points where
//          the cutter is more curved than the part, status gouge or
//          concave_crease), single linkage within contact_cluster_distance
//          mm, per face: id "L<n>" in path order, the contacts' uv box; the
//          predicted depth is the deepest overcut of the error field in
//          the reached cells meeting the site's search box (none when the
//          error field shows no overcut there).
// A measured point is ON a site when its foot lies on the site's face
// inside the site's uv box grown by site_margin mm on the surface (the
// margin is turned into parameter units with the smallest parameter speed
// |S_u|, |S_v| over 3 x 3 samples of the box, so it is at least
// site_margin mm everywhere to first order; clamped to the face's domain).
// The margin covers the alignment's and the cell grid's uncertainty about
// where a probed spot lies, and the cutter's footprint around a contact.
//
// Overcut threshold at point i (its deviation must be below -threshold):
//   threshold_i = max(overcut_sigmas * sqrt(u_i^2 + sigma_probe^2),
//                     tolerance_fraction * |lower limit of the zone|)
// (u_i the registration's 1-sigma deviation uncertainty): beyond the
// measurement's noise AND a sizeable share of what the tolerance allows below
// nominal, so that neither noise nor a harmless in-tolerance dip confirms a
// gouge.
//
// Status of a site, from the evaluated points on it:
//   not_measured   no such point;
//   confirmed      the deepest of them (smallest deviation) is an overcut
//                  beyond its threshold;
//   not_confirmed  otherwise.
// Evidence: the points, the measured depth (-deviation of the deepest),
// its uncertainty sqrt(u^2 + sigma_probe^2), the threshold, the predicted
// error at that same point and whether the two agree (|residual| <=
// within_sigmas sigma_total of the prediction comparison). A confirmed site
// whose depth disagrees is still confirmed - the gouge happened - and says
// so (depth_consistent = false).
//
// Unexplained overcuts: evaluated points below -threshold that are on no
// site and whose depth the prediction does not account for at the point
// itself (not reached, or |residual| > within_sigmas sigma_total). They are
// grouped by single linkage of their foot points within
// overcut_cluster_distance mm; each cluster is listed with its deepest
// point's location, depth and uncertainty: ids "U<n>", deepest first.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/prediction_comparison.hpp"
#include "inspection/registration.hpp"
#include "inspection/tolerance_zone.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow {

struct GougeConfirmationOptions {
  double overcut_sigmas = 3;              // k in the threshold
  double tolerance_fraction = 0.5;        // of |lower limit| in the threshold, 0..1
  double site_margin = 1.0;               // [mm] on the surface around every site
  double contact_cluster_distance = 2.0;  // [mm] local-gouge contacts of one site
  double overcut_cluster_distance = 5.0;  // [mm] measured overcuts of one cluster
};

enum class GougeSiteSource { zmap, local };
const char* to_string(GougeSiteSource source);
GougeSiteSource parse_gouge_site_source(const std::string& text, const std::string& where);

enum class GougeSiteStatus { confirmed, not_confirmed, not_measured };
const char* to_string(GougeSiteStatus status);  // "CONFIRMED", "NOT CONFIRMED", "NOT MEASURED"
GougeSiteStatus parse_gouge_site_status(const std::string& text, const std::string& where);

struct GougeSiteCheck {
  std::string id;  // "G<n>" or "L<n>"
  GougeSiteSource source = GougeSiteSource::zmap;
  std::string face;
  int face_index = 0;
  Eigen::AlignedBox2d uv_box;      // the site
  Eigen::AlignedBox2d search_box;  // grown by the margin: where points count
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // zmap: area-weighted; local: mean contact
  std::optional<double> predicted_depth;  // [mm] > 0
  std::size_t contacts = 0;               // local: contact points in the cluster
  // Where the prediction puts the gouge, on the nominal surface (part
  // frame): zmap, its deepest point; local, every contact of the cluster.
  // A scan must see these to refute a site (scan_verification.hpp).
  std::vector<Eigen::Vector3d> anchors;
  GougeSiteStatus status = GougeSiteStatus::not_measured;
  std::vector<std::size_t> points;  // evaluated points on the site (indices)
  // With points on the site:
  std::optional<std::size_t> deepest;      // the point with the smallest deviation
  std::optional<double> measured_depth;    // -deviation there [mm] (negative: material left)
  std::optional<double> uncertainty;       // 1 sigma of that deviation [mm]
  std::optional<double> threshold;         // its overcut threshold [mm]
  std::optional<double> predicted_error;   // the prediction at that point [mm], where reached
  std::optional<bool> depth_consistent;    // measured vs predicted there agree, where reached
};

struct OvercutCluster {
  std::string id;                   // "U<n>"
  std::vector<std::size_t> points;  // indices, increasing
  std::size_t deepest = 0;          // point with the smallest deviation
  std::string face;                 // of the deepest point's foot
  int face_index = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  // its foot point
  double depth = 0;        // -deviation of the deepest point [mm], > threshold
  double uncertainty = 0;  // its 1 sigma [mm]
  double threshold = 0;    // its overcut threshold [mm]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // mean foot point of the cluster
};

struct GougeConfirmation {
  std::vector<GougeSiteCheck> sites;          // zmap sites first, then local clusters
  std::vector<OvercutCluster> unexplained;    // deepest first
  std::size_t confirmed() const;
};

// The overcut threshold of a point with registration uncertainty `u` [mm].
double overcut_threshold(double u, double probe_sigma, const ToleranceZone& zone,
                         const GougeConfirmationOptions& options);

// The sites a prediction names, with their search boxes and predicted
// depths, before any measurement (the first step of confirm_gouges, shared
// with the scan's confirmation). Throws InputError for an option out of
// range or a site on a face the part does not have.
std::vector<GougeSiteCheck> predicted_gouge_sites(const Part& part, const Prediction& prediction,
                                                  const GougeConfirmationOptions& options);

// `compared` is the prediction comparison of the same registration (its
// residuals and sigma_total decide depth agreement and what the prediction
// accounts for). The prediction must belong to the part
// (check_prediction_against_part). Throws InputError for an option out of
// range.
GougeConfirmation confirm_gouges(const RegistrationResult& registration, const Part& part,
                                 const ToleranceZone& zone, const Prediction& prediction,
                                 const PredictionComparison& compared,
                                 const PredictionComparisonOptions& comparison_options,
                                 const GougeConfirmationOptions& options);

}  // namespace furrow
