#pragma once
// The curvature partition of a part as data: what regions.json holds
// (docs/formats.md "regions.json") and what the planner, inspection and the
// report read back.
//
// A region lies on one face and is a set of whole grid cells of that face's
// curvature field; its border is exact along cell edges (region_boundary.hpp),
// so the even-odd rule over its uv loops gives back precisely its cells:
// region_at(face, u, v) answers "which region is this surface point in" from
// the file alone, and a cell's centre is always found in the region it was
// labelled with. Points in trimmed-away or degenerate cells, or outside the
// face's domain, are in no region.
//
// Units: mm, mm^2, curvatures in 1/mm (K in 1/mm^2), sign convention of
// docs/architecture.md (normal out of the material; convex => H < 0).
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "geometry/trim.hpp"
#include "partition/classification.hpp"

namespace furrow {

struct ValueStats {
  double mean = 0, min = 0, max = 0;  // mean weighted by area
};

struct BorderLoop {
  bool hole = false;                    // clockwise in uv: a hole in the region
  std::vector<Eigen::Vector2d> uv;      // closed, first vertex not repeated
  std::vector<Eigen::Vector3d> xyz;     // the same vertices on the surface [mm]
};

struct RegionNeighbour {
  int id = 0;          // region id (same face)
  double length = 0;   // shared border [mm]
};

struct Region {
  int id = 0;
  int face = 0;  // index into RegionMap::faces (= the part's face index)
  CurvatureClass curvature_class = CurvatureClass::planar;
  double area = 0;           // mm^2, area element integrated over its cells
  double absorbed_area = 0;  // mm^2 of its cells whose own class differs (merged specks)
  int cells = 0;
  int merged_components = 1;  // connected components of the raw classes merged into it
  Eigen::AlignedBox2d uv_box;
  Eigen::AlignedBox3d xyz_box;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // area-weighted, need not be on the surface
  // A cell centre deep inside the region (largest distance to its border),
  // a safe place for a label or a first probe point.
  Eigen::Vector2d interior_uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d interior_xyz = Eigen::Vector3d::Zero();
  ValueStats K, H, k1, k2;
  std::vector<BorderLoop> border;  // outer loops first, then holes
  std::vector<RegionNeighbour> neighbours;  // by id
  int group = -1;  // RegionMap::groups: the surface it is part of across faces (-1: not grouped)
  Trim uv_outline;  // even-odd set of the border's uv loops (set with set_border)

  void set_border(std::vector<BorderLoop> loops);
};

// Regions of one class on several faces that meet tangentially
// (partition/region_groups.hpp): one surface to a metrologist, a fillet
// chain for instance. A region that joins none is a group of its own.
struct RegionGroup {
  int id = 0;
  CurvatureClass curvature_class = CurvatureClass::planar;
  double area = 0;           // sum of its regions' areas [mm^2]
  std::vector<int> regions;  // ids, ascending
  std::vector<int> faces;    // face indices, ascending, distinct
};

struct RegionFace {
  std::string name;
  std::string fingerprint;  // part_fingerprint.hpp
  int nu = 0, nv = 0;       // grid cells
  ParameterDomain domain;
  double eps = 0;             // curvature tolerance used [1/mm]
  bool eps_from_user = false;
  double curvature_scale = 0;  // [1/mm], see curvature_tolerance.hpp
  double min_area = 0;         // [mm^2] used for merging
  double area = 0;             // valid cells [mm^2]
  double class_area[kCurvatureClassCount] = {0, 0, 0, 0};  // before merging [mm^2]
  int valid_cells = 0, trimmed_cells = 0, degenerate_cells = 0;
  std::vector<int> regions;  // ids, ascending
};

struct RegionMap {
  std::string source_units = "mm";  // of the part file
  std::string part_fingerprint;
  std::vector<RegionFace> faces;
  std::vector<Region> regions;  // regions[k].id == k
  std::vector<RegionGroup> groups;  // groups[k].id == k; every region in exactly one

  // Builds `groups` from every region's `group` (ids 0..n-1, each used).
  // Precondition: the ids are that.
  void collect_groups();

  // The region holding the surface point (u, v) of face `face`, or nullopt
  // when the point is outside every region (trimmed, degenerate, outside the
  // domain) or `face` is not a face index of the map. Points exactly on a
  // border go to one of the regions sharing it.
  std::optional<int> region_at(int face, double u, double v) const;

  // Throws InputError when the map was not computed for `part`: face count,
  // face names (in order) or geometry fingerprint differ. `map_name` and
  // `part_name` (file names) appear in the message.
  void check_belongs_to(const Part& part, const std::string& map_name,
                        const std::string& part_name) const;
};

}  // namespace furrow
