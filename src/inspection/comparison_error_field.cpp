#include "inspection/comparison_error_field.hpp"

#include "base/error.hpp"

namespace furrow {

ComparisonErrorField fit_error_field(const ComparisonDocument& comparison, const Part& part,
                                     const ErrorFieldOptions& options, const std::string& where,
                                     const Prediction* prediction) {
  ComparisonErrorField out;
  out.prediction_given = prediction != nullptr;
  out.prediction_removed = out.prediction_given || comparison.prediction.has_value();
  std::vector<std::vector<FieldSample>> by_face(part.faces.size());
  for (std::size_t i = 0; i < comparison.points.size(); ++i) {
    const ComparisonDocument::Point& p = comparison.points[i];
    const std::string name = where + ": points[" + std::to_string(i) + "] (" + p.id + ")";
    if (!p.evaluated) {
      ++out.not_evaluated;
      continue;
    }
    if (p.face_index < 0 || std::size_t(p.face_index) >= part.faces.size() ||
        part.faces[std::size_t(p.face_index)].name() != p.face)
      throw InputError(name + ": face '" + p.face + "' (index " + std::to_string(p.face_index) +
                       ") is not a face of the part: the comparison is of another part");
    double value = p.deviation;
    if (prediction) {
      const PredictedError e = prediction->find_face(p.face)
                                   ? prediction->predicted_error_at(p.face, p.uv.x(), p.uv.y())
                                   : PredictedError{};
      if (!e.reached()) {
        ++out.not_predicted;
        continue;
      }
      value = p.deviation - e.value;
    } else if (out.prediction_removed) {
      if (!p.prediction || !p.prediction->compared) {
        ++out.not_predicted;
        continue;
      }
      value = p.prediction->residual;
    }
    by_face[std::size_t(p.face_index)].push_back({p.uv.x(), p.uv.y(), value});
    ++out.samples;
  }
  out.field = fit_face_fields(part, std::move(by_face), options, where);
  return out;
}

}  // namespace furrow
