#pragma once
// Parts, partitions and brute-force checks shared by the planning tests.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "partition/region_map.hpp"

namespace furrow::test {

inline Part one_face(const NurbsSurface& surface, const std::string& name = "face", Trim trim = {}) {
  Part part;
  part.faces.emplace_back(name, surface, std::move(trim));
  return part;
}

// The curvature partition at nu x nv cells per face (plan_fixtures.cpp).
RegionMap partition_of(const Part& part, int nu = 120, int nv = 120);

// A floor z = 0 over x in [x_min, 5], y in [-half_width, half_width], and
// a wall x = 5 facing -x, z in [0, height]: where an indexable head's
// assembly meets a wall (test_head_access.cpp, test_head_relocation.cpp).
inline Part floor_and_wall(double x_min, double half_width, double height) {
  Part part;
  part.faces.emplace_back("floor", make_plane({x_min, -half_width, 0}, {5 - x_min, 0, 0}, {0, 2 * half_width, 0}));
  part.faces.emplace_back("wall", make_plane({5, -half_width, 0}, {0, 0, height}, {0, 2 * half_width, 0}));
  return part;
}

// Samples of both faces of floor_and_wall() every h mm (brute-force oracles).
inline std::vector<Eigen::Vector3d> floor_and_wall_samples(double h, double x_min, double half_width, double height) {
  std::vector<Eigen::Vector3d> s;
  for (double y = -half_width; y <= half_width + 1e-9; y += h) {
    for (double x = x_min; x <= 5 + 1e-9; x += h) s.emplace_back(x, y, 0);
    for (double z = h; z <= height + 1e-9; z += h) s.emplace_back(5, y, z);
  }
  return s;
}

// A top face z = height over x in [-height tan(lean), top_to], y in
// [0, width], and below its -x edge a wall from its foot (0, y, 0) up to
// that edge, leaning out over the foot by `lean_degrees`: its normal points
// -x and `lean_degrees` below horizontal, an undercut no vertical stylus
// takes (test_auto_tips.cpp, tests/cli/test_cli_plan_tips.cpp).
inline Part undercut_part(double height, double width, double top_to, double lean_degrees) {
  const double top_x = -height * std::tan(lean_degrees * 3.14159265358979323846 / 180);
  Part part;
  part.faces.emplace_back("top", make_plane({top_x, 0, height}, {top_to - top_x, 0, 0}, {0, width, 0}));
  part.faces.emplace_back("overhang", make_plane({0, 0, 0}, {top_x, 0, height}, {0, width, 0}));
  return part;
}

// A box [0, x] x [0, y] x [0, z] of six planes, normals outward. Faces:
// 0 top (+z), 1 bottom (-z), 2 front (-y), 3 back (+y), 4 left (-x),
// 5 right (+x) (test_setups.cpp, tests/cli/test_cli_plan_setups.cpp).
inline Part box_part(double x, double y, double z) {
  Part part;
  part.faces.emplace_back("top", make_plane({0, 0, z}, {x, 0, 0}, {0, y, 0}));
  part.faces.emplace_back("bottom", make_plane({0, 0, 0}, {0, y, 0}, {x, 0, 0}));
  part.faces.emplace_back("front", make_plane({0, 0, 0}, {x, 0, 0}, {0, 0, z}));
  part.faces.emplace_back("back", make_plane({0, y, 0}, {0, 0, z}, {x, 0, 0}));
  part.faces.emplace_back("left", make_plane({0, 0, 0}, {0, 0, z}, {0, y, 0}));
  part.faces.emplace_back("right", make_plane({x, 0, 0}, {0, y, 0}, {0, 0, z}));
  return part;
}

inline Part mould() { return read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json"); }

// A flat floor z = 0 over x in [-10, 10], y in [0, 20], cut by a groove of
// radius `groove_radius` along y at x = 0 (the lower half of a cylinder,
// concave, normals toward its axis). Three faces: left floor, groove, right
// floor; all normals point up / into the air.
inline Part groove_part(double groove_radius) {
  const double pi = 3.14159265358979323846;
  const double R = groove_radius;
  Part part;
  part.faces.emplace_back("left", make_plane({-10, 0, 0}, {10 - R, 0, 0}, {0, 20, 0}));
  part.faces.emplace_back("groove", make_cylinder(R, 20, pi, 2 * pi));
  part.faces.emplace_back("right", make_plane({R, 0, 0}, {10 - R, 0, 0}, {0, 20, 0}));
  return part;
}

// Straight-line distance from p to the region's edges, by brute force: every
// uv border edge cut into `samples` pieces evaluated on the surface (points
// on the true edge), and the face's trim loops likewise.
inline double brute_edge_distance(const Part& part, const RegionMap& map, int region, const Eigen::Vector3d& p,
                                  int samples = 16) {
  const Region& r = map.regions[static_cast<std::size_t>(region)];
  const Face& face = part.faces[static_cast<std::size_t>(r.face)];
  double best = std::numeric_limits<double>::infinity();
  auto walk = [&](const std::vector<Eigen::Vector2d>& loop) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
      for (int s = 0; s <= samples; ++s) {
        const Eigen::Vector2d uv = a + (b - a) * (static_cast<double>(s) / samples);
        best = std::min(best, (face.surface().point(uv.x(), uv.y()) - p).norm());
      }
    }
  };
  for (const BorderLoop& loop : r.border) walk(loop.uv);
  for (const UvLoop& loop : face.trim().loops()) walk(loop);
  return best;
}

inline double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

inline double variance(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return s / static_cast<double>(v.size() - 1);
}

}  // namespace furrow::test
