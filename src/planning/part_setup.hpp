#pragma once
// Setups: the part as it lies on the CMM table (docs/cmm.md "Setups").
//
// Setup 1 is the part as imported, +z up, nothing below it: the frame of
// the part file. In setup k > 1 the part rests on one of its planar faces
// (outward normal n) on a fixture plane: turned by the smallest rotation
// that takes n to -z (about the axis n x -z; a face already facing +z
// turns over about +x), then moved up so that the face lies in z = 0. The
// turn about the table's normal is fixed by that rule and not chosen: any
// other would do as well, since the alignment measured in each setup ties
// the CMM to the part, and a fixed rule gives the same programs every run.
//
// A face can carry the part only when the part lies wholly on its inner
// side (a face on the convex hull): every region border vertex and region
// interior point of the partition is at most kStableTolerance above its
// plane; and when the part's centre of mass (geometry/solid_mass.hpp)
// projects along the normal inside the convex hull of what touches the
// table (every border vertex and interior point within kStableTolerance
// of the plane: the face and any face coplanar with it), so the part does
// not tip over. When the faces do not bound a solid (an open shell) there
// is no centre of mass and only the first condition is checked. Faces that
// are not planar or not stable are refused by name.
//
// Units: mm. Pure functions; no geometry is changed in place.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "geometry/solid_mass.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// How far a point of the part may stand out of a resting face's plane and
// the face still carry it [mm] (import round-off, not a real overhang).
constexpr double kStableTolerance = 0.01;

struct PartSetup {
  int index = 1;                          // 1, 2, ...
  std::optional<int> resting_face;        // the face it rests on; none in setup 1
  // Part frame -> setup frame (the frame the setup's plan and programs are in).
  Eigen::Isometry3d to_setup = Eigen::Isometry3d::Identity();
  // The fixture plane (z in the setup frame): 0 when resting on a face.
  std::optional<double> fixture_z;
  bool named = false;                     // the face came from --setup-faces
};

// A planar face as a resting candidate.
struct RestingFace {
  int face = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, outward
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // on the face
  double area = 0;                                    // of its regions [mm^2]
  bool on_hull = false;                               // the part lies on its inner side
  // How far the centre of mass's projection lies inside the support's
  // convex hull [mm] (negative: outside, the part tips over); +infinity
  // when the part has no centre of mass (not a closed solid).
  double balance_margin = 0;
  bool stable = false;                                // on_hull and balance_margin >= 0
};

// The face as a resting candidate; nullopt when it is not planar (neither
// recognised as a plane at import nor by recognise_analytic) or holds no
// region. Precondition: `map` belongs to `part`.
std::optional<RestingFace> planar_face(const Part& part, const RegionMap& map, int face);
// The same with the part's mass computed beforehand (solid_mass(part)).
std::optional<RestingFace> planar_face(const Part& part, const RegionMap& map, int face, const SolidMass& mass);

// Every stable planar face, largest area first (ties: lower index), one per
// plane: coplanar faces (bosses of one height) are one support, named by
// the largest of them.
std::vector<RestingFace> resting_candidates(const Part& part, const RegionMap& map);

// The setup resting on `face` (index >= 2).
PartSetup resting_setup(const RestingFace& face, int index, bool named);

// Throws InputError naming `where` and the face when it is not a face of
// the part, not planar, or not stable (saying which condition fails: the
// part stands out beyond the plane, or its centre of mass lies outside the
// support and by how much).
RestingFace named_resting_face(const Part& part, const RegionMap& map, int face, const std::string& where);

// The part and its partition moved rigidly (control points, region border
// and box xyz; uv, trims and orientation unchanged).
Part moved_part(const Part& part, const Eigen::Isometry3d& motion);
RegionMap moved_regions(const RegionMap& map, const Eigen::Isometry3d& motion);

}  // namespace furrow
