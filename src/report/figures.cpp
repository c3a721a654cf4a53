#include "report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

constexpr int kWidth = 900, kHeight = 640;

struct Bounds {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  void add(const Eigen::Vector2d& p) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  bool empty() const { return x0 > x1; }
  // 3 % margin so markers on the border stay inside the frame.
  void pad() {
    if (empty()) {
      x0 = y0 = 0;
      x1 = y1 = 1;
    }
    const double mx = 0.03 * std::max(x1 - x0, 1e-9), my = 0.03 * std::max(y1 - y0, 1e-9);
    x0 -= mx;
    x1 += mx;
    y0 -= my;
    y1 += my;
  }
};

cv::Mat blank_with_title(const std::string& title) {
  cv::Mat img(kHeight, kWidth, CV_8UC3, plot::kPaper);
  plot::text(img, title, {20, 30}, 0.65, plot::kInk, 1);
  return img;
}

void draw_outlines(cv::Mat& img, const plot::PlotArea& area, const std::vector<Outline>& outlines) {
  for (const Outline& o : outlines) {
    std::vector<cv::Point> pts;
    for (const auto& p : o) pts.push_back(area.to_pixel(p.x(), p.y()));
    if (pts.size() >= 2) cv::polylines(img, pts, false, cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
  }
}

double scale_range(const std::vector<MapPoint>& points, const ToleranceLimits& tol) {
  double range = std::max(std::fabs(tol.lower), std::fabs(tol.upper));
  for (const MapPoint& p : points)
    if (std::isfinite(p.value)) range = std::max(range, std::fabs(p.value));
  return range > 0 ? range : 1e-3;
}

}  // namespace

std::vector<unsigned char> deviation_map_png(const std::string& title, const std::vector<MapPoint>& points,
                                             const std::vector<Outline>& outlines,
                                             const ToleranceLimits& tolerance, const std::string& x_label,
                                             const std::string& y_label, bool equal_aspect) {
  cv::Mat img = blank_with_title(title);
  Bounds b;
  for (const auto& o : outlines)
    for (const auto& p : o) b.add(p);
  for (const MapPoint& p : points) b.add(p.position);
  b.pad();
  const cv::Rect rect(90, 55, kWidth - 90 - 150, kHeight - 55 - 70);
  const plot::PlotArea area = equal_aspect ? plot::equal_aspect_area(rect, b.x0, b.x1, b.y0, b.y1)
                                           : plot::PlotArea(rect, b.x0, b.x1, b.y0, b.y1);
  area.draw_axes(img, x_label, y_label, false);
  draw_outlines(img, area, outlines);
  const DeviationScale scale{scale_range(points, tolerance)};
  // Larger |value| drawn last so extremes stay visible where points overlap.
  std::vector<const MapPoint*> order;
  for (const MapPoint& p : points) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(), [](const MapPoint* a, const MapPoint* b) {
    return std::fabs(a->value) < std::fabs(b->value);
  });
  const int radius = points.size() > 2000 ? 3 : points.size() > 300 ? 5 : 7;
  for (const MapPoint* p : order) {
    const cv::Point c = area.to_pixel(p->position.x(), p->position.y());
    cv::circle(img, c, radius, plot::bgr(scale.colour(p->value)), cv::FILLED, cv::LINE_AA);
    cv::circle(img, c, radius, cv::Scalar(90, 90, 90), 1, cv::LINE_AA);
    if (p->flagged) cv::circle(img, c, radius + 3, plot::kInk, 2, cv::LINE_AA);
  }
  plot::draw_colour_bar(img, cv::Rect(kWidth - 110, 75, 22, kHeight - 75 - 90), scale, tolerance.lower,
                        tolerance.upper, "um");
  return plot::encode_png(img);
}

std::vector<unsigned char> histogram_png(const std::string& title, const std::vector<double>& values,
                                         const ToleranceLimits& tolerance) {
  cv::Mat img = blank_with_title(title);
  std::vector<double> um;
  for (double v : values)
    if (std::isfinite(v)) um.push_back(v * 1000.0);
  double lo = std::min(tolerance.lower, 0.0) * 1000.0, hi = std::max(tolerance.upper, 0.0) * 1000.0;
  for (double v : um) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  const double pad = 0.05 * std::max(hi - lo, 1e-3);
  lo -= pad;
  hi += pad;
  // Freedman-Diaconis would need quantiles; a square-root rule is robust
  // enough for report sizes (tens to thousands of points).
  const int bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(um.size())))), 5, 60);
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double v : um) {
    const int k = std::clamp(static_cast<int>((v - lo) / (hi - lo) * bins), 0, bins - 1);
    ++counts[static_cast<std::size_t>(k)];
  }
  const int peak = std::max(1, *std::max_element(counts.begin(), counts.end()));
  const plot::PlotArea area(cv::Rect(90, 55, kWidth - 130, kHeight - 55 - 70), lo, hi, 0, peak * 1.1);
  area.draw_axes(img, "deviation [um]  (+ material left, - overcut)", "points");
  const DeviationScale scale{std::max(std::fabs(lo), std::fabs(hi)) / 1000.0};
  for (int k = 0; k < bins; ++k) {
    if (counts[static_cast<std::size_t>(k)] == 0) continue;
    const double a = lo + (hi - lo) * k / bins, b = lo + (hi - lo) * (k + 1) / bins;
    const cv::Point p0 = area.to_pixel(a, 0), p1 = area.to_pixel(b, counts[static_cast<std::size_t>(k)]);
    cv::rectangle(img, p0, p1, plot::bgr(scale.colour(0.5 * (a + b) / 1000.0)), cv::FILLED);
    cv::rectangle(img, p0, p1, cv::Scalar(90, 90, 90), 1);
  }
  for (double tol : {tolerance.lower, tolerance.upper}) {
    const cv::Point top = area.to_pixel(tol * 1000.0, peak * 1.1), bottom = area.to_pixel(tol * 1000.0, 0);
    cv::line(img, top, bottom, plot::kInk, 2);
    plot::text_centred(img, tol >= 0 ? "+tol" : "-tol", {top.x, top.y - 10}, 0.45);
  }
  return plot::encode_png(img);
}

std::vector<unsigned char> scatter_png(const std::string& title, const std::vector<double>& predicted,
                                       const std::vector<double>& measured, const std::vector<double>& sigma) {
  cv::Mat img = blank_with_title(title);
  double lo = 0, hi = 0;
  const std::size_t n = std::min(predicted.size(), measured.size());
  for (std::size_t k = 0; k < n; ++k) {
    const double s = k < sigma.size() ? sigma[k] : 0.0;
    lo = std::min({lo, predicted[k], measured[k] - s});
    hi = std::max({hi, predicted[k], measured[k] + s});
  }
  const double pad = 0.05 * std::max(hi - lo, 1e-6);
  lo = (lo - pad) * 1000.0;
  hi = (hi + pad) * 1000.0;
  const int side = kHeight - 55 - 70;
  const plot::PlotArea area(cv::Rect(110, 55, side, side), lo, hi, lo, hi);
  area.draw_axes(img, "predicted [um]", "measured [um]");
  cv::line(img, area.to_pixel(lo, lo), area.to_pixel(hi, hi), cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
  plot::text(img, "measured = predicted", area.to_pixel(lo + 0.05 * (hi - lo), lo + 0.12 * (hi - lo)), 0.4,
             cv::Scalar(120, 120, 120));
  for (std::size_t k = 0; k < n; ++k) {
    const double x = predicted[k] * 1000.0, y = measured[k] * 1000.0;
    if (k < sigma.size() && sigma[k] > 0) {
      const double s = sigma[k] * 1000.0;
      cv::line(img, area.to_pixel(x, y - s), area.to_pixel(x, y + s), cv::Scalar(150, 150, 150), 1);
    }
    cv::circle(img, area.to_pixel(x, y), 4, cv::Scalar(160, 90, 30), cv::FILLED, cv::LINE_AA);
  }
  return plot::encode_png(img);
}

std::vector<unsigned char> status_map_png(const std::string& title, const std::vector<StatusItem>& items,
                                          const std::vector<Outline>& outlines,
                                          const std::vector<Eigen::Vector2d>& background_points,
                                          const std::string& x_label, const std::string& y_label) {
  cv::Mat img = blank_with_title(title);
  Bounds b;
  for (const auto& o : outlines)
    for (const auto& p : o) b.add(p);
  for (const auto& it : items) b.add(it.position);
  for (const auto& p : background_points) b.add(p);
  b.pad();
  const cv::Rect rect(90, 55, kWidth - 90 - 190, kHeight - 55 - 70);
  const plot::PlotArea area = plot::equal_aspect_area(rect, b.x0, b.x1, b.y0, b.y1);
  area.draw_axes(img, x_label, y_label, false);
  draw_outlines(img, area, outlines);
  for (const auto& p : background_points)
    cv::circle(img, area.to_pixel(p.x(), p.y()), 2, cv::Scalar(170, 170, 170), cv::FILLED, cv::LINE_AA);
  std::map<std::string, int> seen;
  for (const StatusItem& it : items) {
    const cv::Scalar colour = plot::bgr(status_colour(it.status.c_str()));
    if (it.outline.size() >= 3) {
      std::vector<cv::Point> poly;
      for (const auto& p : it.outline) poly.push_back(area.to_pixel(p.x(), p.y()));
      cv::Mat layer = img.clone();
      cv::fillPoly(layer, std::vector<std::vector<cv::Point>>{poly}, colour, cv::LINE_AA);
      cv::addWeighted(layer, 0.45, img, 0.55, 0, img);
      cv::polylines(img, poly, true, colour, 2, cv::LINE_AA);
    }
    const cv::Point c = area.to_pixel(it.position.x(), it.position.y());
    cv::circle(img, c, 7, colour, cv::FILLED, cv::LINE_AA);
    cv::circle(img, c, 7, plot::kInk, 1, cv::LINE_AA);
    plot::text(img, it.label, {c.x + 10, c.y - 8}, 0.45);
    seen.emplace(it.status, 0);
  }
  int y = 80;
  for (const auto& [status, unused] : seen) {
    (void)unused;
    cv::circle(img, {kWidth - 175, y - 5}, 7, plot::bgr(status_colour(status.c_str())), cv::FILLED, cv::LINE_AA);
    plot::text(img, status, {kWidth - 160, y}, 0.45);
    y += 26;
  }
  return plot::encode_png(img);
}

}  // namespace furrow
