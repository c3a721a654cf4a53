#pragma once
// The report's figures as PNG bytes (OpenCV drawing stays inside the .cpp).
//
// Deviations are in millimetres in, micrometres on the axes and colour bars
// (what a QA engineer reads). Every figure is deterministic: the same data
// give the same bytes.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace furrow {

// A value at a 2-D position of the figure's own frame (part top view x-y in
// mm, or a face's (u,v)).
struct MapPoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double value = 0;      // deviation [mm]
  bool flagged = false;  // drawn with a black ring (outlier / out of tolerance)
};

// A polyline drawn in thin grey under the points (face outlines, region
// borders) in the same frame.
using Outline = std::vector<Eigen::Vector2d>;

struct ToleranceLimits {
  double lower = -0.05, upper = 0.05;  // [mm], lower <= 0 <= upper
};

// Points coloured by value on a diverging scale with a colour bar in µm and
// the tolerance limits marked. `equal_aspect` for geometric maps.
std::vector<unsigned char> deviation_map_png(const std::string& title, const std::vector<MapPoint>& points,
                                             const std::vector<Outline>& outlines,
                                             const ToleranceLimits& tolerance, const std::string& x_label,
                                             const std::string& y_label, bool equal_aspect);

// Histogram of deviations (µm) with the tolerance limits as vertical lines.
std::vector<unsigned char> histogram_png(const std::string& title, const std::vector<double>& values,
                                         const ToleranceLimits& tolerance);

// Scatter of measured (y) against predicted (x) values in µm, with the line
// y = x and, when `sigma` is given per point, vertical 1-sigma bars.
std::vector<unsigned char> scatter_png(const std::string& title, const std::vector<double>& predicted,
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
std::vector<unsigned char> status_map_png(const std::string& title, const std::vector<StatusItem>& items,
                                          const std::vector<Outline>& outlines,
                                          const std::vector<Eigen::Vector2d>& background_points,
                                          const std::string& x_label, const std::string& y_label);

}  // namespace furrow
