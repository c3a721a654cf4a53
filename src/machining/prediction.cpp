#include "machining/prediction.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/error.hpp"

namespace furrow {

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
  if (result.status != SampleStatus::reached) return result;
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
      if (f->status[k] != SampleStatus::reached) continue;
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

}  // namespace furrow
