#pragma once
// The verification parts of comparison.json, both ways: predicted versus
// measured (prediction_comparison.hpp) and gouge confirmation
// (gouge_confirmation.hpp), read through the JSON cursor
// (base/json_cursor.hpp) the comparison reader is built on. docs/formats.md "Comparison" describes the
// members.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <map>
#include <string>
#include <vector>

#include "inspection/gouge_confirmation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"

namespace furrow::verification_json {

using json_fields::json;


json options_json(const PredictionComparisonOptions& options);
json options_json(const GougeConfirmationOptions& options);
PredictionComparisonOptions read_prediction_options(const JsonCursor& node);
GougeConfirmationOptions read_gouge_options(const JsonCursor& node);

// One point's "prediction" member.
json point_prediction_json(const PointPrediction& point);
PointPrediction read_point_prediction(const JsonCursor& node);

// "prediction_comparison" without the per-point part.
json prediction_comparison_json(const PredictionComparison& comparison);
PredictionComparison read_prediction_comparison(const JsonCursor& node);

// "gouge_sites" and "unexplained"; points are written as ids (`ids[i]` of
// point i) and read back through `index_of`.
json gouge_sites_json(const GougeConfirmation& gouges, const std::vector<std::string>& ids);
// One site of "gouge_sites", its points and deepest point as the caller
// names them (a probe comparison by ids, a scan by count and cloud index).
json gouge_site_json(const GougeSiteCheck& site, json points, json deepest);
json unexplained_json(const GougeConfirmation& gouges, const std::vector<std::string>& ids);
// One cluster of "unexplained", its points and deepest point as the caller
// names them.
json overcut_cluster_json(const OvercutCluster& cluster, json points, json deepest);
// The members of one site / cluster other than "points" and "deepest",
// which the caller reads in its own naming (ids, or a scan's counts and
// cloud indices).
GougeSiteCheck read_gouge_site_fields(const JsonCursor& node);
OvercutCluster read_overcut_cluster_fields(const JsonCursor& node);
// `root` holds both arrays.
GougeConfirmation read_gouge_confirmation(const JsonCursor& root,
                                          const std::map<std::string, std::size_t>& index_of);

}  // namespace furrow::verification_json
