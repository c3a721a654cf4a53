#pragma once
// Seed cells for the global closest-point search (closest_point.hpp): every
// face of a part cut into small (u,v) boxes, each with an oriented bounding
// box and a cone of normals of its piece of surface, and a binary tree of
// axis-aligned boxes over all cells.
//
// Cells follow the knot spans (ClosestPointOptions::cells_per_span per span
// and direction, at least min_cells and at most max_cells per direction), so
// a cell is polynomial and small against the surface's features.
//
// Bounding volumes are conservative: oriented boxes hold a 9 x 9 sub-sample
// of the cell grown by a bound on how far the surface can bulge between
// sub-samples, (hu^2 |Suu| + 2 hu hv |Suv| + hv^2 |Svv|) / 8 with the
// sampled maxima doubled. The distance from q to a cell's box is a lower
// bound on the distance to its surface; that is what lets the search skip
// cells safely. (A bounding sphere was kept too until it was measured never
// to prune a cell the box had not: the box about the middle tangent frame is
// the tighter of the two.)
//
// Cones of normals (CellBounds::may_hold_foot) are bounded the same way: the
// angle between the middle normal and the normals at the sub-samples, plus
// the most the normal can turn from the nearest sub-sample (half a sub-step
// in u and in v), |dn/du| <= (|Suu x Sv| + |Su x Suv|) / |Su x Sv| (and
// likewise along v) with the sampled maxima doubled.
//
// Trims: cells wholly trimmed away are dropped; cells cut by a trim loop keep
// the loop segments clipped to their box, so the search can minimise along
// the trim boundary there.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/bezier_patch.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/part.hpp"

namespace furrow {

// The cell itself: where it lies in (u,v), its seeds and its trim.
struct SeedCell {
  std::uint32_t face = 0;
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();  // (u,v) box
  // Tangent plane at the middle sample: seeds Newton at q's projection on it.
  Eigen::Vector3d middle_su = Eigen::Vector3d::Zero(), middle_sv = Eigen::Vector3d::Zero();
  // Corners (lo, (hi.u, lo.v), (lo.u, hi.v), hi) and the middle, in (u,v) and 3-D.
  Eigen::Vector2d sample_uv[5];
  Eigen::Vector3d sample_point[5];
  std::uint8_t sample_kept = 0x1f;  // bit k: sample k is kept by the trim
  bool cut_by_trim = false;
  std::uint32_t first_segment = 0, segment_count = 0;  // into SeedGrid::trim_segments()
};

// What the search reads of every cell it walks past, kept apart from the
// SeedCell it bounds (SeedGrid::bounds() runs parallel to cells()): a query
// far from the surface screens some twenty cells and solves two, so the
// screening data is packed into three cache lines, not spread over seven.
struct CellBounds {
  // Oriented bounding box: rows of `axes` are the unit tangents and normal
  // at the middle, `half_extent` the half sizes along them, about `centre`.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extent = Eigen::Vector3d::Zero();
  // A point of the cell's surface kept by the trim (the middle sample when
  // it is kept): its distance from q bounds the answer from above. Infinite
  // when no sample of the cell is kept.
  Eigen::Vector3d surface_point = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  // Cone of normals about the box's third axis (the middle normal): every
  // unit normal of the cell makes an angle of at most atan(cone_tan) with
  // +-that axis. Negative when the cell is never pruned by it: it touches
  // the face's domain edge or a trim loop (feet there need not be
  // orthogonal), has a degenerate normal, or its normals turn by 80 degrees
  // or more.
  double cone_tan = -1;

  // False when no point of the cell can be an orthogonal foot of q: q - S
  // would have to lie along a normal, but q is too far sideways of the
  // oriented box for any direction in the double cone of normals. A global
  // minimum inside the face's domain is such a foot (the distance is
  // stationary there), so a cell for which this is false cannot hold it.
  bool may_hold_foot(const Eigen::Vector3d& q) const;
  // False when no point within `radius` of `c` can have an orthogonal foot
  // in the cell: the same test with every coordinate of q free to move by
  // `radius` (candidate_voxels.hpp).
  bool may_hold_foot_near(const Eigen::Vector3d& c, double radius) const;
  // A lower bound on the squared distance from q to any surface point of
  // the cell (to the oriented box), or infinity when the cell cannot hold
  // an orthogonal foot of q: both tests share q in the box's frame.
  // Squared because the search compares it with squared distances only.
  double squared_screen(const Eigen::Vector3d& q) const;
};

// A trim loop segment clipped to one cell, in (u,v), with a sphere holding
// its image on the surface: about the chord between its end points, the
// radius half the chord plus the most the image can bow away from it,
// (du^2 |Suu| + 2 |du dv| |Suv| + dv^2 |Svv|) / 8 with the cell's sampled
// maxima doubled (as for the cell's own volumes). The closest-point search
// solves a cut cell's segments nearest sphere first and skips those whose
// sphere is farther than the best foot: a fine trim polygon has hundreds of
// segments in a cell.
struct TrimSegment {
  Eigen::Vector2d a, b;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

// Node of the box tree: an axis-aligned box holding the oriented boxes of
// its cells. Leaves cover cells [first, first + count).
struct SeedNode {
  Eigen::AlignedBox3d box;
  std::int32_t left = -1, right = -1;  // children; -1 for a leaf
  std::uint32_t first = 0, count = 0;
};

class SeedGrid {
 public:
  SeedGrid(const Part& part, const ClosestPointOptions& options);

  const std::vector<SeedCell>& cells() const { return cells_; }
  const std::vector<CellBounds>& bounds() const { return bounds_; }  // parallel to cells()
  const std::vector<SeedNode>& nodes() const { return nodes_; }  // nodes_[0] is the root
  const std::vector<TrimSegment>& trim_segments() const { return segments_; }
  // The surface over cell k in Bezier form (one polynomial, cheap to
  // evaluate), or null when the cell crosses a knot (faces with more spans
  // than max_cells are divided uniformly) and must be evaluated as a NURBS.
  const BezierPatch* patch(std::size_t k) const { return patches_[k] ? &*patches_[k] : nullptr; }

  // Index of the cell of `face` whose box contains (u,v) (clamped to the
  // domain), or -1 when that cell was trimmed away.
  int cell_at(std::size_t face, const Eigen::Vector2d& uv) const;

 private:
  struct FaceCells {
    std::vector<double> breaks_u, breaks_v;  // cell boundaries
    std::vector<std::int32_t> index;         // (i * cells_v + j) -> cell or -1
  };
  void add_face(const Part& part, std::size_t face, const ClosestPointOptions& options);
  std::int32_t build_tree(std::vector<std::uint32_t>& order, std::uint32_t first,
                          std::uint32_t count);

  std::vector<SeedCell> cells_;
  std::vector<CellBounds> bounds_;
  std::vector<SeedNode> nodes_;
  std::vector<TrimSegment> segments_;
  std::vector<FaceCells> faces_;
  std::vector<std::optional<BezierPatch>> patches_;  // parallel to cells_
};

// Cell boundaries along one direction: every knot span cut into equal parts
// (see ClosestPointOptions), or a uniform division when there are too many
// spans. Exposed for tests.
std::vector<double> seed_breaks(const std::vector<double>& knots, double lo, double hi,
                                const ClosestPointOptions& options);

}  // namespace furrow
