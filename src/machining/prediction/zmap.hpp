#pragma once
// Z-map simulation of a whole 3-axis tool path (docs/architecture.md "Machining error
// between contact points", predictor 2).
//
// A height grid over the part's xy extent: node (i, j) at (x0 + i c, y0 + j c)
// holds the lowest height any cutting move reached above it (+infinity: never
// cut). Every move lowers the nodes under its shadow to its swept lower
// envelope (swept_envelope.hpp: the ball in closed form per node, the flat
// end mill exactly, the bull-nose by a bracketed convex minimisation along
// the move). Each node also remembers which move cut it lowest.
//
// Why the move index: a grid stores heights only at nodes, and interpolating
// between nodes rounds every cusp (a scallop's ridge, a gouge's rim) by up to
// its slope times half a cell. height_at() instead starts from the moves that
// own the four nodes around the point and follows each one's pass (the moves
// joined end to end) to the lowest position above the point; the result is
// the exact swept envelope wherever the lowest pass at the point is also
// lowest at one of those four nodes, however short the moves are (true
// except for features narrower than a cell, e.g. a pass whose whole shadow
// falls between nodes). Within one cell of the swept region's boundary the
// four nodes need not all be cut and the point may be reached by a move none
// of them saw: near_boundary() says where that can happen, so that callers
// can report it instead of trusting the number.
// interpolated_height_at() is the plain bilinear z-map for comparison.
//
// Parallel with OpenMP over bands of rows; within a band the moves are
// applied in path order. A node update is a min (ties keep the earlier
// move), so heights and owners do not depend on the thread count.
// Units: millimetres, part frame, tool axis +z; moves are tool-tip segments.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "geometry/part.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/prediction/swept_envelope.hpp"

namespace furrow {

struct ZMapMove {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // tip [mm]
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  int pass = 0;  // index of the pass in the tool path
  int step = 0;  // index of the move within its pass
};

// The cutting moves (G1 segments) of a tip path, pass by pass.
std::vector<ZMapMove> moves_from_toolpath(const Toolpath& path);

// Default node spacing [mm]: a tenth of the flat-surface side step whose
// ball scallop equals `tolerance` (w = 2 sqrt(2 r e - e^2), r the corner
// radius, the shank radius for a flat end mill), rounded to the nearest
// 1, 2 or 5 x 10^k: the scallop between passes spans ten nodes or more.
// Ball 6 mm, tolerance 0.01 mm: 0.05 mm.
double default_zmap_resolution(const Cutter& cutter, double tolerance);

struct ZMapOptions {
  EnvelopeOptions envelope;
  int band_rows = 8;                    // rows per parallel work item
  std::size_t max_nodes = 200'000'000;  // refuse larger grids (12 bytes per node)
};

class ZMap {
 public:
  // Nodes from extent.min() in steps of `cell` until extent.max() is covered.
  // Throws InputError when cell is not positive and finite, the extent is
  // empty, or the grid would exceed max_nodes.
  ZMap(const Eigen::AlignedBox2d& extent, double cell, const ZMapOptions& options = {});

  // Applies the moves (may be called again with more moves; move indices
  // continue). The cutter must outlive the z-map. `progress(done, total)`
  // is called from one thread now and then (may be empty).
  void cut(const Cutter& cutter, const std::vector<ZMapMove>& moves,
           const std::function<void(std::size_t, std::size_t)>& progress = {});

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  double x(int i) const { return x0_ + i * cell_; }
  double y(int j) const { return y0_ + j * cell_; }
  std::size_t node_count() const { return heights_.size(); }
  double node_height(int i, int j) const { return heights_[index(i, j)]; }
  // Index of the move that cut node (i, j) lowest; -1 when never cut.
  std::int32_t node_owner(int i, int j) const { return owners_[index(i, j)]; }
  std::size_t cut_node_count() const;
  const std::vector<ZMapMove>& moves() const { return moves_; }
  // Bounds of the machined surface, for searches that must know where it
  // can be (normal_error.hpp floor and shadow): the lowest tip of any move
  // (+infinity before the first cut), and the box of every move's shadow.
  double lowest_tip() const { return lowest_tip_; }
  const Eigen::AlignedBox2d& shadow_box() const { return shadow_; }

  // Machined height at any (x, y): the lowest exact envelope of the passes
  // through the moves owning the four surrounding nodes; +infinity when none
  // of them reaches.
  double height_at(double x, double y) const;
  // True when the nodes within one cell of (x, y) (in x and in y) are some
  // cut and some never cut, or (x, y) lies off the grid: (x, y) is within a
  // cell of the swept region's boundary as the grid resolves it, where
  // height_at() depends on the resolution.
  bool near_boundary(double x, double y) const;
  // Bilinear interpolation of the node heights; +infinity when a node is
  // uncut or (x, y) is off the grid.
  double interpolated_height_at(double x, double y) const;

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }
  // Lowest envelope at (x, y) along the pass from move `start`; [lo, hi]:
  // the moves the walk went down through.
  double lowest_along_pass(std::int32_t start, double x, double y, std::int32_t& lo, std::int32_t& hi) const;

  ZMapOptions options_;
  double x0_ = 0, y0_ = 0, cell_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> heights_;
  std::vector<std::int32_t> owners_;
  std::vector<ZMapMove> moves_;
  std::vector<SweptEnvelope> envelopes_;
  double lowest_tip_ = std::numeric_limits<double>::infinity();
  Eigen::AlignedBox2d shadow_;
};

// The part's xy extent: the box of its faces' control nets (which contains
// every face).
Eigen::AlignedBox2d part_xy_extent(const Part& part);

}  // namespace furrow
