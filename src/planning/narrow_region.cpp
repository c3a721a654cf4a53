#include "planning/narrow_region.hpp"

#include <algorithm>

namespace furrow {

namespace {

InRegion in_region_of(const Part& part, const RegionMap& map, int region_id) {
  return [&part, &map, region_id](std::size_t face, const Eigen::Vector2d& uv) {
    const std::optional<int> r = map.region_at(static_cast<int>(face), uv.x(), uv.y());
    return r && *r == region_id && part.faces[face].contains(uv.x(), uv.y());
  };
}

// Farthest from the region's edges (straight line, within kReach): the
// inside cell centre that is, moved by a compass search on (u, v).
std::optional<Eigen::Vector2d> most_interior(const RegionDomain& domain) {
  constexpr double kReach = 10;  // mm: far beyond a narrow region's half width
  const Face& f = domain.face();
  auto clearance = [&](const Eigen::Vector2d& uv) {
    if (!domain.inside(uv)) return -1.0;
    return std::min(domain.edge_distance(f.surface().point(uv.x(), uv.y()), kReach), kReach);
  };
  std::optional<Eigen::Vector2d> best;
  double best_d = -1;
  for (const DomainCell& c : domain.cells()) {
    if (!c.inside) continue;
    const double d = clearance(c.uv);
    if (d > best_d) best_d = d, best = c.uv;
  }
  if (!best) return best;
  const Eigen::AlignedBox2d& box = domain.region().uv_box;
  Eigen::Vector2d step = box.sizes() / domain.grid_cells();
  for (int halving = 0; halving < 40; ++halving) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1),
                                         Eigen::Vector2d(0, -1)}) {
        const Eigen::Vector2d uv = *best + step.cwiseProduct(dir);
        const double d = clearance(uv);
        if (d > best_d) {
          best_d = d, best = uv, moved = true;
        }
      }
    }
    step /= 2;
  }
  return best;
}

}  // namespace

RegionDomain contact_rule_domain(const Part& part, const RegionMap& map, int region_id, RegionDomainOptions options,
                                 const RiskMap* risk, const ClosestPointFinder& finder, double radius,
                                 const BallContactOptions& contact) {
  options.border = 0;
  RegionDomain domain(part, map, region_id, options, risk);
  const std::size_t face = static_cast<std::size_t>(domain.face_index());
  const Face* f = &part.faces[face];
  InRegion in_region = in_region_of(part, map, region_id);
  domain.set_contact_check([&finder, f, face, radius, contact, in_region](const Eigen::Vector2d& uv,
                                                                          const Eigen::Vector3d& xyz) {
    const DifferentialGeometry g = f->geometry(uv.x(), uv.y());
    if (g.degenerate) return false;
    return check_ball_contact(finder, face, xyz, g.normal, radius, in_region, contact) == ContactProblem::none;
  });
  return domain;
}

double largest_ball_in_region(const RegionDomain& domain, const RegionMap& map, const ClosestPointFinder& finder,
                              double radius, const BallContactOptions& contact, std::size_t max_candidates) {
  const Part& part = finder.part();
  const std::size_t face = static_cast<std::size_t>(domain.face_index());
  const Face& f = part.faces[face];
  std::vector<ContactCandidate> inside;
  for (const DomainCell& c : domain.cells()) {
    if (!c.inside) continue;
    const DifferentialGeometry g = f.geometry(c.uv.x(), c.uv.y());
    if (!g.degenerate) inside.push_back({face, g.point, g.normal});
  }
  std::vector<ContactCandidate> picked;
  const std::size_t n = std::min(inside.size(), std::max<std::size_t>(max_candidates, 1));
  for (std::size_t k = 0; k < n; ++k) picked.push_back(inside[k * inside.size() / n]);
  // The widest ball usually stands farthest from the edges, which falls
  // between cell centres on a strip: that point too, found from the best
  // cell by a pattern search.
  if (const std::optional<Eigen::Vector2d> uv = most_interior(domain)) {
    const DifferentialGeometry g = f.geometry(uv->x(), uv->y());
    if (!g.degenerate) picked.insert(picked.begin(), {face, g.point, g.normal});
  }
  return largest_fitting_ball(finder, picked, radius, in_region_of(part, map, domain.region_id()), contact);
}

}  // namespace furrow
