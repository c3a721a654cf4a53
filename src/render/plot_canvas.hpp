#pragma once
// Drawing helpers for every figure (internal: this header includes OpenCV
// and is included only by the .cpp files that draw figures; it is not
// installed).
//
// A PlotArea maps data coordinates to pixels inside a rectangle of an image,
// y up, and draws the frame, "nice" 1-2-5 ticks and axis labels. Text uses
// OpenCV's Hershey font with anti-aliasing; everything is drawn on white.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "render/chart.hpp"
#include "render/colour_scale.hpp"
#include "render/ticks.hpp"

namespace furrow::plot {

const cv::Scalar kInk(35, 35, 35);
const cv::Scalar kGrid(225, 225, 225);
const cv::Scalar kPaper(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

inline cv::Scalar bgr(const Rgb& c) { return cv::Scalar(c[2], c[1], c[0]); }

// Text helpers: anchor at the left baseline, or centred on a point.
void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.5,
          const cv::Scalar& colour = kInk, int thickness = 1);
void text_centred(cv::Mat& img, const std::string& s, cv::Point centre, double scale = 0.5,
                  const cv::Scalar& colour = kInk, int thickness = 1);
void text_right(cv::Mat& img, const std::string& s, cv::Point right_baseline, double scale = 0.5,
                const cv::Scalar& colour = kInk);
// Vertical text (rotated 90 degrees counter-clockwise) centred on a point.
void text_vertical(cv::Mat& img, const std::string& s, cv::Point centre, double scale = 0.5);

// nice_ticks, tick_label: render/ticks.hpp (shared with the vector figures).

class PlotArea {
 public:
  // `rect` in pixels; x in [x0, x1], y in [y0, y1] (both ranges non-empty:
  // an empty range is widened so nothing divides by zero).
  PlotArea(cv::Rect rect, double x0, double x1, double y0, double y1);
  cv::Point to_pixel(double x, double y) const;
  cv::Point2d to_pixel_exact(double x, double y) const;
  const cv::Rect& rect() const { return rect_; }
  double x0() const { return frame_.x0(); }
  double x1() const { return frame_.x1(); }
  double y0() const { return frame_.y0(); }
  double y1() const { return frame_.y1(); }
  // Frame, grid, ticks and labels.
  void draw_axes(cv::Mat& img, const std::string& x_label, const std::string& y_label, bool grid = true) const;

 private:
  cv::Rect rect_;
  ChartFrame frame_;  // the data-to-pixel mapping, shared with the vector figures
};

// Equal-aspect data window: expands [x0,x1] x [y0,y1] so one data unit is
// the same number of pixels in x and y inside `rect` (for maps).
PlotArea equal_aspect_area(cv::Rect rect, double x0, double x1, double y0, double y1);

// Vertical colour bar for a deviation scale, labelled in micrometres, with
// the tolerance limits marked as black ticks and labels ("+tol", "-tol").
void draw_colour_bar(cv::Mat& img, cv::Rect bar, const DeviationScale& scale, double lower_tolerance,
                     double upper_tolerance, const std::string& label);

// PNG bytes of an 8-bit image (render/png.hpp).
std::vector<unsigned char> encode_png(const cv::Mat& img);

}  // namespace furrow::plot
