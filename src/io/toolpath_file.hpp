#pragma once
// Tool paths: a G-code subset and CSV files (docs/architecture.md "Files").
//
// A path is a list of passes; a pass is a polyline the tool follows while
// cutting (G1). Rapid moves (G0) separate passes and are not cut. Positions
// are millimetres in the part frame; the tool axis is +z.
//
// G-code subset: G0/G00, G1/G01, G20 (inch), G21 (mm), G90 (absolute), G91
// (relative), words X Y Z F, N line numbers, comments in parentheses or after
// ';', '%' and O program-number lines. Words that do not change the tool's
// geometry (spindle M3/M4/M5 S, coolant M7/M8/M9, tool change T M6, program
// end M2/M30, plane G17, cancels G40/G49/G80, work offsets G54-G59, G94, G64)
// are ignored and listed with their line numbers in `ignored`. Anything that
// would change the geometry but is not supported (arcs G2/G3, cutter
// compensation G41/G42, length offset G43, rotary axes A B C, arc words I J K
// R, G28 homing, unknown G codes or letters) is an error naming the line:
// silently dropping it would predict the wrong part.
//
// CSV: `x,y,z` tool tips or `x,y,z,nx,ny,nz` contact points with their
// surface normals, one point per line, an optional header line naming the
// columns (any order; an optional `pass` column numbers the passes; optional
// `u`, `v` and `face` columns give each contact point's face and surface
// parameters, so it need not be projected back onto the part; other columns
// are an error), '#' comments, and a blank line between passes when there is
// no `pass` column.
#include <Eigen/Core>
#include <string>
#include <vector>

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
};

struct IgnoredWord {
  int line = 0;
  std::string word;
};

struct Toolpath {
  ToolpathKind kind = ToolpathKind::tool_tips;
  std::vector<ToolpathPass> passes;
  std::vector<IgnoredWord> ignored;  // G-code words read but without geometric effect
  std::string source;                // file name, for reports

  std::size_t point_count() const;
  std::size_t move_count() const;  // cutting segments
};

struct ToolpathReadOptions {
  // Units of CSV coordinates, and of G-code before any G20/G21 ("mm"|"inch").
  std::string units = "mm";
};

// Dispatches on the extension: .csv / .txt as CSV, anything else as G-code.
Toolpath read_toolpath(const std::string& path, const ToolpathReadOptions& options = {});
Toolpath parse_gcode(const std::string& text, const std::string& name,
                     const ToolpathReadOptions& options = {});
Toolpath parse_toolpath_csv(const std::string& text, const std::string& name,
                            const ToolpathReadOptions& options = {});

// G-code for tool tips: a header comment, G21 G90, per pass a rapid to a
// safe height above the first point, down, G1 moves, back up to the safe
// height; ends with M30. Coordinates with 4 decimals (0.1 µm).
std::string toolpath_to_gcode(const Toolpath& path, double safe_z, double feed,
                              const std::string& header_comment);

}  // namespace furrow
