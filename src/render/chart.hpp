#pragma once
// Axes, ticks and colour bars drawn into a Drawing (render/drawing.hpp):
// the vector counterpart of plot_canvas.hpp's PlotArea, used by the
// report's figures so each is described once and rendered as SVG or PNG.
//
// A ChartFrame maps data coordinates to pixels inside a rectangle, y up in
// the data (down in pixels). Empty data ranges are widened so nothing
// divides by zero. Tick labels come from ticks.hpp.
#include <Eigen/Core>
#include <string>

#include "render/colour_scale.hpp"
#include "render/drawing.hpp"

namespace furrow {

struct PixelRect {
  double x = 0, y = 0, width = 1, height = 1;  // top-left corner and size [px]
};

class ChartFrame {
 public:
  ChartFrame(PixelRect rect, double x0, double x1, double y0, double y1);
  Eigen::Vector2d to_pixel(double x, double y) const;
  Eigen::Vector2d to_pixel(const Eigen::Vector2d& p) const { return to_pixel(p.x(), p.y()); }
  const PixelRect& rect() const { return rect_; }
  double x0() const { return x0_; }
  double x1() const { return x1_; }
  double y0() const { return y0_; }
  double y1() const { return y1_; }
  // Frame, optional grid, ticks with labels, axis labels.
  void draw_axes(Drawing& d, const std::string& x_label, const std::string& y_label, bool grid = true) const;

 private:
  PixelRect rect_;
  double x0_, x1_, y0_, y1_;
};

// Equal-aspect window: [x0,x1] x [y0,y1] widened so one data unit is the
// same length in x and y (for maps).
ChartFrame equal_aspect_frame(PixelRect rect, double x0, double x1, double y0, double y1);

// Vertical colour bar of a deviation scale labelled in micrometres (`label`
// above it), the tolerance limits marked with black ticks "+tol"/"-tol".
void draw_colour_bar(Drawing& d, PixelRect bar, const DeviationScale& scale, double lower_tolerance,
                     double upper_tolerance, const std::string& label);

}  // namespace furrow
