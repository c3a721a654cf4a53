#pragma once
// The part's surface point straight above or below a horizontal position:
// solve S_xy(u, v) = (x, y) on a face.
//
// Why vertical and not the closest point: a 3-axis tool moves in vertical
// planes and a z-map is indexed by (x, y), so iso-planar sections, the
// design curve between two contact points of a G-code move and the nominal
// height of a z-map cell are all "the surface at this (x, y)". Faces a 3-axis
// tool can finish are graphs over the xy plane (n_z > 0), where this map is
// one-to-one and Newton's method on the 2x2 system converges from any nearby
// seed; near vertical walls (n_z -> 0) the Jacobian degenerates and the
// solver reports failure instead of guessing.
//
// Faces are assumed not to overlap in xy (a part seen from above); where
// they do, the highest point wins (the one the tool meets first).
#include <Eigen/Core>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct SurfacePoint {
  bool valid = false;  // false: no face point above/below (x, y) was found
  int face = -1;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, out of the material
};

// Unit normal of a face at (u, v) (Su x Sv, flipped when reversed), without
// the curvature analysis of Face::geometry. False at degenerate points.
bool face_normal(const Face& face, double u, double v, Eigen::Vector3d& point, Eigen::Vector3d& normal);
// The same on derivatives already evaluated at (u, v) (e.g. a SurfaceGrid row).
bool face_normal(const Face& face, const SurfaceDerivatives& d, Eigen::Vector3d& point,
                 Eigen::Vector3d& normal);
SurfacePoint surface_point(const Part& part, int face, const Eigen::Vector2d& uv);

struct VerticalProjectionOptions {
  double tolerance = 1e-9;  // residual |S_xy - (x, y)| accepted [mm]
  int max_iterations = 40;  // Newton steps per face and seed
  int seed_grid = 32;       // seed samples per direction per face
};

// Newton from `seed` on one face; valid only when the residual is below the
// tolerance at a point the face keeps (trim).
SurfacePoint project_vertically(const Part& part, int face, double x, double y, const Eigen::Vector2d& seed,
                                const VerticalProjectionOptions& options = {});

class VerticalProjector {
 public:
  explicit VerticalProjector(const Part& part, const VerticalProjectionOptions& options = {});

  // Tries `hint` (face and seed) first when given; otherwise, or when that
  // fails, every face from its nearest seed sample, keeping the highest hit.
  SurfacePoint project(double x, double y, const SurfacePoint* hint = nullptr) const;
  const Part& part() const { return *part_; }

 private:
  struct Seed {
    Eigen::Vector2d xy;
    Eigen::Vector2d uv;
  };
  const Part* part_;
  VerticalProjectionOptions options_;
  std::vector<std::vector<Seed>> seeds_;  // per face
};

}  // namespace furrow
