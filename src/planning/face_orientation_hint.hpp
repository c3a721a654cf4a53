#pragma once
// Faces whose planned points mostly face down: the usual sign of a face
// whose normals point into the material (an IGES surface model, a face
// reversed in the export). Normals must point out of the material
// (docs/architecture.md "Conventions"); a 3-axis CMM probe reaches such a
// face only from below, so the planner drops its points as "tilted". When
// many points are dropped the planner names these faces, so the user looks
// at the part's orientation instead of at the probe (docs/cmm.md "Faces that face down").
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

// One candidate probe point as the planner saw it.
struct OrientationSample {
  std::size_t face = 0;  // part face index
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  bool kept = false;  // accessible (possibly after moving)
};

struct FaceFacingDown {
  std::size_t face = 0;
  std::string name;
  int candidates = 0;
  double down_share = 0;  // share of its candidates with n_z < 0
};

// A face is named when its orientation was not established by the CAD
// import's topology (Face::orientation_established: a face of a closed,
// consistently oriented solid is an underside when it faces down, never
// suspect), it has at least kMinCandidates candidates, at least kDownShare
// of their normals have n_z < 0 and none of them was kept. Sorted by face
// index; `faces` are the part's faces.
constexpr int kOrientationMinCandidates = 3;
constexpr double kOrientationDownShare = 0.9;
std::vector<FaceFacingDown> faces_facing_down(const std::vector<OrientationSample>& samples,
                                              const std::vector<Face>& faces);

// "face 12 \"top\" (98 % of its 40 candidate normals point down)"
std::string describe(const FaceFacingDown& face);
// What to do about it, one sentence.
extern const char* const kFacingDownHint;

}  // namespace furrow
