#include "render/plot_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "render/png.hpp"

namespace furrow::plot {

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale, const cv::Scalar& colour,
          int thickness) {
  cv::putText(img, s, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

void text_centred(cv::Mat& img, const std::string& s, cv::Point centre, double scale,
                  const cv::Scalar& colour, int thickness) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, thickness, &baseline);
  text(img, s, {centre.x - size.width / 2, centre.y + size.height / 2}, scale, colour, thickness);
}

void text_right(cv::Mat& img, const std::string& s, cv::Point right_baseline, double scale,
                const cv::Scalar& colour) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, 1, &baseline);
  text(img, s, {right_baseline.x - size.width, right_baseline.y}, scale, colour, 1);
}

void text_vertical(cv::Mat& img, const std::string& s, cv::Point centre, double scale) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, 1, &baseline);
  cv::Mat strip(size.height + baseline + 4, size.width + 4, img.type(), kPaper);
  text(strip, s, {2, size.height + 1}, scale);
  cv::Mat rotated;
  cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect target(centre.x - rotated.cols / 2, centre.y - rotated.rows / 2, rotated.cols, rotated.rows);
  target &= cv::Rect(0, 0, img.cols, img.rows);
  if (target.area() > 0) rotated(cv::Rect(0, 0, target.width, target.height)).copyTo(img(target));
}

PlotArea::PlotArea(cv::Rect rect, double x0, double x1, double y0, double y1)
    : rect_(rect),
      frame_(PixelRect{static_cast<double>(rect.x), static_cast<double>(rect.y), static_cast<double>(rect.width),
                       static_cast<double>(rect.height)},
             x0, x1, y0, y1) {}

cv::Point2d PlotArea::to_pixel_exact(double x, double y) const {
  const Eigen::Vector2d p = frame_.to_pixel(x, y);
  return {p.x(), p.y()};
}

cv::Point PlotArea::to_pixel(double x, double y) const {
  const cv::Point2d p = to_pixel_exact(x, y);
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}

void PlotArea::draw_axes(cv::Mat& img, const std::string& x_label, const std::string& y_label,
                         bool grid) const {
  const std::vector<double> xt = nice_ticks(x0(), x1()), yt = nice_ticks(y0(), y1());
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1, ys = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (double x : xt) {
    const cv::Point p = to_pixel(x, y0());
    if (grid) cv::line(img, {p.x, rect_.y}, {p.x, rect_.y + rect_.height}, kGrid, 1);
    cv::line(img, p, {p.x, p.y + 5}, kInk, 1);
    text_centred(img, tick_label(x, xs), {p.x, p.y + 16}, 0.4);
  }
  for (double y : yt) {
    const cv::Point p = to_pixel(x0(), y);
    if (grid) cv::line(img, {rect_.x, p.y}, {rect_.x + rect_.width, p.y}, kGrid, 1);
    cv::line(img, {p.x - 5, p.y}, p, kInk, 1);
    text_right(img, tick_label(y, ys), {p.x - 8, p.y + 4}, 0.4);
  }
  cv::rectangle(img, rect_, kInk, 1);
  if (!x_label.empty())
    text_centred(img, x_label, {rect_.x + rect_.width / 2, rect_.y + rect_.height + 38}, 0.5);
  if (!y_label.empty()) text_vertical(img, y_label, {rect_.x - 58, rect_.y + rect_.height / 2}, 0.5);
}

PlotArea equal_aspect_area(cv::Rect rect, double x0, double x1, double y0, double y1) {
  const ChartFrame f = equal_aspect_frame(PixelRect{static_cast<double>(rect.x), static_cast<double>(rect.y),
                                                    static_cast<double>(rect.width), static_cast<double>(rect.height)},
                                          x0, x1, y0, y1);
  return PlotArea(rect, f.x0(), f.x1(), f.y0(), f.y1());
}

void draw_colour_bar(cv::Mat& img, cv::Rect bar, const DeviationScale& scale, double lower_tolerance,
                     double upper_tolerance, const std::string& label) {
  for (int y = 0; y < bar.height; ++y) {
    const double value = scale.range * (1.0 - 2.0 * (y + 0.5) / bar.height);
    cv::line(img, {bar.x, bar.y + y}, {bar.x + bar.width - 1, bar.y + y}, bgr(scale.colour(value)), 1);
  }
  cv::rectangle(img, bar, kInk, 1);
  const double range_um = scale.range * 1000.0;
  const std::vector<double> ticks = nice_ticks(-range_um, range_um, 8);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1;
  auto y_of = [&](double um) {
    return bar.y + static_cast<int>(std::lround((1.0 - (um / range_um + 1.0) / 2.0) * bar.height));
  };
  for (double t : ticks) {
    const int y = y_of(t);
    cv::line(img, {bar.x + bar.width, y}, {bar.x + bar.width + 4, y}, kInk, 1);
    text(img, tick_label(t, step), {bar.x + bar.width + 7, y + 4}, 0.4);
  }
  for (double tol : {lower_tolerance, upper_tolerance}) {
    if (!std::isfinite(tol) || std::fabs(tol) > scale.range) continue;
    const int y = y_of(tol * 1000.0);
    cv::line(img, {bar.x - 6, y}, {bar.x + bar.width + 6, y}, kInk, 2);
    text_right(img, tol >= 0 ? "+tol" : "-tol", {bar.x - 8, y + 4}, 0.4);
  }
  text_centred(img, label, {bar.x + bar.width / 2, bar.y - 14}, 0.45);
}

std::vector<unsigned char> encode_png(const cv::Mat& img) {
  if (img.depth() != CV_8U) throw std::invalid_argument("encode_png: the image is not 8-bit");
  return encode_png(ImageRows{img.cols, img.rows, img.channels(), img.data, img.step, true});
}

}  // namespace furrow::plot
