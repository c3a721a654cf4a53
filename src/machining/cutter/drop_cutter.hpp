#pragma once
// Bounded drop cutter: the height at which an end mill (cutter.hpp), lowered
// along its vertical axis at a given xy, first touches the part, found by
// branch and bound over parameter cells with a proven upper bound per cell,
// so a collision cannot hide between seeds (docs/tool_selection.md
// "Interference search"). contact_from_tip.cpp runs it after its seeded
// Newton search and polishes what it finds with that search's code; tool
// selection asks only its decision form (rests_above).
//
// The rest height is the maximum over part points p within the shank radius
// of phi(p) = p_z - H(p_xy), H(x, y) = height_at(|(x, y) - axis|) the
// cutter's lower envelope (+infinity beyond the radius). Two facts give a
// rigorous bound of phi over a cell:
//   1. Convex hull: each face is split once into its Bezier patches (knot
//      spans, by blossoming the homogeneous control net) and cells are
//      halved by de Casteljau subdivision of the homogeneous net, which is
//      exact. With positive weights every surface point of a cell lies in
//      the convex hull of the cell's projected control points, and the
//      net's corners are surface points.
//   2. Envelope: height_at is non-decreasing and convex in rho, and rho is
//      convex in xy, so H is convex and phi is concave in space.
// Hence over a cell, phi <= min of
//   box bound      zmax(hull box) - height_at(min xy distance axis-to-box)
//                  (H is non-decreasing with the distance), and
//   tangent bound  psi(c) + max_i grad psi(c) . (P_i - c), c the centroid of
//                  the cell's control points, P_i those points, for
//                  psi = z - H~(rho) + lambda (R' - rho), any lambda >= 0:
//                  H~ is the envelope continued beyond some rho1 < R by its
//                  tangent line (convex, finite, never above the envelope)
//                  and R' the radius that holds the cutter (below), so
//                  psi >= phi under the cutter and psi is concave: it lies
//                  below its tangent plane, and a linear function is largest
//                  over a hull at a vertex. The bound is a convex polyline in
//                  lambda, minimised exactly. lambda = 0 is the plain tangent
//                  bound; lambda > 0 (a Lagrange multiplier of rho <= R')
//                  handles the rim, where a flat end mill rests on a sloping
//                  face and the envelope is a vertical step. The slack
//                  shrinks with the square of the cell size, so the cells
//                  next to the contact, where the cutter touches the part,
//                  are settled after a few halvings; the box bound's slack
//                  shrinks only linearly.
// Lower bounds are phi at the cells' corners (surface points) kept by the
// face's trim. Cells whose upper bound is not above the best lower bound by
// more than `height_tolerance` are dropped, the others halved (best first),
// until none is left or `max_cells` cells were looked at.
//
// Grazing: a point at the shank radius does not hold the cutter up (the
// side slides along a wall it was located against: contact_from_tip.hpp).
// Control nets reach slightly inside a convex wall that the curved side
// only touches, so the search treats points within `radial_tolerance` of
// the radius as grazing: it can miss material that reaches less than that
// far horizontally into the side. Trims: a cell's bound counts trimmed-away
// parts of its rectangle (it can only be too high, never too low), lower
// bounds only come from kept points.
//
// Result: the best height found is at most the true rest height and, when
// the search was exhausted (`complete`), at least it minus
// height_tolerance (radial_tolerance as above). With the cap hit,
// `unresolved` bounds from above how high the rest can be.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "geometry/part.hpp"
#include "machining/cutter/cutter.hpp"

namespace furrow {

struct DropCutterOptions {
  double height_tolerance = 1e-5;  // [mm] cells bounded within this of the best are dropped
  double radial_tolerance = 1e-6;  // [mm] points this close to the shank radius graze (above)
  int max_cells = 20000;           // cells bounded per query before giving up (complete = false)
};

struct DropCutterResult {
  bool any = false;        // some kept part point lies under the cutter
  double tip_z = -std::numeric_limits<double>::infinity();  // best rest height found [mm]
  std::size_t face = 0;    // where (a cell corner: a surface point)
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  bool complete = true;    // false: max_cells reached with cells left
  // With complete false: no part point rests the cutter higher than this [mm].
  double unresolved = -std::numeric_limits<double>::infinity();
  int cells = 0;           // cells bounded
};

class DropCutter {
 public:
  // Keeps references to `part` and `cutter`: both must outlive it.
  DropCutter(const Part& part, const Cutter& cutter, const DropCutterOptions& options = {});
  // Lowered at `xy`; `known` is a tip height already known to be reached
  // (e.g. a tangency found by another search), -infinity if none: cells
  // that cannot beat it are dropped from the start.
  DropCutterResult drop(const Eigen::Vector2d& xy,
                        double known = -std::numeric_limits<double>::infinity()) const;
  // The decision form: whether the cutter lowered at `xy` rests above
  // `height`. The same search as drop(xy, height), stopped at the first part
  // point that holds the cutter higher (tip_z > height: proven, tip_z is
  // that point's, a lower bound of the rest height). Otherwise, when
  // complete, no point rests it higher than height + height_tolerance; when
  // not, `unresolved` bounds the rest as in drop(). An interference verdict
  // needs no more, and stopping early makes it several times cheaper than
  // the rest height.
  DropCutterResult rests_above(const Eigen::Vector2d& xy, double height) const;

  // A Bezier patch or a piece of one: homogeneous control net, row-major
  // (i along u) with (degree_u + 1) x (degree_v + 1) points.
  struct Cell {
    std::size_t face = 0;
    int p = 0, q = 0;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    std::vector<Eigen::Vector4d> net;
  };

 private:
  // A cell during the search: its net is in the search's arena at `net`.
  struct Piece {
    std::size_t face;
    int p, q;
    double u0, u1, v0, v1;
    std::size_t net;
  };
  DropCutterResult search(const Eigen::Vector2d& xy, double known, bool first_above) const;

  const Part& part_;
  const Cutter& cutter_;
  DropCutterOptions options_;
  std::vector<Cell> patches_;                 // the Bezier patches of every face
  std::vector<Eigen::AlignedBox3d> boxes_;    // their hull boxes
};

}  // namespace furrow
