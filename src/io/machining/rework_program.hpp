#pragma once
// A rework program written from kept stretches of a compensated path
// (docs/compensation.md "Rework"): the original program's header (every
// line before its first motion: comments, units, tool, spindle, coolant)
// and its end (every line after its last motion), and between them, per
// stretch, a rapid to the clearance height over the stretch's start, a
// plunge at the stretch's feed down to it, the stretch's cutting moves and
// a rapid retract straight up. G-code (G0/G1 with F) or APT CL data
// (RAPID GOTO/, FEDRAT/MMPM, GOTO/), in the original's line endings.
//
// Lines in the middle of the original that are not motions (a feed or
// spindle change between passes) are not carried: each plunge and each
// change of feed writes its F (FEDRAT/) again. The coordinates are written
// in millimetres in the part frame with `decimals` decimals; the caller
// reads the program back and refuses it if the header sets other units or
// a work offset (the coordinates would not mean what was written).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/machining/toolpath_file.hpp"

namespace furrow {

// One stretch: tips [mm, part frame] cut in order, and the feed [mm/min]
// of the move ending at each tip (feeds[0], the plunge's, is the first
// move's). At least 2 tips.
struct ReworkStretch {
  std::vector<Eigen::Vector3d> tips;
  std::vector<double> feeds;
  int first_line = 0, last_line = 0;  // source lines of the original moves it re-cuts
};

enum class ReworkFormat { gcode, apt };

// `original_text` is the program `original` was read from (its lines give
// the header and the end). `clearance` [mm] the height of every rapid.
// Precondition: at least one stretch.
std::string write_rework_program(const std::string& original_text, const Toolpath& original,
                                 const std::vector<ReworkStretch>& stretches, double clearance, int decimals,
                                 ReworkFormat format);

}  // namespace furrow
