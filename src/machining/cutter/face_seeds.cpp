#include "machining/cutter/face_seeds.hpp"

#include <string>

#include "base/error.hpp"

namespace furrow {

FaceSeedGrid make_face_seeds(const Face& face, int n) {
  if (n < 2) throw InputError("seed grid: " + std::to_string(n) + " nodes, need at least 2");
  FaceSeedGrid grid;
  grid.n = n;
  grid.seeds.resize(static_cast<std::size_t>(n) * n);
  const ParameterDomain& d = face.domain();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      FaceSeed& s = grid.seeds[static_cast<std::size_t>(i) * n + j];
      s.uv = {grid_parameter(d.u0, d.u1, i, n), grid_parameter(d.v0, d.v1, j, n)};
      const DifferentialGeometry g = face.geometry(s.uv.x(), s.uv.y());
      s.point = g.point;
      s.normal = g.normal;
      s.valid = !g.degenerate && face.contains(s.uv.x(), s.uv.y());
    }
  }
  return grid;
}

}  // namespace furrow
