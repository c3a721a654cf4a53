#include "partition/curvature_field.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace furrow {

CurvatureField compute_curvature_field(const Face& face, int nu, int nv) {
  if (nu < 1 || nv < 1)
    throw InputError("curvature grid " + std::to_string(nu) + "x" + std::to_string(nv) +
                     ": both counts must be at least 1");
  CurvatureField field;
  field.nu = nu;
  field.nv = nv;
  field.domain = face.domain();
  field.samples.resize(static_cast<std::size_t>(nu) * nv);
  const double cell = field.du() * field.dv();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const Eigen::Vector2d uv = field.uv(i, j);
      CurvatureSample& s = field.samples[static_cast<std::size_t>(i) * nv + j];
      if (!face.trim().contains(uv)) {
        s.status = SampleStatus::trimmed;
        s.point = face.surface().point(uv.x(), uv.y());
        continue;
      }
      const DifferentialGeometry g = face.geometry(uv.x(), uv.y());
      s.point = g.point;
      if (g.degenerate) {
        s.status = SampleStatus::degenerate;
        continue;
      }
      s.status = SampleStatus::valid;
      s.normal = g.normal;
      s.d1 = g.d1;
      s.d2 = g.d2;
      s.K = g.K;
      s.H = g.H;
      s.k1 = g.k1;
      s.k2 = g.k2;
      s.area = g.area_element * cell;
      s.length_u = std::sqrt(g.E) * field.du();
      s.length_v = std::sqrt(g.G) * field.dv();
    }
  }
  return field;
}

std::vector<double> class_areas(const CurvatureField& field, double eps) {
  std::vector<double> areas(kCurvatureClassCount, 0.0);
  for (const CurvatureSample& s : field.samples)
    if (s.valid()) areas[static_cast<int>(classify_curvature(s.k1, s.k2, eps))] += s.area;
  return areas;
}

}  // namespace furrow
