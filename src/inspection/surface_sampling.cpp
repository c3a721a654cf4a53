#include "inspection/surface_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

double iso_length(const Face& face, bool along_u) {
  const ParameterDomain& d = face.domain();
  const int segments = 32;
  double total = 0;
  for (double f : {0.25, 0.5, 0.75}) {
    Eigen::Vector3d prev;
    for (int k = 0; k <= segments; ++k) {
      const double t = static_cast<double>(k) / segments;
      const double u = along_u ? d.u0 + t * d.width_u() : d.u0 + f * d.width_u();
      const double v = along_u ? d.v0 + f * d.width_v() : d.v0 + t * d.width_v();
      const Eigen::Vector3d p = face.surface().point(u, v);
      if (k > 0) total += (p - prev).norm();
      prev = p;
    }
  }
  return total / 3;
}

std::vector<SurfaceSample> sample_part_surface(const Part& part, std::size_t target_count) {
  std::vector<double> lu(part.faces.size()), lv(part.faces.size());
  double area = 0;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    lu[f] = iso_length(part.faces[f], true);
    lv[f] = iso_length(part.faces[f], false);
    area += lu[f] * lv[f];
  }
  const double spacing = std::sqrt(std::max(area, 1e-300) / std::max<std::size_t>(target_count, 1));
  std::vector<SurfaceSample> samples;
  samples.reserve(target_count + target_count / 4);
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const int nu = std::clamp(static_cast<int>(std::ceil(lu[f] / spacing)), 2, 4000);
    const int nv = std::clamp(static_cast<int>(std::ceil(lv[f] / spacing)), 2, 4000);
    const std::vector<SurfaceSample> face = sample_face_grid(part, f, nu, nv);
    samples.insert(samples.end(), face.begin(), face.end());
  }
  return samples;
}

std::vector<SurfaceSample> sample_face_grid(const Part& part, std::size_t f, int nu, int nv) {
  const Face& face = part.faces[f];
  const ParameterDomain& d = face.domain();
  std::vector<SurfaceSample> samples;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = d.u0 + (i + 0.5) / nu * d.width_u();
      const double v = d.v0 + (j + 0.5) / nv * d.width_v();
      if (!face.contains(u, v)) continue;
      const DifferentialGeometry g = face.geometry(u, v);
      if (g.degenerate) continue;
      samples.push_back({g.point, g.normal, f, {u, v}});
    }
  return samples;
}

}  // namespace furrow
