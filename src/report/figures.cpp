#include "report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <map>

#include "render/chart.hpp"

#include "base/number_text.hpp"

namespace furrow {

namespace {

constexpr int kWidth = 900, kHeight = 640;
constexpr Rgb kOutline{150, 150, 150}, kRim{90, 90, 90}, kMuted{120, 120, 120};

struct Bounds {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  void add(const Eigen::Vector2d& p) {
    if (!p.allFinite()) return;
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

Drawing blank_with_title(const std::string& title) {
  Drawing d(kWidth, kHeight);
  d.text(title, {20, 30}, 20).bold = true;
  return d;
}

void draw_outlines(Drawing& d, const ChartFrame& frame, const std::vector<Outline>& outlines) {
  for (const Outline& o : outlines) {
    std::vector<Eigen::Vector2d> pts;
    for (const auto& p : o) pts.push_back(frame.to_pixel(p));
    if (pts.size() >= 2) d.polyline(pts, kOutline);
  }
}

double scale_range(const std::vector<MapPoint>& points, const ToleranceLimits& tol) {
  double range = std::max(std::fabs(tol.lower), std::fabs(tol.upper));
  for (const MapPoint& p : points)
    if (std::isfinite(p.value)) range = std::max(range, std::fabs(p.value));
  return range > 0 ? range : 1e-3;
}

// Micrometres with a sign and one decimal ("+61.3"), as in the report's tables.
std::string signed_um(double mm) { return signed_fixed(mm * 1000.0, 1); }

// Labels of the out-of-tolerance points, largest |value| first, at most
// kMaxMapLabels; the rest are counted in a note under the title.
void label_out_of_tolerance(Drawing& d, const ChartFrame& frame, const std::vector<MapPoint>& points, double radius) {
  std::vector<const MapPoint*> out;
  for (const MapPoint& p : points)
    if (p.out_of_tolerance && std::isfinite(p.value)) out.push_back(&p);
  std::stable_sort(out.begin(), out.end(),
                   [](const MapPoint* a, const MapPoint* b) { return std::fabs(a->value) > std::fabs(b->value); });
  const std::size_t shown = std::min(out.size(), kMaxMapLabels);
  for (std::size_t k = 0; k < shown; ++k) {
    const MapPoint& p = *out[k];
    const Eigen::Vector2d c = frame.to_pixel(p.position);
    const std::string value = signed_um(p.value);
    DrawItem& t = d.text(p.label + " " + value + " \u00b5m", {c.x() + radius + 4, c.y() - radius - 2}, 11.5);
    t.css_class = "oot-label";
    t.data = {{"id", p.label}, {"value", value}};
  }
  if (shown < out.size())
    d.text(std::to_string(shown) + " of " + std::to_string(out.size()) +
               " points out of tolerance labelled (the largest deviations)",
           {20, 50}, 12, TextAnchor::start, kMuted);
}

}  // namespace

Drawing deviation_map_drawing(const std::string& title, const std::vector<MapPoint>& points,
                              const std::vector<Outline>& outlines, const ToleranceLimits& tolerance,
                              const std::string& x_label, const std::string& y_label, bool equal_aspect,
                              double range) {
  Drawing d = blank_with_title(title);
  Bounds b;
  for (const auto& o : outlines)
    for (const auto& p : o) b.add(p);
  for (const MapPoint& p : points) b.add(p.position);
  b.pad();
  const PixelRect rect{90, 60, kWidth - 90 - 150, kHeight - 60 - 70};
  const ChartFrame frame = equal_aspect ? equal_aspect_frame(rect, b.x0, b.x1, b.y0, b.y1)
                                        : ChartFrame(rect, b.x0, b.x1, b.y0, b.y1);
  frame.draw_axes(d, x_label, y_label, false);
  draw_outlines(d, frame, outlines);
  const DeviationScale scale{range > 0 ? range : scale_range(points, tolerance)};
  // Larger |value| drawn last so extremes stay visible where points overlap.
  std::vector<const MapPoint*> order;
  for (const MapPoint& p : points) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(), [](const MapPoint* a, const MapPoint* b) {
    return std::fabs(a->value) < std::fabs(b->value);
  });
  const double radius = points.size() > 2000 ? 3 : points.size() > 300 ? 5 : 7;
  // A rim separates markers of similar colour; on 3 px dots it would be
  // most of the dot, so dense maps go without (and draw twice as fast).
  const std::optional<Rgb> rim = points.size() > 2000 ? std::nullopt : std::optional<Rgb>(kRim);
  for (const MapPoint* p : order) {
    const Eigen::Vector2d c = frame.to_pixel(p->position);
    d.circle(c, radius, scale.colour(p->value), rim);
    if (p->flagged) d.circle(c, radius + 3, std::nullopt, Drawing::kInk, 2);
  }
  label_out_of_tolerance(d, frame, points, radius);
  draw_colour_bar(d, {kWidth - 110.0, 75, 22, kHeight - 75 - 90.0}, scale, tolerance.lower, tolerance.upper,
                  "\u00b5m");
  return d;
}

Drawing histogram_drawing(const std::string& title, const std::vector<double>& values,
                          const ToleranceLimits& tolerance) {
  Drawing d = blank_with_title(title);
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
  const ChartFrame frame({90, 60, kWidth - 130, kHeight - 60 - 70}, lo, hi, 0, peak * 1.1);
  frame.draw_axes(d, "deviation [\u00b5m]  (+ material left, \u2212 overcut)", "points");
  const DeviationScale scale{std::max(std::fabs(lo), std::fabs(hi)) / 1000.0};
  for (int k = 0; k < bins; ++k) {
    const int n = counts[static_cast<std::size_t>(k)];
    if (n == 0) continue;
    const double a = lo + (hi - lo) * k / bins, b = lo + (hi - lo) * (k + 1) / bins;
    DrawItem& bar = d.rect(frame.to_pixel(a, 0), frame.to_pixel(b, n), scale.colour(0.5 * (a + b) / 1000.0), kRim);
    bar.css_class = "bin";
    bar.data = {{"count", std::to_string(n)}};
  }
  for (double tol : {tolerance.lower, tolerance.upper}) {
    const Eigen::Vector2d top = frame.to_pixel(tol * 1000.0, peak * 1.1), bottom = frame.to_pixel(tol * 1000.0, 0);
    d.line(top, bottom, Drawing::kInk, 2);
    d.text(tol >= 0 ? "+tol" : "\u2212tol", {top.x(), top.y() - 6}, 14, TextAnchor::middle);
  }
  return d;
}

Drawing histogram_bins_drawing(const std::string& title, const std::vector<double>& edges,
                               const std::vector<std::size_t>& counts, const ToleranceLimits& tolerance) {
  Drawing d = blank_with_title(title);
  if (edges.size() < 2 || counts.size() + 1 != edges.size())
    throw std::logic_error("histogram_bins_drawing: one count per bin expected");
  const double lo = std::min(edges.front(), std::min(tolerance.lower, 0.0)) * 1000.0;
  const double hi = std::max(edges.back(), std::max(tolerance.upper, 0.0)) * 1000.0;
  const std::size_t peak = std::max<std::size_t>(1, *std::max_element(counts.begin(), counts.end()));
  const ChartFrame frame({90, 60, kWidth - 130, kHeight - 60 - 70}, lo, hi, 0, static_cast<double>(peak) * 1.1);
  frame.draw_axes(d, "deviation [\u00b5m]  (+ material left, \u2212 overcut)", "points");
  const DeviationScale scale{std::max(std::fabs(lo), std::fabs(hi)) / 1000.0};
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const std::size_t n = counts[k];
    if (n == 0) continue;
    const double a = edges[k] * 1000.0, b = edges[k + 1] * 1000.0;
    DrawItem& bar = d.rect(frame.to_pixel(a, 0), frame.to_pixel(b, static_cast<double>(n)),
                           scale.colour(0.5 * (a + b) / 1000.0), kRim);
    bar.css_class = "bin";
    bar.data = {{"count", std::to_string(n)}};
  }
  for (double tol : {tolerance.lower, tolerance.upper}) {
    const Eigen::Vector2d top = frame.to_pixel(tol * 1000.0, static_cast<double>(peak) * 1.1);
    const Eigen::Vector2d bottom = frame.to_pixel(tol * 1000.0, 0);
    d.line(top, bottom, Drawing::kInk, 2);
    d.text(tol >= 0 ? "+tol" : "\u2212tol", {top.x(), top.y() - 6}, 14, TextAnchor::middle);
  }
  return d;
}

Drawing scatter_drawing(const std::string& title, const std::vector<double>& predicted,
                        const std::vector<double>& measured, const std::vector<double>& sigma) {
  Drawing d = blank_with_title(title);
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
  const double side = kHeight - 60 - 70;
  const ChartFrame frame({110, 60, side, side}, lo, hi, lo, hi);
  frame.draw_axes(d, "predicted [\u00b5m]", "measured [\u00b5m]");
  d.line(frame.to_pixel(lo, lo), frame.to_pixel(hi, hi), kMuted);
  d.text("measured = predicted", frame.to_pixel(lo + 0.05 * (hi - lo), lo + 0.12 * (hi - lo)), 12.5,
         TextAnchor::start, kMuted);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = predicted[k] * 1000.0, y = measured[k] * 1000.0;
    if (k < sigma.size() && sigma[k] > 0) {
      const double s = sigma[k] * 1000.0;
      d.line(frame.to_pixel(x, y - s), frame.to_pixel(x, y + s), kOutline);
    }
    d.circle(frame.to_pixel(x, y), 4, Rgb{30, 90, 160});
  }
  return d;
}

Drawing status_map_drawing(const std::string& title, const std::vector<StatusItem>& items,
                           const std::vector<Outline>& outlines, const std::vector<Eigen::Vector2d>& background_points,
                           const std::string& x_label, const std::string& y_label) {
  Drawing d = blank_with_title(title);
  Bounds b;
  for (const auto& o : outlines)
    for (const auto& p : o) b.add(p);
  for (const auto& it : items) b.add(it.position);
  for (const auto& p : background_points) b.add(p);
  b.pad();
  const ChartFrame frame = equal_aspect_frame({90, 60, kWidth - 90 - 190, kHeight - 60 - 70}, b.x0, b.x1, b.y0, b.y1);
  frame.draw_axes(d, x_label, y_label, false);
  draw_outlines(d, frame, outlines);
  for (const auto& p : background_points) d.circle(frame.to_pixel(p), 2, Rgb{170, 170, 170});
  std::map<std::string, int> seen;
  for (const StatusItem& it : items) {
    const Rgb colour = status_colour(it.status.c_str());
    if (it.outline.size() >= 3) {
      std::vector<Eigen::Vector2d> poly;
      for (const auto& p : it.outline) poly.push_back(frame.to_pixel(p));
      d.polygon(poly, colour, 0.45, colour, 2);
    }
    const Eigen::Vector2d c = frame.to_pixel(it.position);
    d.circle(c, 7, colour, Drawing::kInk);
    DrawItem& label = d.text(it.label, {c.x() + 10, c.y() - 8}, 14);
    label.css_class = "site-label";
    label.data = {{"id", it.label}, {"status", it.status}};
    seen.emplace(it.status, 0);
  }
  double y = 80;
  for (const auto& [status, unused] : seen) {
    (void)unused;
    d.circle({kWidth - 175.0, y - 5}, 7, status_colour(status.c_str()));
    d.text(status, {kWidth - 160.0, y}, 14);
    y += 26;
  }
  return d;
}

}  // namespace furrow
