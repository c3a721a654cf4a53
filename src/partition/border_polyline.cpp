#include "partition/border_polyline.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace furrow {

namespace {

double grid_coordinate(int k, int n, double lo, double hi) {
  return k == n ? hi : lo + k * ((hi - lo) / n);
}

double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Marks the nodes of xyz[first..last] that Douglas-Peucker keeps.
void thin_run(const std::vector<Eigen::Vector3d>& xyz, std::size_t first, std::size_t last,
              double tolerance, std::vector<char>& keep) {
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [s, e] = stack.back();
    stack.pop_back();
    double worst = tolerance;
    std::size_t split = 0;
    for (std::size_t k = s + 1; k < e; ++k) {
      const double d = distance_to_segment(xyz[k], xyz[s], xyz[e]);
      if (d > worst) {
        worst = d;
        split = k;
      }
    }
    if (split == 0) continue;
    keep[split] = 1;
    stack.push_back({s, split});
    stack.push_back({split, e});
  }
}

}  // namespace

BorderLoop border_polyline(const NodeLoop& loop, const Face& face, const ParameterDomain& domain,
                           int nu, int nv, double chord_tolerance) {
  const std::size_t m = loop.nodes.size();
  // Start at a corner so that every straight run is contiguous in the
  // unrolled sequence below.
  auto is_corner = [&](std::size_t k) {
    const Eigen::Vector2i in = loop.nodes[k] - loop.nodes[(k + m - 1) % m];
    const Eigen::Vector2i out = loop.nodes[(k + 1) % m] - loop.nodes[k];
    return in != out;
  };
  std::size_t start = 0;
  while (start < m && !is_corner(start)) ++start;
  if (start == m) start = 0;  // cannot happen for a closed grid loop; harmless

  std::vector<Eigen::Vector2d> uv(m + 1);
  std::vector<Eigen::Vector3d> xyz(m + 1);
  std::vector<char> keep(m + 1, 0);
  for (std::size_t k = 0; k <= m; ++k) {
    const Eigen::Vector2i& n = loop.nodes[(start + k) % m];
    uv[k] = {grid_coordinate(n.x(), nu, domain.u0, domain.u1),
             grid_coordinate(n.y(), nv, domain.v0, domain.v1)};
    xyz[k] = face.surface().point(uv[k].x(), uv[k].y());
    keep[k] = (k == 0 || k == m || is_corner((start + k) % m)) ? 1 : 0;
  }
  std::size_t run_start = 0;
  for (std::size_t k = 1; k <= m; ++k) {
    if (!keep[k]) continue;
    if (k > run_start + 1) thin_run(xyz, run_start, k, chord_tolerance, keep);
    run_start = k;
  }
  BorderLoop out;
  out.hole = loop.hole;
  for (std::size_t k = 0; k < m; ++k) {  // node m repeats node 0
    if (!keep[k]) continue;
    out.uv.push_back(uv[k]);
    out.xyz.push_back(xyz[k]);
  }
  return out;
}

}  // namespace furrow
