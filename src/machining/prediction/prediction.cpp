#include "machining/prediction/prediction.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "base/number_text.hpp"

namespace furrow {

std::string describe_step_errors(const PredictionSummary& s) {
  std::string text = "largest error " + fixed(s.max_step_error * 1000, 1) + " um, " +
                     std::to_string(s.steps_over_tolerance) + " steps over the tolerance";
  if (!s.steps_not_converged)
    return text + " (whether each step's search converged is not recorded in this file)";
  if (*s.steps_not_converged == 0) return text + ", every step exact";
  // A search stopped by its cap found a value, not the extreme: the step's
  // error may be larger than what it says (docs/formats.md "prediction.json").
  return text + "; " + std::to_string(*s.steps_not_converged) +
         (*s.steps_not_converged == 1 ? " step" : " steps") +
         " did not converge: not exact, the errors found before the iteration cap (steps[].converged false)";
}

const FaceGridRecord* Prediction::find_face(const std::string& face) const {
  for (const FaceGridRecord& f : faces)
    if (f.name == face) return &f;
  return nullptr;
}

PredictedError Prediction::predicted_error_at(const std::string& face, double u, double v) const {
  const FaceGridRecord* f = find_face(face);
  if (!f) throw InputError("prediction: no face \"" + face + "\" (the prediction was made for another part?)");
  PredictedError result;
  const ParameterDomain& d = f->domain;
  const double slack_u = 1e-12 * std::max(1.0, d.width_u()), slack_v = 1e-12 * std::max(1.0, d.width_v());
  if (!(u >= d.u0 - slack_u && u <= d.u1 + slack_u && v >= d.v0 - slack_v && v <= d.v1 + slack_v)) return result;
  // Position in cell units; cell centres at integer + 0.5.
  const double fu = (u - d.u0) / d.width_u() * f->cells_u, fv = (v - d.v0) / d.width_v() * f->cells_v;
  result.cell_u = std::clamp(static_cast<int>(std::floor(fu)), 0, f->cells_u - 1);
  result.cell_v = std::clamp(static_cast<int>(std::floor(fv)), 0, f->cells_v - 1);
  const std::size_t own = static_cast<std::size_t>(result.cell_v) * f->cells_u + result.cell_u;
  result.status = f->status[own];
  if (result.status != ErrorCellStatus::reached) return result;
  result.max_undercut = f->max_undercut[own];
  result.max_overcut = f->max_overcut[own];
  // Bilinear between the four nearest cell centres, over reached cells only
  // (the own cell always has a weight of at least 1/4).
  const double cu = std::clamp(fu - 0.5, 0.0, double(f->cells_u - 1));
  const double cv = std::clamp(fv - 0.5, 0.0, double(f->cells_v - 1));
  const int i0 = std::min(static_cast<int>(cu), std::max(f->cells_u - 2, 0));
  const int j0 = std::min(static_cast<int>(cv), std::max(f->cells_v - 2, 0));
  const double a = cu - i0, b = cv - j0;
  double sum = 0, weight = 0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      const int i = i0 + di, j = j0 + dj;
      if (i >= f->cells_u || j >= f->cells_v) continue;
      const std::size_t k = static_cast<std::size_t>(j) * f->cells_u + i;
      if (f->status[k] != ErrorCellStatus::reached) continue;
      const double w = (di ? a : 1 - a) * (dj ? b : 1 - b);
      sum += w * f->mean[k];
      weight += w;
    }
  result.value = weight > 0 ? sum / weight : f->mean[own];
  return result;
}

std::vector<int> Prediction::gouge_sites_at(const std::string& face, double u, double v) const {
  if (!find_face(face)) throw InputError("prediction: no face \"" + face + "\"");
  std::vector<int> ids;
  for (const GougeSiteRecord& s : gouge_sites)
    if (s.face == face && s.uv_box.contains(Eigen::Vector2d(u, v))) ids.push_back(s.id);
  return ids;
}

void check_prediction_against_part(const Prediction& prediction, const Part& part,
                                   const std::string& prediction_name, const std::string& part_name) {
  const std::string other =
      ": the prediction was made for another part than " + part_name + " (run furrow predict again)";
  auto face_of = [&](const std::string& face, const std::string& where) {
    const std::optional<std::size_t> f = part.find_face(face);
    if (!f) throw InputError(where + ": face \"" + face + "\" is not a face of " + part_name + other);
    return *f;
  };
  for (std::size_t k = 0; k < prediction.faces.size(); ++k) {
    const FaceGridRecord& g = prediction.faces[k];
    const std::string where = prediction_name + ": faces[" + std::to_string(k) + "]";
    const ParameterDomain& d = part.faces[face_of(g.name, where)].domain();
    const double tol = 1e-9 * std::max({1.0, d.width_u(), d.width_v()});
    if (std::abs(d.u0 - g.domain.u0) > tol || std::abs(d.u1 - g.domain.u1) > tol ||
        std::abs(d.v0 - g.domain.v0) > tol || std::abs(d.v1 - g.domain.v1) > tol)
      throw InputError(where + ": the parameter domain of face \"" + g.name + "\" differs" + other);
  }
  for (std::size_t k = 0; k < prediction.gouge_sites.size(); ++k)
    face_of(prediction.gouge_sites[k].face, prediction_name + ": gouge_sites[" + std::to_string(k) + "]");
  for (std::size_t k = 0; k < prediction.local_gouges.size(); ++k)
    face_of(prediction.local_gouges[k].at.face, prediction_name + ": local_gouges[" + std::to_string(k) + "]");
  for (std::size_t k = 0; k < prediction.rapids.gouges.size(); ++k)
    if (prediction.rapids.gouges[k].kind == "part")
      face_of(prediction.rapids.gouges[k].at.face, prediction_name + ": rapids.gouges[" + std::to_string(k) + "]");
}

}  // namespace furrow
