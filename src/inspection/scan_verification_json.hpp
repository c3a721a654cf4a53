#pragma once
// The verification members of comparison.json of a scan, both ways
// (docs/formats.md "comparison.json of a scan"): "verification" (the
// noise and read rules), "gouge_sites" and "unexplained". They are the
// probe points' members (verification_json.hpp) with what a cloud changes:
// a site's or cluster's "points" is a count, not a list of ids, and
// "deepest" the index (in the scan's finite points, the deviation cloud's
// order) of the point whose local mean is deepest; a site adds its anchors,
// how many were seen and how many points its reading holds; a cluster adds
// the points of its reading and its extent. The QA report writes the same
// members into report.json, from the same functions.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"
#include "inspection/scan_verification.hpp"

namespace furrow::scan_verification_json {

using json_fields::json;

json site_json(const ScanGougeSite& site);
json sites_json(const std::vector<ScanGougeSite>& sites);
json cluster_json(const ScanOvercutCluster& cluster);
json clusters_json(const std::vector<ScanOvercutCluster>& clusters);
// "verification": noise, read radius and points, the options.
json rules_json(const ScanVerification& verification);

// `root` holds "verification", "prediction_comparison", "gouge_sites" and
// "unexplained" (a file written before unexplained clusters of a scan has
// none: read as an empty list). InputError naming the member for anything
// missing or mistyped.
ScanVerification read_scan_verification(const JsonCursor& root);

}  // namespace furrow::scan_verification_json
