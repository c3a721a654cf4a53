#pragma once
// The compensated program cut against the original with a z-map
// (docs/compensation.md "Safety"): what is checked is what is written, the
// program read back, so rounding and the writer's choices are inside.
//
// Node by node of a z-map over where tips moved (plus a cutter radius), at
// a fifteenth of the cutter's radius: a node the compensated program cuts
// lower than the original by more than the offset of the move that cuts it
// (the larger of its two ends', as applied, divided by the original
// machined surface's n_z there: a move of d along the normal lowers the
// surface at a fixed (x, y) by d / n_z) plus `tolerance` (1 um and the
// written rounding) is a gouge the compensation would add. Nodes at the
// rim of the swept region (a neighbour uncut) and where the machined
// surface is steeper than n_z = 0.2 are not judged (counted): there a
// lateral move of a micrometre changes the height by tens. A gouge
// narrower than a cell can fall between nodes.
//
// Each move the check blames is listed (its pass and step in the original
// path, so that the caller can reduce its ends' offsets: the clip-back of
// docs/compensation.md), when the written program has the original's
// points (arcs are split through the same points); else none is, and the
// offset allowed is the largest anywhere.
// Units: mm, part frame.
#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

#include "io/machining/toolpath_file.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/cutter/path_tools.hpp"

namespace furrow {

struct CompensationGougeCheck {
  double resolution = 0;        // z-map node spacing [mm]
  double tolerance = 0;         // allowed beyond the offset [mm]
  std::size_t nodes = 0;        // nodes both programs cut
  std::size_t not_judged = 0;   // of those: at the rim or too steep
  std::size_t deeper = 0;       // nodes beyond the allowance
  double worst_excess = 0;      // [mm] the largest excess (0 when none)
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();  // where [mm]
  int worst_line = 0;           // line of the compensated program cutting it there
  // (pass, step) of every move that cuts a node beyond the allowance,
  // sorted, each once; empty when the points differ (see above).
  std::vector<std::pair<std::size_t, std::size_t>> blamed;
  bool safe() const { return deeper == 0; }
};

// `written` is the compensated program read back, `offset` the offsets its
// tips were moved by, `half_unit` [mm] half a unit of the written
// coordinates' last decimal.
CompensationGougeCheck check_compensation_zmap(const Cutter& cutter, const Toolpath& original,
                                               const Toolpath& written, const PathOffset& offset, double half_unit);

// A program that changes tools: each tool's passes checked as above against
// the same tool's passes of the original, with that tool (its own z-maps,
// at a fifteenth of its radius), and the results summed (nodes, not judged,
// deeper), the worst the deepest of all, the blamed moves named by their
// pass in the whole path and `resolution` the finest used. Per tool rather
// than the part as all tools leave it: a node one tool's compensation
// lowers beyond its offset is refused even where another tool cut lower
// (conservative, as a check before cutting should be). Precondition: the
// written program has the original's passes (the rewriters keep them),
// tools.of_pass covers them. One cutter: exactly the check above.
CompensationGougeCheck check_compensation_zmap(const PathTools& tools, const Toolpath& original,
                                               const Toolpath& written, const PathOffset& offset, double half_unit);

}  // namespace furrow
