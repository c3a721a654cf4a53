#pragma once
// Borders of regions as closed loops along cell edges ("crack" boundaries).
//
// A region is a set of whole cells, so its exact border runs along cell
// edges. Loops are traced on the grid nodes: node (a, b) is the corner at
// u = u0 + a du, v = v0 + b dv (0 <= a <= nu, 0 <= b <= nv). Every loop keeps
// its region on the left (u to the right, v up), so an outer border runs
// counter-clockwise (positive area) and a hole clockwise. Where two cells of
// a region touch only at a corner the tracer turns left, keeping the loops of
// 4-connected pieces apart, so loops never cross; a loop may touch another
// loop of the same region at a corner node.
//
// Why our own tracer and not cv::findContours: findContours returns the
// centres of border pixels, half a cell inside the region; converting them
// back to cell edges is exactly this walk. With crack loops the even-odd rule
// over all loops of a region reproduces its cells exactly (a cell centre is
// never on a loop), which is what region_at relies on.
#include <Eigen/Core>
#include <vector>

#include "partition/region_labels.hpp"

namespace furrow {

struct NodeLoop {
  std::vector<Eigen::Vector2i> nodes;  // closed: the first node is not repeated
  bool hole = false;                   // clockwise: a hole in its region
  long long twice_area = 0;            // signed shoelace area in cells, times 2
};

// Per label, its loops: outer borders first, then holes, each in tracing
// order starting from the lowest node. Every node of the border is listed
// (straight runs included); callers simplify.
std::vector<std::vector<NodeLoop>> trace_region_boundaries(const RegionLabels& labels);

}  // namespace furrow
