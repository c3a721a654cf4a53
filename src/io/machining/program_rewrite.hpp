#pragma once
// What writing a program again with moved tool tips changed
// (docs/compensation.md "Writing the program"): the record both writers
// return, the G-code one (gcode_rewrite.hpp) and the APT CL one
// (apt_rewrite.hpp), so that a caller reports either the same way.
#include <cstddef>
#include <string>

namespace furrow {

struct ProgramRewrite {
  std::string text;                // the program written again
  int decimals = 4;                // of the written coordinates
  double unit_mm = 1;              // mm per program unit, the coarsest where units mix (inch: 25.4)
  std::size_t lines_moved = 0;     // lines (statements) whose coordinates changed or were added
  std::size_t words_rewritten = 0; // coordinate values written again
  std::size_t words_added = 0;     // coordinate values the line did not have
  std::size_t arcs_split = 0;      // arcs written as straight segments
  std::size_t lines_inserted = 0;  // segment lines after the first of each split arc
  std::size_t lines_removed = 0;   // lines dropped (APT: the CIRCLE/ of a split arc)
};

}  // namespace furrow
