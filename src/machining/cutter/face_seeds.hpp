#pragma once
// A regular sample of a face (points and normals at grid nodes over its
// parameter rectangle, domain edges included), used to seed the Newton
// solvers of contact_from_tip.hpp and the border search: a seed near the
// answer is what makes those iterations converge to the right root.
#include <Eigen/Core>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct FaceSeed {
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // out of the material
  bool valid = false;  // kept by the trim and not degenerate
};

struct FaceSeedGrid {
  int n = 0;  // nodes per direction
  std::vector<FaceSeed> seeds;  // index i * n + j (i along u)
};

// n >= 2 nodes per direction (InputError otherwise).
FaceSeedGrid make_face_seeds(const Face& face, int n);

// Parameter of node k of n along [lo, hi] (ends exact).
inline double grid_parameter(double lo, double hi, int k, int n) {
  return k == n - 1 ? hi : lo + (hi - lo) * k / (n - 1);
}

}  // namespace furrow
