#pragma once
// The verification parts of comparison.json, both ways: predicted versus
// measured (prediction_comparison.hpp) and gouge confirmation
// (gouge_confirmation.hpp), plus FieldReader, the checked accessor the
// comparison reader is built on. docs/formats.md "Comparison" describes the
// members.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <map>
#include <string>
#include <vector>

#include "inspection/gouge_confirmation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "base/json_fields.hpp"

namespace furrow::verification_json {

using json_fields::json;

// A JSON object with its path, so that every read names the field
// ("c.json: points[3].deviation: expected a number, found null").
struct FieldReader {
  const json& value;
  std::string where;

  FieldReader(const json& v, std::string w);
  FieldReader at(const std::string& key) const;
  const json& raw(const std::string& key) const;
  std::string path(const std::string& key) const;
  bool has(const std::string& key) const { return value.contains(key); }
  bool is_null(const std::string& key) const { return raw(key).is_null(); }

  double number(const std::string& key) const;
  double non_negative(const std::string& key) const;
  int integer(const std::string& key) const;
  std::size_t count(const std::string& key) const;
  bool boolean(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::string optional_string(const std::string& key) const;  // null -> ""
  std::optional<double> optional_number(const std::string& key) const;
  Eigen::Vector2d vector2(const std::string& key) const;
  Eigen::Vector3d vector3(const std::string& key) const;
  const json& array(const std::string& key) const;
};

json options_json(const PredictionComparisonOptions& options);
json options_json(const GougeConfirmationOptions& options);
PredictionComparisonOptions read_prediction_options(const FieldReader& node);
GougeConfirmationOptions read_gouge_options(const FieldReader& node);

// One point's "prediction" member.
json point_prediction_json(const PointPrediction& point);
PointPrediction read_point_prediction(const FieldReader& node);

// "prediction_comparison" without the per-point part.
json prediction_comparison_json(const PredictionComparison& comparison);
PredictionComparison read_prediction_comparison(const FieldReader& node);

// "gouge_sites" and "unexplained"; points are written as ids (`ids[i]` of
// point i) and read back through `index_of`.
json gouge_sites_json(const GougeConfirmation& gouges, const std::vector<std::string>& ids);
json unexplained_json(const GougeConfirmation& gouges, const std::vector<std::string>& ids);
// `root` holds both arrays.
GougeConfirmation read_gouge_confirmation(const FieldReader& root,
                                          const std::map<std::string, std::size_t>& index_of);

}  // namespace furrow::verification_json
