#pragma once
// Foot point of a 3-D point on a part: the closest point over all faces,
// with its face and (u,v). Used to attach curvature to contact points read
// from a file (furrow gouge --points).
//
// Method: every face is sampled once on a seed grid (face_seeds.hpp); a query
// starts Newton iterations on the distance function from the nearest seeds
// over all faces and keeps the closest converged foot point kept by its
// face's trim. Newton uses the exact Hessian when it is positive definite and
// Gauss-Newton otherwise, with step halving so the distance never grows, and
// clamps to the parameter rectangle (a foot point on a face edge is found as
// such). Non-convergence within the cap is reported, never hidden.
//
// (A general closest-point routine belongs in geometry/; this one lives here
// until the foundation has one, and is kept self-contained for the move.)
#include <Eigen/Core>
#include <vector>

#include "geometry/part.hpp"
#include "machining/face_seeds.hpp"

namespace furrow {

struct ClosestPointOptions {
  int seed_grid = 17;        // seed nodes per direction per face
  int max_starts = 4;        // Newton starts from the nearest seeds
  int max_iterations = 50;   // per start
  // Converged when a step moves (u,v) by less than this fraction of the
  // domain width (1e-12: sub-nanometre on any part size).
  double parameter_tolerance = 1e-12;
};

struct FootPoint {
  bool found = false;      // a converged foot point kept by its face's trim
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double distance = 0;     // [mm] from the query
  int starts = 0;          // Newton starts tried
  int failed_starts = 0;   // of which did not converge within the cap
};

class PartProjector {
 public:
  explicit PartProjector(const Part& part, const ClosestPointOptions& options = {});
  FootPoint project(const Eigen::Vector3d& query) const;

 private:
  const Part& part_;
  ClosestPointOptions options_;
  std::vector<FaceSeedGrid> seeds_;
};

}  // namespace furrow
