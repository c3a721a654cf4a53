#pragma once
// The report's figures as drawing descriptions (render/drawing.hpp): each
// figure is described once and rendered as SVG (inline in the HTML) or PNG
// (figure files, large maps) by the back ends, never drawn twice.
//
// Deviations are in millimetres in, micrometres on the axes and colour bars
// (what a QA engineer reads; the SVG writes "µm"). Every figure is
// deterministic: the same data give the same drawing.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/drawing.hpp"

namespace furrow {

// A value at a 2-D position of the figure's own frame (part top view x-y in
// mm, or a face's (u,v)).
struct MapPoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double value = 0;      // deviation [mm]
  bool flagged = false;  // drawn with a black ring (outlier / out of tolerance)
  std::string label;     // point id; written next to the point with its value when out of tolerance
  bool out_of_tolerance = false;
};

// At most this many out-of-tolerance points are labelled in one map (the
// largest |value| first; the figure says how many were left out): beyond
// that the labels would hide the map.
constexpr std::size_t kMaxMapLabels = 60;

// A polyline drawn in thin grey under the points (face outlines, region
// borders) in the same frame.
using Outline = std::vector<Eigen::Vector2d>;

struct ToleranceLimits {
  double lower = -0.05, upper = 0.05;  // [mm], lower <= 0 <= upper
};

// Points coloured by value on a diverging scale with a colour bar in µm and
// the tolerance limits marked. `equal_aspect` for geometric maps. The scale
// runs over ±`range` [mm] when it is given (> 0), so that two maps compared
// side by side share their colours; else over the largest |value| and limit. Each
// out-of-tolerance label is an SVG <text class="oot-label" data-id=ID
// data-value=UM> reading "ID +61.3 µm" (value in µm, one decimal).
Drawing deviation_map_drawing(const std::string& title, const std::vector<MapPoint>& points,
                              const std::vector<Outline>& outlines, const ToleranceLimits& tolerance,
                              const std::string& x_label, const std::string& y_label, bool equal_aspect,
                              double range = 0);

// Histogram of deviations (µm) with the tolerance limits as vertical lines.
Drawing histogram_drawing(const std::string& title, const std::vector<double>& values,
                                         const ToleranceLimits& tolerance);

// The same from bins counted elsewhere (a scan's histogram, counted over
// every point when it was compared): `edges` [mm] increasing, one count per
// bin; the axis spans the bins and the limits. Each bar carries its count
// (class "bin", data-count).
Drawing histogram_bins_drawing(const std::string& title, const std::vector<double>& edges,
                               const std::vector<std::size_t>& counts, const ToleranceLimits& tolerance);

// Scatter of measured (y) against predicted (x) values in µm, with the line
// y = x and, when `sigma` is given per point, vertical 1-sigma bars.
Drawing scatter_drawing(const std::string& title, const std::vector<double>& predicted,
                                       const std::vector<double>& measured, const std::vector<double>& sigma);

// A labelled marker figure: each item is a filled disc (or, when `outline`
// has >= 3 points, a filled polygon) in the status colour, with its label; a
// legend lists the statuses that occur. For gouge sites on the top view.
struct StatusItem {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Outline outline;        // optional extent in the figure frame
  std::string label;      // drawn next to the marker
  std::string status;     // e.g. "CONFIRMED" (colour from status_colour)
};
Drawing status_map_drawing(const std::string& title, const std::vector<StatusItem>& items,
                                          const std::vector<Outline>& outlines,
                                          const std::vector<Eigen::Vector2d>& background_points,
                                          const std::string& x_label, const std::string& y_label);

}  // namespace furrow
