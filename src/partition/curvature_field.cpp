#include "partition/curvature_field.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "geometry/surface_grid.hpp"

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
  // Cell centres as one tensor grid: the basis functions are computed once per
  // grid column and row (geometry/surface_grid.hpp), bit-identical to
  // evaluating every centre on its own.
  std::vector<double> us(nu), vs(nv);
  for (int i = 0; i < nu; ++i) us[i] = field.uv(i, 0).x();
  for (int j = 0; j < nv; ++j) vs[j] = field.uv(0, j).y();
  const SurfaceGrid grid(face.surface(), std::move(us), std::move(vs), 2);
#pragma omp parallel
  {
    SurfaceGridScratch scratch;
    std::vector<SurfaceDerivatives> row(nu);
#pragma omp for schedule(static)
    for (int j = 0; j < nv; ++j) {
      grid.evaluate_row(j, row.data(), scratch);
      for (int i = 0; i < nu; ++i) {
        const Eigen::Vector2d uv(grid.u(i), grid.v(j));
        CurvatureSample& s = field.samples[static_cast<std::size_t>(i) * nv + j];
        const SurfaceDerivatives& d = row[i];
        if (!face.trim().contains(uv)) {
          s.status = SampleStatus::trimmed;
          s.point = d.S;
          continue;
        }
        const DifferentialGeometry g = face.geometry(d);
        s.point = g.point;
        if (g.degenerate) {
          s.status = SampleStatus::degenerate;
          continue;
        }
        s.status = SampleStatus::valid;
        s.K = g.K;
        s.H = g.H;
        s.k1 = g.k1;
        s.k2 = g.k2;
        s.area = g.area_element * cell;
        s.length_u = std::sqrt(g.E) * field.du();
        s.length_v = std::sqrt(g.G) * field.dv();
      }
    }
  }
  return field;
}

}  // namespace furrow
