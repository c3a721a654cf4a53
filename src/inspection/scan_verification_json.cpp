// The verification members of comparison.json of a scan (contract in
// scan_verification_json.hpp).
#include "inspection/scan_verification_json.hpp"

#include "base/error.hpp"
#include "inspection/verification_json.hpp"

namespace furrow::scan_verification_json {

namespace jf = json_fields;
namespace vj = verification_json;

json site_json(const ScanGougeSite& g) {
  const GougeSiteCheck& s = g.check;
  json anchors = json::array();
  for (const Eigen::Vector3d& a : s.anchors) anchors.push_back(jf::vector_json(a));
  json j = vj::gouge_site_json(s, g.on_site, s.deepest ? json(*s.deepest) : json(nullptr));
  j["anchors"] = std::move(anchors);
  j["anchors_seen"] = g.anchors_seen;
  j["read_points"] = g.read_points;
  return j;
}

json sites_json(const std::vector<ScanGougeSite>& sites) {
  json out = json::array();
  for (const ScanGougeSite& g : sites) out.push_back(site_json(g));
  return out;
}

json cluster_json(const ScanOvercutCluster& c) {
  json j = vj::overcut_cluster_json(c.cluster, c.points, c.cluster.deepest);
  j["read_points"] = c.read_points;
  j["extent"] = {{"min", jf::vector_json(c.extent_min)}, {"max", jf::vector_json(c.extent_max)}};
  return j;
}

json clusters_json(const std::vector<ScanOvercutCluster>& clusters) {
  json out = json::array();
  for (const ScanOvercutCluster& c : clusters) out.push_back(cluster_json(c));
  return out;
}

json rules_json(const ScanVerification& v) {
  return {{"noise", jf::finite(v.noise, "scan noise")},
          {"read_radius", jf::finite(v.read_radius, "read radius")},
          {"read_points", kScanReadPoints},
          {"prediction", vj::options_json(v.options)},
          {"gouges", vj::options_json(v.gouge_options)}};
}

ScanVerification read_scan_verification(const JsonCursor& root) {
  ScanVerification v;
  const JsonCursor rules = root.at("verification");
  v.noise = rules.non_negative("noise");
  v.read_radius = rules.positive("read_radius");
  v.options = vj::read_prediction_options(rules.at("prediction"));
  v.gouge_options = vj::read_gouge_options(rules.at("gouges"));
  v.compared = vj::read_prediction_comparison(root.at("prediction_comparison"));
  const json& sites = root.array("gouge_sites");
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const JsonCursor n(sites[k], jf::child(root.path("gouge_sites"), k));
    ScanGougeSite g;
    g.check = vj::read_gouge_site_fields(n);
    g.on_site = n.count("points");
    if (!n.is_null("deepest")) g.check.deepest = n.count("deepest");
    const json& anchors = n.array("anchors");
    for (std::size_t a = 0; a < anchors.size(); ++a)
      g.check.anchors.push_back(jf::vector3(anchors[a], jf::child(n.path("anchors"), a)));
    g.anchors_seen = n.count("anchors_seen");
    g.read_points = n.count("read_points");
    if (g.check.deepest.has_value() != g.check.measured_depth.has_value() || g.anchors_seen > anchors.size())
      throw InputError(n.where() + ": a site has a deepest point exactly when it has a measured depth, and at most "
                                   "as many anchors seen as it has");
    v.sites.push_back(std::move(g));
  }
  if (const json* unexplained = root.find("unexplained"); unexplained && !unexplained->is_null()) {
    const json& list = root.array("unexplained");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JsonCursor n(list[k], jf::child(root.path("unexplained"), k));
      ScanOvercutCluster c;
      c.cluster = vj::read_overcut_cluster_fields(n);
      c.points = n.count("points");
      c.cluster.deepest = n.count("deepest");
      c.read_points = n.count("read_points");
      const JsonCursor e = n.at("extent");
      c.extent_min = e.vector3("min");
      c.extent_max = e.vector3("max");
      v.unexplained.push_back(std::move(c));
    }
  }
  return v;
}

}  // namespace furrow::scan_verification_json
