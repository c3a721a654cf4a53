#pragma once
// The APT CL data reader: cutter-location files (.cl, .apt, .cls) as UG/NX
// and CATIA write them for 3-axis milling, read into the same tool-tip passes
// as the G-code reader (docs/formats.md "Tool paths", APT CL data).
//
// Positions are tool tips (the cutter's end point on its axis) in millimetres
// in the part frame; the tool axis is +z. A pass is what the tool cuts
// between rapids: a GOTO after RAPID (RAPID applies to the next motion only),
// FROM (the start point) and the first motion end a pass as G0 does and are
// not cut; a first GOTO from an unknown position is refused.
//
// Honoured: GOTO/x,y,z[,i,j,k] and GODLTA/dx,dy,dz (or /dz along the axis),
// FROM/, RAPID, UNITS/MM|INCHES (applies to what follows; before it
// ToolpathReadOptions::units), FEDRAT/ (per minute in mm or inch: the
// points' feed; per revolution: 0, the spindle speed is the machine's),
// circular arcs flattened by io/machining/gcode_arc.hpp exactly as the G-code reader's:
// CIRCLE/xc,yc,zc,i,j,k,r[,...] followed by the GOTO that ends the arc (NX,
// CATIA; counter-clockwise about i,j,k, which must lie along x, y or z), and
// INDIRV/ + TLON,GOFWD/(CIRCLE/xc,yc,zc,r),ON,(LINE/...) (the arc starts
// along INDIRV and ends where it first meets the line). CUTTER/d, /d,r and
// the 7-parameter /d,r,e,f,a,b,h (and NX's TLDATA/MILL,d,r,l,0,0) define the
// tool, a ball, flat or bull end mill: Toolpath::tool is the first, and
// Toolpath::defined_tools lists each geometry once. One with another
// geometry than the cutter in effect is a tool change: the pass ends, the
// position is unknown until FROM/ or a RAPID GOTO/ (the change is an
// unchecked rapid), and the passes and rapids after it carry its number
// (1 + its index in defined_tools; 0 before the first). The same geometry
// again (posts repeat CUTTER/ per operation) changes nothing.
//
// 3-axis only: a tool axis (TLAXIS/, GOTO's i,j,k, CIRCLE's) must be +z;
// anything tilted is refused naming its line, whatever MULTAX says.
//
// Ignored and listed in Toolpath::ignored (no effect on the cut): PARTNO,
// PPRINT, MACHIN, LOADTL, LOAD, SPINDL, COOLNT, MULTAX, TLAXIS/0,0,1, the
// identity MSYS, TOOL PATH, END-OF-PATH, PAINT, SELCTL, OPSTOP, STOP, END,
// DELAY, SEQNO, TPRINT, DISPLY, OPSKIP, CUTCOM/OFF, CYCLE/OFF. `$$` comments.
// FINI ends the program; any statement after it is refused.
//
// Refused, naming the line: any other major word (INSERT, CUTCOM/ON, CYCLE/
// with a cycle, RETRCT, ORIGIN, ROTABL and the like move or offset the tool in
// ways not in the file), a tapered or otherwise non-cylindrical cutter,
// values that are not finite numbers, missing values, coordinates beyond
// docs/formats.md "Limits", arc errors (gcode_arc.hpp), a CIRCLE not
// followed by its GOTO.
#include <string>

#include "io/machining/toolpath_file.hpp"

namespace furrow {

// Throws InputError "name:line: what" for anything refused above, and
// "name: no cutting moves" for a file without one.
Toolpath parse_apt(const std::string& text, const std::string& name, const ToolpathReadOptions& options = {});

// The tool to cut `path` with: `given` (from --tool or a job, named by
// `given_source`) or else the one the path defines. Throws InputError when
// neither exists, or when both do and differ by more than 0.001 mm in
// diameter or corner radius (naming both sources), since a prediction with
// the other tool would not be the part the file cuts.
ToolSpec tool_for_path(const std::optional<ToolSpec>& given, const std::string& given_source, const Toolpath& path);

}  // namespace furrow
