#include "render/chart.hpp"

#include <algorithm>
#include <cmath>

#include "render/ticks.hpp"

namespace furrow {

namespace {

constexpr Rgb kGrid{225, 225, 225};
constexpr double kTickFont = 12.5, kLabelFont = 15.5;

}  // namespace

ChartFrame::ChartFrame(PixelRect rect, double x0, double x1, double y0, double y1)
    : rect_(rect), x0_(x0), x1_(x1), y0_(y0), y1_(y1) {
  auto widen = [](double& a, double& b) {
    if (!(b > a)) {
      const double pad = std::max(1e-9, std::fabs(a) * 0.05);
      a -= pad;
      b += pad;
    }
  };
  widen(x0_, x1_);
  widen(y0_, y1_);
}

Eigen::Vector2d ChartFrame::to_pixel(double x, double y) const {
  return {rect_.x + (x - x0_) / (x1_ - x0_) * rect_.width, rect_.y + rect_.height - (y - y0_) / (y1_ - y0_) * rect_.height};
}

void ChartFrame::draw_axes(Drawing& d, const std::string& x_label, const std::string& y_label, bool grid) const {
  const std::vector<double> xt = plot::nice_ticks(x0_, x1_), yt = plot::nice_ticks(y0_, y1_);
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1, ys = yt.size() > 1 ? yt[1] - yt[0] : 1;
  const double top = rect_.y, bottom = rect_.y + rect_.height, left = rect_.x, right = rect_.x + rect_.width;
  for (double x : xt) {
    const double px = to_pixel(x, y0_).x();
    if (grid) d.line({px, top}, {px, bottom}, kGrid);
    d.line({px, bottom}, {px, bottom + 5}, Drawing::kInk);
    d.text(plot::tick_label(x, xs), {px, bottom + 20}, kTickFont, TextAnchor::middle);
  }
  for (double y : yt) {
    const double py = to_pixel(x0_, y).y();
    if (grid) d.line({left, py}, {right, py}, kGrid);
    d.line({left - 5, py}, {left, py}, Drawing::kInk);
    d.text(plot::tick_label(y, ys), {left - 8, py + 4}, kTickFont, TextAnchor::end);
  }
  d.rect({left, top}, {right, bottom}, std::nullopt, Drawing::kInk);
  if (!x_label.empty()) d.text(x_label, {0.5 * (left + right), bottom + 42}, kLabelFont, TextAnchor::middle);
  if (!y_label.empty()) d.text(y_label, {left - 52, 0.5 * (top + bottom)}, kLabelFont, TextAnchor::middle).vertical = true;
}

ChartFrame equal_aspect_frame(PixelRect rect, double x0, double x1, double y0, double y1) {
  double w = std::max(x1 - x0, 1e-9), h = std::max(y1 - y0, 1e-9);
  const double per_px = std::max(w / rect.width, h / rect.height);
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  w = per_px * rect.width;
  h = per_px * rect.height;
  return ChartFrame(rect, cx - w / 2, cx + w / 2, cy - h / 2, cy + h / 2);
}

void draw_colour_bar(Drawing& d, PixelRect bar, const DeviationScale& scale, double lower_tolerance,
                     double upper_tolerance, const std::string& label) {
  // Bands one or two pixels tall: smooth in a PNG, few elements in an SVG.
  const int bands = std::max(1, static_cast<int>(bar.height / 2));
  for (int k = 0; k < bands; ++k) {
    const double y0 = bar.y + bar.height * k / bands, y1 = bar.y + bar.height * (k + 1) / bands;
    const double value = scale.range * (1.0 - 2.0 * (k + 0.5) / bands);
    d.rect({bar.x, y0}, {bar.x + bar.width, y1}, scale.colour(value));
  }
  d.rect({bar.x, bar.y}, {bar.x + bar.width, bar.y + bar.height}, std::nullopt, Drawing::kInk);
  const double range_um = scale.range * 1000.0;
  const std::vector<double> ticks = plot::nice_ticks(-range_um, range_um, 8);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1;
  auto y_of = [&](double um) { return bar.y + (1.0 - (um / range_um + 1.0) / 2.0) * bar.height; };
  const double right = bar.x + bar.width;
  for (double t : ticks) {
    const double y = y_of(t);
    d.line({right, y}, {right + 4, y}, Drawing::kInk);
    d.text(plot::tick_label(t, step), {right + 7, y + 4}, kTickFont);
  }
  for (double tol : {lower_tolerance, upper_tolerance}) {
    if (!std::isfinite(tol) || std::fabs(tol) > scale.range) continue;
    const double y = y_of(tol * 1000.0);
    d.line({bar.x - 6, y}, {right + 6, y}, Drawing::kInk, 2);
    d.text(tol >= 0 ? "+tol" : "-tol", {bar.x - 8, y + 4}, kTickFont, TextAnchor::end);
  }
  d.text(label, {bar.x + bar.width / 2, bar.y - 10}, 14, TextAnchor::middle);
}

}  // namespace furrow
