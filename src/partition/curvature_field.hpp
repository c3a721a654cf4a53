#pragma once
// Curvature of one face sampled on a regular (u,v) grid.
//
// Samples sit at cell centres: cell (i, j) covers [u0 + i du, u0 + (i+1) du] x
// [v0 + j dv, v0 + (j+1) dv], so a sample's `area` (area element times du dv)
// is the midpoint-rule area of its cell and sums of areas integrate over the
// face. Cells whose centre is trimmed away or whose normal is degenerate are
// marked and carry no area. Computed in parallel with OpenMP; the result does
// not depend on the thread count.
#include <Eigen/Core>
#include <vector>

#include "geometry/part.hpp"
#include "partition/large_block_allocator.hpp"
#include "partition/classification.hpp"

namespace furrow {

enum class SampleStatus : unsigned char { valid = 0, trimmed = 1, degenerate = 2 };

// Only what classification, merging, statistics and borders read: a field
// has millions of samples, and their size is most of the field's cost (the
// memory is written once and read by every later pass). Normals and principal
// directions are not kept; Face::geometry gives them at any (u, v).
struct CurvatureSample {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double K = 0, H = 0, k1 = 0, k2 = 0;
  double area = 0;  // mm^2 of the cell (0 unless valid)
  // Side lengths of the cell on the surface [mm]: |Su| du and |Sv| dv at the
  // centre (0 unless valid). They weigh shared borders when regions merge.
  double length_u = 0, length_v = 0;
  SampleStatus status = SampleStatus::trimmed;
  bool valid() const { return status == SampleStatus::valid; }
};

struct CurvatureField {
  int nu = 0, nv = 0;
  ParameterDomain domain;
  // index i * nv + j (i along u); huge-page backed when large
  // (large_block_allocator.hpp).
  std::vector<CurvatureSample, LargeBlockAllocator<CurvatureSample>> samples;

  double du() const { return domain.width_u() / nu; }
  double dv() const { return domain.width_v() / nv; }
  Eigen::Vector2d uv(int i, int j) const {
    return {domain.u0 + (i + 0.5) * du(), domain.v0 + (j + 0.5) * dv()};
  }
  const CurvatureSample& at(int i, int j) const { return samples[static_cast<std::size_t>(i) * nv + j]; }
};

// Preconditions: nu, nv >= 1 (InputError otherwise).
CurvatureField compute_curvature_field(const Face& face, int nu, int nv);

}  // namespace furrow
