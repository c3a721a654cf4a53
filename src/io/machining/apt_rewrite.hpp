#pragma once
// An APT CL file written again with some tool tips moved
// (docs/compensation.md "Writing the program"): the same idea as
// gcode_rewrite.hpp. Every byte of the original is kept (headers, PPRINT,
// CUTTER, FEDRAT, SPINDL, comments, RAPID, continuation lines, spacing,
// line endings, a byte-order mark) except the coordinates of the motion
// statements whose tips moved.
//
// The moved tips are given as parse_apt's passes (same read options):
// tips[p][i] is the new position of passes[p].points[i], in the part frame
// [mm]. Each statement then ends where its last point now is:
//   - GOTO/ and FROM/: a coordinate (the first three values) is rewritten
//     only when its new value, written with the file's decimals in the
//     statement's units (UNITS/), differs from the value written; the other
//     values (a tool axis i,j,k) and everything around them stay;
//   - GODLTA/ (incremental): written from where the rewritten program then
//     is, so it still ends where its tip now is; a GODLTA/dz that must move
//     in x or y as well becomes GODLTA/dx,dy,dz (counted as words added);
//   - a zero-length cutting move stays with the tool; a statement without
//     a moved point ends where it did;
//   - the first point of a pass is where the statement before the pass's
//     first cut (FROM/, a RAPID GOTO/ or GODLTA/) left the tool: when it
//     moved, that statement moves;
//   - an arc (CIRCLE/ + its GOTO/, or TLON,GOFWD/) whose start or any point
//     moved becomes GOTO/ statements through the moved points of the
//     reader's flattening, so its chords stay within the read option's arc
//     tolerance of the moved arc: the CIRCLE/ statement is dropped, the
//     GOTO/ keeps its line (its first three values become the first point;
//     a comment and an i,j,k stay), and one "GOTO/x,y,z" line per further
//     point is inserted after it (with the file's separator and the same
//     i,j,k). A TLON,GOFWD/ statement is replaced by those GOTO/ lines; the
//     INDIRV/ before it stays (it moves nothing). An arc that did not move
//     is kept as it is.
// Decimals: the most any coordinate of a GOTO/, FROM/ or GODLTA/ has; 4
// when that is fewer than 3 (a file written to whole units would lose the
// correction). Numbers are written "%.*f" (never "-0.0000").
// Throws InputError naming `name` when `tips` does not have the shape of
// parse_apt's passes, when a moved pass start has no positioning statement
// before it, or when a value to rewrite is split over a continuation line.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/machining/program_rewrite.hpp"
#include "io/machining/toolpath_file.hpp"

namespace furrow {

ProgramRewrite rewrite_apt(const std::string& text, const std::string& name, const ToolpathReadOptions& options,
                           const std::vector<std::vector<Eigen::Vector3d>>& tips);

}  // namespace furrow
