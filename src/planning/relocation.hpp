#pragma once
// Moving an inaccessible probe point to a nearby one the probe can take.
//
// Candidates lie on `rings` circles around the point in its tangent plane,
// radii max_distance * k / rings (k = 1..rings), `directions` each
// (staggered by half a step from ring to ring), mapped to (u, v) to first
// order through the surface Jacobian. They are tried nearest ring first,
// each ring in angle order; the first that is admissible in the region
// (region_domain.hpp; on a gouge site's terms when `on_site`), passes `keep`
// and is accessible (check_access) wins.
// The reported distance is the straight-line distance between the surface
// points.
//
// Units: mm. Deterministic; thread safe for a const domain and finder.
#include <Eigen/Core>
#include <functional>
#include <optional>

#include "planning/accessibility.hpp"
#include "planning/region_domain.hpp"

namespace furrow {

struct RelocationOptions {
  double max_distance = 1;  // [mm], > 0
  int rings = 6;            // >= 1
  int directions = 12;      // >= 1
};

struct Relocated {
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double distance = 0;
};

std::optional<Relocated> relocate(const RegionDomain& domain, const ClosestPointFinder& finder,
                                  const Eigen::Vector2d& uv, const ProbeGeometry& probe, const AccessOptions& access,
                                  const RelocationOptions& options, bool on_site = false,
                                  const std::function<bool(const Eigen::Vector2d&)>& keep = {});

}  // namespace furrow
