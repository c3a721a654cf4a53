#pragma once
// A G-code program written again with some tool tips moved
// (docs/compensation.md "Writing the program"): every byte of the original
// is kept (comments, N numbers, feeds, spindle, coolant, tool changes,
// rapids, G10 work offsets, modal words, line endings) except the X Y Z
// words of the lines whose tips moved.
//
// The moved tips are given as the reader's passes (parse_gcode with the same
// read options): tips[p][i] is the new position of passes[p].points[i], in
// the part frame [mm]. Each line then ends where its last point now is:
//   - a word is rewritten only when its new value, written with the
//     program's decimals, differs from the value written; the value is in
//     the line's own units (G20/G21), mode (G90, or G91 from where the
//     rewritten program is) and work system (the inverse of the reader's
//     G54-G59.3 shift);
//   - an axis word the line omitted is added when the line must end
//     elsewhere on that axis than where the rewritten program already is
//     (this includes a line after a moved one that relied on the modal
//     position: it still ends where it did);
//   - a zero-length cutting line (no point of its own) stays with the tool;
//   - the first point of a pass is the end of the line before the pass's
//     first cut (the rapid down to it): when it moved, that line moves;
//   - an arc (G2/G3) whose start or any point moved becomes G1 segments
//     through the moved points of its flattening, so its chords stay within
//     the read option's arc tolerance of the moved arc; the first segment
//     keeps the line (N number, F, comments; I J K R dropped, G2/G3 turned
//     G1), the others are "G1 X Y Z" lines. A later line that relied on the
//     modal G2/G3 gets its G word written.
// Decimals: the most any X Y Z word of the file has; 4 when that is fewer
// than 3 (a program written to whole units would lose the correction).
// An added word needs its axis's work offset: a file that does not give it
// (see gcode_work_offsets.hpp) is an InputError naming the line.
#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "io/machining/program_rewrite.hpp"
#include "io/machining/toolpath_file.hpp"

namespace furrow {

// The record of what was changed (program_rewrite.hpp); lines_removed
// stays 0: a G-code line is never dropped.
using GcodeRewrite = ProgramRewrite;

// Throws InputError naming `name` when `tips` does not have the shape of the
// passes parse_gcode(text, name, options) reads, or when a moved position
// cannot be written (see above).
GcodeRewrite rewrite_gcode(const std::string& text, const std::string& name, const ToolpathReadOptions& options,
                           const std::vector<std::vector<Eigen::Vector3d>>& tips);

}  // namespace furrow
