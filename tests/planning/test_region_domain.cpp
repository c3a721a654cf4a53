// The clearance a region keeps from its face's trim loops (region_domain.hpp):
// each uv edge of the trim polygon is drawn on the surface with as few chords
// as keep it within half the edge margin, so the straight-line distance to
// the loop agrees with a dense sampling of the loop's image on the surface.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "partition/partition.hpp"
#include "planning/region_domain.hpp"

using namespace furrow;

TEST_CASE("region domain: the distance to a trim hole in a cylinder agrees with the densely sampled trim curve") {
  // The inside of a tube (R 10, a curved image for every straight uv edge),
  // u along the angle, v along the axis; a hole of uv radius 0.12 x 6 mm,
  // polygonised with 40 edges: its uv edges bow on the surface.
  const double a0 = kPi + 0.2, a1 = 2 * kPi - 0.2;
  const NurbsSurface tube = make_cylinder(10, 30, a0, a1);
  const ParameterDomain d = tube.domain();
  UvLoop hole;
  for (int k = 0; k < 40; ++k) {
    const double t = 2 * kPi * k / 40;
    hole.emplace_back(0.5 * (d.u0 + d.u1) + 0.25 * d.width_u() * std::cos(t),
                      0.5 * (d.v0 + d.v1) + 0.25 * d.width_v() * std::sin(t));
  }
  Part part;
  part.faces.emplace_back("tube", tube, Trim({hole}));
  PartitionOptions po;
  po.grid = GridSize{40, 40};
  const RegionMap map = partition_part(part, po).map;
  REQUIRE(!map.regions.empty());
  const RegionDomainOptions options;
  const RegionDomain domain(part, map, 0, options);

  // The hole's image: every uv edge sampled 400 times.
  std::vector<Eigen::Vector3d> curve;
  for (std::size_t k = 0; k < hole.size(); ++k)
    for (int s = 0; s < 400; ++s) {
      const Eigen::Vector2d uv = hole[k] + (hole[(k + 1) % hole.size()] - hole[k]) * (s / 400.0);
      curve.push_back(tube.point(uv.x(), uv.y()));
    }
  int near = 0;
  // Points nearer the hole than the face's own boundary.
  for (int i = 6; i <= 24; ++i)
    for (int j = 6; j <= 24; ++j) {
      const Eigen::Vector2d uv(d.u0 + d.width_u() * i / 30, d.v0 + d.width_v() * j / 30);
      if (!part.faces[0].contains(uv.x(), uv.y())) continue;
      const Eigen::Vector3d p = tube.point(uv.x(), uv.y());
      double brute = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& c : curve) brute = std::min(brute, (p - c).norm());
      const double reach = 4;
      const double face_edges = domain.face_edge_distance(p, reach);
      if (!(brute < reach - 0.01)) continue;
      ++near;
      CAPTURE(i);
      CAPTURE(j);
      CAPTURE(brute);
      // The chords depart from the curve by at most half the edge margin
      // (their sagitta); the samples are 3 um apart, 1e-5 mm covers them.
      CHECK(std::fabs(face_edges - brute) <= 0.5 * options.edge_margin + 1e-5);
    }
  CHECK(near > 20);
}
