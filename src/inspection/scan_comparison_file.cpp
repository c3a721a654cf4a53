// comparison.json of a scan (contract in scan_comparison_file.hpp).
#include "inspection/scan_comparison_file.hpp"

#include <algorithm>
#include <stdexcept>

#include "inspection/comparison_json.hpp"
#include "inspection/verification_json.hpp"
#include "inspection/scan_verification_json.hpp"
#include "inspection/scan_display_json.hpp"
#include "inspection/scan_fit_options_json.hpp"

namespace furrow {

namespace jf = json_fields;
using nlohmann::json;

namespace {

// Per region of the partition (null without one); region null: the
// removed points whose foot lies in no region.
json removed_by_region_json(const ScanComparison& c, bool partition) {
  if (!partition) return nullptr;
  json out = json::array();
  for (const ScanRemovedInRegion& r : c.removed_by_region)
    out.push_back({{"region", r.region >= 0 ? json(r.region) : json(nullptr)},
                   {"spray_far", r.spray_far},
                   {"spray_near", r.spray_near},
                   {"off_part", r.off_part},
                   {"grazing", r.grazing}});
  return out;
}

json start_fit_json(const ScanStartFit& f, const char* what) {
  if (!f.ran) return {{"ran", false}, {"status", f.status}};
  return {{"ran", true},
          {"status", f.status},
          {"ok", f.ok},
          {"cost", jf::finite(f.cost, what)},
          {"rms", jf::finite(f.rms, what)},
          {"outer_iterations", f.outer_iterations},
          {"solver_iterations", f.solver_iterations}};
}

// Which start the registration kept, both starts' fits, and the feature
// start itself with the parameters it ran with. No times: the file is the
// same bytes for the same inputs.
json start_json(const ScanStartRecord& s) {
  const FeatureStart& f = s.feature;
  const FeatureStartOptions& o = f.used;
  json feature = nullptr;
  if (s.mode != ScanStart::global)
    feature = {{"found", f.found},
               {"status", f.status},
               {"inlier_share", jf::finite(f.inlier_share, "inlier share")},
               {"inlier_rms", jf::finite(f.inlier_rms, "inlier rms")},
               {"scan_points", f.scan_points},
               {"part_points", f.part_points},
               {"shaped_points", f.shaped_points},
               {"normal_side", f.normal_side},
               {"spacing", jf::finite(o.spacing, "spacing")},
               {"feature_radius", jf::finite(o.feature_radius, "feature radius")},
               {"inlier_distance", jf::finite(o.inlier_distance, "inlier distance")},
               {"iterations", o.iterations},
               {"correspondences", o.correspondences},
               {"similarity", jf::finite(o.similarity, "similarity")},
               {"min_inlier_share", jf::finite(o.min_inlier_share, "min inlier share")},
               {"seed", o.seed},
               {"rotation_to_registration", f.found ? json(jf::finite(s.feature_rotation_error, "rotation")) : json(nullptr)},
               {"translation_to_registration",
                f.found ? json(jf::finite(s.feature_translation_error, "translation")) : json(nullptr)}};
  return {{"mode", to_string(s.mode)},
          {"chosen", s.chosen},
          {"why", s.why},
          {"global", start_fit_json(s.global, "global start")},
          {"features", start_fit_json(s.features, "feature start")},
          {"feature_start", feature}};
}

// The line of sight and what it did (docs/formats.md "Comparison of a
// scan"): without one, view "none" and the reason nothing was rejected or
// weighted, said in the file rather than left to be guessed.
json line_of_sight_json(const ScanComparison& c) {
  const ScanPreprocessed& p = c.pre;
  const ScanPreprocessOptions& o = c.preprocessing;
  json j = {{"view", to_string(p.view)}};
  if (p.view == ScanViewKind::none) {
    j["source"] = nullptr;
    j["note"] = "no viewpoint or view direction given (--viewpoint, --view-direction, a PCD's VIEWPOINT): "
                "no point rejected as grazing, the fit not weighted by incidence";
    return j;
  }
  j["source"] = p.view_source;
  j[p.view == ScanViewKind::viewpoint ? "viewpoint" : "direction"] = jf::vector_json(p.view_vector);
  j["max_incidence"] = o.max_incidence_deg;
  j["grazing"] = p.grazing_count;
  j["no_normal"] = p.no_normal;
  j["weights"] = p.fit_weights.empty() ? "none" : "cos_incidence";
  if (!p.fit_weights.empty()) {
    double low = p.fit_weights.front(), sum = 0;
    for (const double w : p.fit_weights) {
      low = std::min(low, w);
      sum += w;
    }
    j["weight_min"] = low;
    j["weight_mean"] = sum / static_cast<double>(p.fit_weights.size());
  }
  return j;
}

}  // namespace

std::string scan_comparison_json(const ScanComparison& c, const ScanComparisonSources& sources) {
  const ComparisonSummary& s = c.summary;
  const RegistrationResult& r = c.registration;
  json doc;
  doc["kind"] = "scan";
  doc["furrow_version"] = FURROW_VERSION;
  doc["sources"] = {{"part", sources.part},
                    {"scan", sources.scan},
                    {"regions", sources.regions},
                    {"deviations", sources.deviations},
                    {"prediction", sources.prediction},
                    {"scan_units", sources.units}};
  const ScanPreprocessOptions& o = c.preprocessing;
  doc["preprocessing"] = {{"voxel", o.voxel},
                          {"spray_neighbours", o.outlier_neighbours},
                          {"spray_far_sigmas", o.outlier_sigmas},
                          {"spray_near_sigmas", o.spray_sigmas},
                          {"spray_removal", o.remove_spray},
                          {"normal_neighbours", o.normal_neighbours},
                          {"local_origin", jf::vector_json(c.pre.origin)},
                          {"local_plane_sigma", jf::finite(c.pre.local_plane_sigma, "local_plane_sigma")},
                          {"statistical_rule", c.pre.statistical_count},
                          {"normals", c.normals},
                          {"line_of_sight", line_of_sight_json(c)}};
  doc["points"] = {{"read", c.read},
                   {"not_finite", c.not_finite},
                   {"kept", c.evaluated},
                   {"removed", {{"spray_far", c.pre.spray_far},
                                {"spray_near", c.pre.spray_near},
                                {"off_part", c.off_part},
                                {"grazing", c.grazing}}},
                   {"removed_by_region", removed_by_region_json(c, !sources.regions.empty())},
                   {"fit", c.pre.fit.size()},
                   {"in_fit", r.in_fit_count()}};
  doc["registration"] = {{"status", r.status},
                         {"converged", r.converged},
                         {"coarse", to_string(r.coarse.method)},
                         {"coarse_median", jf::finite(r.coarse.median_distance, "coarse median")},
                         {"rms_before", jf::finite(r.rms_before, "rms_before")},
                         {"rms_after", jf::finite(r.rms_after, "rms_after")},
                         {"sigma", jf::finite(r.sigma, "sigma")},
                         {"outer_iterations", r.outer_iterations},
                         {"transform", comparison_json::matrix_json(c.transform.matrix(), "transform")},
                         {"start", start_json(c.start)}};
  doc["tolerance"] = {{"width", c.tolerance.width}, {"outside", c.tolerance.outside}};
  if (c.verification.has_value() == sources.prediction.empty())
    throw std::logic_error("scan_comparison_json: the prediction file and its results go together");
  if (c.verification) {
    const ScanVerification& v = *c.verification;
    doc["verification"] = scan_verification_json::rules_json(v);
    doc["prediction_comparison"] = verification_json::prediction_comparison_json(v.compared);
    doc["gouge_sites"] = scan_verification_json::sites_json(v.sites);
    doc["unexplained"] = scan_verification_json::clusters_json(v.unexplained);
  } else {
    doc["verification"] = nullptr;
    doc["prediction_comparison"] = nullptr;
    doc["gouge_sites"] = nullptr;
    doc["unexplained"] = nullptr;
  }
  json regions = json::array();
  for (const RegionStatistics& g : s.regions)
    regions.push_back({{"region", g.region},
                       {"deviations", comparison_json::statistics_json(g.deviations)},
                       {"out_of_tolerance", g.out_of_tolerance}});
  json inconclusive = json::array();
  for (const InconclusiveReason& why : s.inconclusive)
    inconclusive.push_back({{"kind", why.kind}, {"subject", why.subject}, {"text", why.text}});
  doc["summary"] = {{"evaluated", s.evaluated},
                    {"in_tolerance", s.in_tolerance},
                    {"out_of_tolerance", s.out_of_tolerance},
                    {"deviations", comparison_json::statistics_json(s.deviations)},
                    {"profile", jf::finite(s.profile, "profile")},
                    {"confirmed_gouges", s.confirmed_gouges},
                    {"unexplained_overcuts", s.unexplained_overcuts},
                    {"regions", regions},
                    {"alignment", s.alignment},
                    {"verdict", to_string(s.verdict)},
                    {"inconclusive", inconclusive}};
  doc["fit_options"] = scan_fit_options_json(c.fit_options);
  doc["histogram"] = scan_histogram_json(c.histogram);
  doc["display"] = scan_display_json(c.display);
  return jf::to_text(doc);
}

}  // namespace furrow
