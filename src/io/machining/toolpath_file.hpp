#pragma once
// Tool paths: a G-code subset, APT CL data and CSV files (docs/architecture.md "Files").
//
// A path is a list of passes; a pass is a polyline the tool follows while
// cutting (G1, G2, G3). Rapid moves (G0) separate passes and are not cut;
// they are kept beside the passes (Toolpath::rapids, RapidMove below) so
// that the cutter's travel through them can be checked against the part
// (machining/prediction/rapid_check.hpp). Positions are millimetres in the
// part frame; the tool axis is +z.
//
// G-code: the dialect of Fanuc-style CAM posts, arcs flattened to polylines;
// what is read, ignored and refused is listed in io/machining/gcode_reader.hpp.
//
// CSV: `x,y,z` tool tips or `x,y,z,nx,ny,nz` contact points with their
// surface normals, one point per line, an optional header line naming the
// columns (any order; an optional `pass` column numbers the passes; optional
// `u`, `v` and `face` columns give each contact point's face and surface
// parameters, so it need not be projected back onto the part; other columns
// are an error), '#' comments, and a blank line between passes when there is
// no `pass` column.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/machining/tool_file.hpp"

namespace furrow {

enum class ToolpathKind { tool_tips, contact_points };

struct ToolpathPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // tip, or contact point [mm]
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();    // unit; contact points only
  double feed = 0;                                     // mm/min, 0 when not given
  int line = 0;                                        // source line (1-based)
  // Contact points written by `furrow toolpath` also say where they lie on
  // the part: optional CSV columns u, v (both or neither) and face (a name).
  bool has_uv = false;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  std::string face;  // empty when the file has no face column
};

struct ToolpathPass {
  std::vector<ToolpathPoint> points;  // at least 2
  // The tool number in the spindle while the pass is cut (G-code `T n M6`);
  // 0 when the file loads no tool (CSV, APT, G-code before any tool change).
  int tool = 0;
};

// One rapid move, in file order, as any tool-path reader records it (G-code
// G0, G28, G53; an APT RAPID GOTO): a straight tool-tip segment at rapid
// feed that is not cut but must not touch the part. `known` says whether
// both ends are positions in the part frame. It is false for a move through
// or to machine coordinates (G28 home, G53) and for a move that starts or
// ends with an axis not yet known (the first rapid of a program, which
// starts wherever the machine is, or one after G28): such a move is counted
// as unchecked and its positions are left zero, never guessed.
// Controls move the axes of a rapid together in a straight line only on
// some machines (others move each axis at its own top speed, a dog-leg):
// the straight segment is what this records and what is checked.
// CSV tool paths have no rapids.
struct RapidMove {
  int line = 0;        // source line (1-based)
  bool known = false;  // both ends in the part frame
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // tip [mm], only when known
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  int tool = 0;  // tool number in the spindle, as ToolpathPass::tool
};

// A tool change (G-code M6): the tool number loaded and the line.
struct ToolChange {
  int line = 0;
  int tool = 0;
};

struct IgnoredWord {
  int line = 0;
  std::string word;
};

struct Toolpath {
  ToolpathKind kind = ToolpathKind::tool_tips;
  std::vector<ToolpathPass> passes;
  std::vector<RapidMove> rapids;     // non-cutting moves, in file order (see RapidMove)
  std::vector<IgnoredWord> ignored;  // G-code words read but without geometric effect
  std::vector<ToolChange> tool_changes;  // in file order (G-code only)
  std::string source;                // file name, for reports
  // The cutter the file itself defines first (APT `CUTTER/`,
  // io/machining/apt_reader.hpp), and the line that defines it; empty for G-code and CSV.
  std::optional<ToolSpec> tool;
  int tool_line = 0;
  // Every cutter the file defines (APT), in order of definition: a pass or
  // rapid with tool number n (>= 1) is cut or travelled with
  // defined_tools[n - 1]. Empty for G-code and CSV, whose numbers name
  // tools of a tool table.
  struct DefinedTool {
    ToolSpec tool;
    int line = 0;
  };
  std::vector<DefinedTool> defined_tools;

  std::size_t point_count() const;
  std::size_t move_count() const;  // cutting segments
};

struct ToolpathReadOptions {
  // Units of CSV coordinates, and of G-code before any G20/G21 ("mm"|"inch").
  std::string units = "mm";
  // G-code arcs (G2/G3) become polylines whose chords stay within this
  // distance of the arc [mm] (io/machining/gcode_arc.hpp): 0.1 µm, the resolution the
  // reports print.
  double arc_tolerance = 1e-4;
};

// Dispatches on the extension: .csv / .txt as CSV, .cl / .apt / .cls as APT
// CL data (io/machining/apt_reader.hpp), anything else as G-code.
Toolpath read_toolpath(const std::string& path, const ToolpathReadOptions& options = {});
Toolpath parse_toolpath_csv(const std::string& text, const std::string& name,
                            const ToolpathReadOptions& options = {});

// G-code for tool tips: a header comment, G21 G90, per pass a rapid to a
// safe height above the first point, down, G1 moves, back up to the safe
// height; ends with M30. Coordinates with 4 decimals (0.1 µm).
std::string toolpath_to_gcode(const Toolpath& path, double safe_z, double feed,
                              const std::string& header_comment);

}  // namespace furrow

// parse_gcode and parse_apt, declared with their dialects; need the types above.
#include "io/machining/apt_reader.hpp"    // IWYU pragma: export
#include "io/machining/gcode_reader.hpp"  // IWYU pragma: export
