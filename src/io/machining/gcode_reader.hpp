#pragma once
// The G-code reader: the dialect Fanuc-style CAM posts (Mastercam, Fusion 360,
// and the like) write for 3-axis milling, read into tool-tip passes
// (docs/formats.md "Tool paths").
//
// Positions are tool tips in millimetres in the part frame; the tool axis is
// +z. A pass is the polyline the tool follows while cutting (G1, G2, G3);
// a rapid (G0), G28 or G53 ends the pass and is not cut. Every rapid is
// also kept in Toolpath::rapids with its line (toolpath_file.hpp RapidMove):
// a G0 whose start and end are both known in the part frame as a segment,
// G28, G53 and a G0 from or to a position with an unknown axis as an
// unchecked move without positions.
//
// Read and honoured: G0 G1 G2 G3 (arcs flattened by gcode_arc.hpp, chord sag
// ToolpathReadOptions::arc_tolerance), planes G17 G18 G19 with centre words
// I J (G17), I K (G18), J K (G19) or a signed R (R < 0: the long arc), G20
// inch / G21 mm, G90 / G91 absolute / incremental coordinates, G91.1
// incremental arc centres (the default). G28 (return to home, as posts write
// `G28 G91 Z0.`) and G53 (a rapid in machine coordinates, whatever the motion
// mode, as on Fanuc controls) end the pass
// and make the named axes (all, for a bare G28) unknown until an absolute
// position is given again: the machine's home is not in the part frame.
// Work systems G54-G59.3 and their offsets G10 L2 / G10 L20 Pn (P0 the
// active one), as LinuxCNC reads them (gcode_work_offsets.hpp): positions
// come back in the part frame, the system in effect at the first move; a
// coordinate in a system whose offset from it the file does not give is an
// error. G43 H: the
// positions are taken as tool tips, i.e. the length offset is assumed to be
// the one the tool was measured with; G43 is listed in `ignored`.
//
// Tool changes: `T n` selects tool n (a whole number), M6 loads the
// selected tool (a T on the M6 line, in either order, is the one loaded).
// The change ends the pass and, since the spindle travels to the change
// position in machine coordinates, makes every axis unknown (an unchecked
// rapid, as G28) until the program positions the new tool again. Every
// pass and rapid carries the tool number loaded (0 before the first M6),
// and Toolpath::tool_changes lists the changes: which cutter that number
// is comes from a tool table (machining/cutter/path_tools.hpp). `T0 M6`
// empties the spindle: a cut after it is refused.
//
// Ignored and listed with their line numbers in `ignored` (no geometric
// effect on tool tips): M (other than M6) S H D words, G40 G43 G49 G61 G64
// G80 G94.
//
// Refused, naming the line (dropping them would predict the wrong part):
// G90.1 (absolute arc centres), cutter compensation G41/G42, canned cycles
// G73 G74 G76 G81-G89, G53 with G1/G2/G3 on its line, G10 other than L2 and
// L20 (L1 L10 L11 tool tables), G10 with R (rotation) or a move on its
// line, G92 G92.1-G92.3 G52, rotary axes A B C,
// any other G code or letter, arc errors (gcode_arc.hpp), I J K R outside an
// arc or in the wrong plane, an arc with both R and I J K.
//
// `N` numbers, `O` numbers, `( )` and `;` comments, `%` lines, words without
// spaces (`G90G20M03S2000`, `G1X1.Y2.`) and numbers like `1.` or `.5` are
// read as written. Mode and unit words apply to the coordinates of their own
// line, in any word order.
#include <string>
#include <vector>

#include "io/machining/toolpath_file.hpp"

namespace furrow {

// One line that moves the tool in the part frame (G0 G1 G2 G3 with a
// coordinate or an arc word; not G28, G53 or G10), as read: what a writer
// that puts a moved position back into the program's own words needs
// (io/machining/gcode_rewrite.hpp). A word value v on an axis given here
// lands at v * scale + shift[axis] (absolute) or at start + v * scale
// (incremental).
struct GcodeMotionBlock {
  int line = 0;       // source line (1-based)
  int motion = 0;     // 0 rapid, 1 linear, 2 clockwise arc, 3 counter-clockwise arc
  bool motion_word = false;  // the line has its own G0-G3 (else the mode is modal)
  bool axis_given[3] = {false, false, false};
  bool start_known[3] = {false, false, false};  // per axis, before the line
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // tip before the line [mm]; unknown axes 0
  Eigen::Vector3d end = Eigen::Vector3d::Zero();    // tip after it [mm]; unknown axes 0
  bool absolute = true;                             // G90
  double scale = 1;                                 // mm per program unit (G20: 25.4)
  double shift[3] = {0, 0, 0};                      // work offset into the part frame [mm]
  bool shift_known[3] = {false, false, false};      // the file gives the shift on that axis
};

// Throws InputError "name:line: what" for anything refused above, and
// "name: no cutting moves" for a file without G1/G2/G3. `blocks`, when
// given, receives every motion line in file order.
Toolpath parse_gcode(const std::string& text, const std::string& name, const ToolpathReadOptions& options = ToolpathReadOptions{},
                     std::vector<GcodeMotionBlock>* blocks = nullptr);

}  // namespace furrow
