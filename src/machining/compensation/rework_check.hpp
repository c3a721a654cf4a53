#pragma once
// A rework program checked before it is written (docs/compensation.md
// "Rework"), what is checked being the program read back:
//
// 1. Cutting: z-maps of the rework program and of the compensated full
//    program over the rework's tips (plus a cutter radius), at a fifteenth
//    of the cutter radius as the full program's own check
//    (zmap_check.hpp). Every node the rework cuts must be cut by the full
//    program too and no deeper than it by more than `tolerance` (1 um and
//    the rounding of both programs' written coordinates). The full program
//    is itself checked against the original, so the rework cuts nowhere
//    into the part beyond the offsets that check allows.
// 2. Rapids: the part as machined (a z-map of the original program's cuts
//    and the rework's, over the original's tips plus a cutter radius) and a
//    z-map of the rework's rapids (those with both ends known). A node the
//    rapids cut below the machined height by more than `tolerance`, or,
//    where the programs never cut, below the clearance height, is a rapid
//    cutting material. Rapids from an unknown position (the first, from
//    wherever the machine is) are counted as unchecked.
// Units: mm, part frame.
#include <Eigen/Core>
#include <cstddef>

#include "io/machining/toolpath_file.hpp"
#include "machining/cutter/cutter.hpp"

namespace furrow {

struct ReworkCheck {
  double resolution = 0;          // [mm] node spacing of both checks
  double tolerance = 0;           // [mm]
  std::size_t nodes = 0;          // nodes the rework cuts
  std::size_t deeper = 0;         // of those: deeper than the full program, or not cut by it
  double worst_excess = 0;        // [mm]
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();
  std::size_t rapids = 0, rapids_unchecked = 0;
  std::size_t rapid_nodes_cut = 0;  // nodes a rapid cuts into material
  double worst_rapid_depth = 0;   // [mm]
  Eigen::Vector3d worst_rapid = Eigen::Vector3d::Zero();
  int worst_rapid_line = 0;       // line of the rework program's rapid cutting deepest
  bool safe() const { return deeper == 0 && rapid_nodes_cut == 0; }
};

// `rework`, `full` and `original` as read back; `clearance` [mm].
ReworkCheck check_rework(const Cutter& cutter, const Toolpath& original, const Toolpath& full, const Toolpath& rework,
                         double clearance, double tolerance);

}  // namespace furrow
