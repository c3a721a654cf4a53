#include "planning/relocation.hpp"
#include "base/numbers.hpp"

#include <cmath>

namespace furrow {

std::optional<Relocated> relocate(const RegionDomain& domain, const ClosestPointFinder& finder,
                                  const Eigen::Vector2d& uv, const ProbeGeometry& probe, const AccessOptions& access,
                                  const RelocationOptions& options, bool on_site,
                                  const std::function<bool(const Eigen::Vector2d&)>& keep) {
  const Face& face = domain.face();
  const SurfaceDerivatives d = face.surface().evaluate(uv.x(), uv.y(), 1);
  const DifferentialGeometry g = face.geometry(uv.x(), uv.y());
  if (g.degenerate) return std::nullopt;
  Eigen::Matrix<double, 3, 2> J;
  J.col(0) = d.Su;
  J.col(1) = d.Sv;
  const Eigen::Matrix2d normal_matrix = J.transpose() * J;
  if (!(std::abs(normal_matrix.determinant()) > 0)) return std::nullopt;
  const Eigen::Vector3d e1 = d.Su.normalized();
  const Eigen::Vector3d e2 = g.normal.cross(e1);
  for (int ring = 1; ring <= options.rings; ++ring) {
    const double radius = options.max_distance * ring / options.rings;
    for (int k = 0; k < options.directions; ++k) {
      const double angle = 2 * kPi * (k + 0.5 * (ring % 2)) / options.directions;
      const Eigen::Vector3d offset = radius * (std::cos(angle) * e1 + std::sin(angle) * e2);
      const Eigen::Vector2d candidate = uv + normal_matrix.ldlt().solve(J.transpose() * offset);
      if (keep && !keep(candidate)) continue;
      Relocated r;
      if (!(on_site ? domain.admissible_on_site(candidate, &r.xyz) : domain.admissible(candidate, &r.xyz))) continue;
      const DifferentialGeometry gc = face.geometry(candidate.x(), candidate.y());
      if (gc.degenerate) continue;
      if (!check_access(finder, r.xyz, gc.normal, probe, access).ok()) continue;
      r.uv = candidate;
      r.normal = gc.normal;
      r.distance = (r.xyz - g.point).norm();
      return r;
    }
  }
  return std::nullopt;
}

}  // namespace furrow
