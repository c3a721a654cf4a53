#include "results/spc_chart.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "base/number_text.hpp"
#include "render/chart.hpp"

namespace furrow {
namespace {

constexpr int kWidth = 760;
constexpr Rgb kValue{40, 90, 160};
constexpr Rgb kAlarm{200, 30, 30};
constexpr Rgb kCentre{60, 140, 60};
constexpr Rgb kLimit{200, 120, 30};

double um(double mm) { return mm * 1000; }

// A y range covering the values and lines, with a margin so nothing sits
// on the frame.
std::pair<double, double> y_range(const std::vector<double>& values, const std::vector<double>& lines) {
  double lo = 0, hi = 0;
  bool first = true;
  for (const std::vector<double>* set : {&values, &lines})
    for (double v : *set) {
      lo = first ? v : std::min(lo, v);
      hi = first ? v : std::max(hi, v);
      first = false;
    }
  // Nothing to show, or one level only (a single value, a constant
  // series): a window of 1 µm either side, so the ticks still read.
  if (hi - lo < 1e-6) return {lo - 1, hi + 1};
  const double margin = 0.08 * (hi - lo);
  return {lo - margin, hi + margin};
}

void horizontal(Drawing& d, const ChartFrame& f, double value, const Rgb& colour, const char* css, const std::string& label) {
  DrawItem& line = d.line(f.to_pixel(f.x0(), value), f.to_pixel(f.x1(), value), colour, 1.5);
  line.css_class = css;
  line.data = {{"value", shortest(value)}};
  const Eigen::Vector2d end = f.to_pixel(f.x1(), value);
  d.text(label, {end.x() + 6, end.y() + 4}, 12, TextAnchor::start, colour);
}

// One panel: the frame, its data range for readers, lines, then the points.
void panel(Drawing& d, PixelRect rect, double x0, double x1, const std::vector<double>& xs,
           const std::vector<double>& ys, const std::vector<bool>& alarm, const char* point_class,
           const std::vector<std::pair<double, std::pair<const char*, std::string>>>& lines, const std::string& y_label) {
  std::vector<double> line_values;
  for (const auto& l : lines) line_values.push_back(l.first);
  const auto [y0, y1] = y_range(ys, line_values);
  const ChartFrame f(rect, x0, x1, y0, y1);
  f.draw_axes(d, "part", y_label);
  DrawItem& area = d.rect({rect.x, rect.y}, {rect.x + rect.width, rect.y + rect.height}, std::nullopt);
  area.css_class = "plot-area";
  area.data = {{"x0", shortest(f.x0())}, {"x1", shortest(f.x1())}, {"y0", shortest(f.y0())}, {"y1", shortest(f.y1())}};
  for (const auto& [value, style] : lines)
    horizontal(d, f, value, std::string(style.first) == "centre" ? kCentre : kLimit, style.first, style.second);
  std::vector<Eigen::Vector2d> trace;
  for (std::size_t i = 0; i < xs.size(); ++i) trace.push_back(f.to_pixel(xs[i], ys[i]));
  if (trace.size() > 1) d.polyline(trace, kValue, 1);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    DrawItem& dot = d.circle(trace[i], 3.5, alarm[i] ? kAlarm : kValue);
    dot.css_class = alarm[i] ? std::string(point_class) + " alarm" : point_class;
    dot.data = {{"part", std::to_string(static_cast<long long>(xs[i]))}, {"value", shortest(ys[i])}};
  }
}

}  // namespace

Drawing imr_chart(const CharacteristicSpc& c, std::size_t part_count, std::size_t window) {
  Drawing d(kWidth, 560);
  d.text(c.id + " (" + c.kind + ")", {12, 22}, 16, TextAnchor::start).bold = true;
  const std::size_t parts = std::max<std::size_t>(part_count, 1);
  const std::size_t first_part = parts > window && window > 0 ? parts - window : 0;
  const double x0 = static_cast<double>(first_part) - 0.5, x1 = static_cast<double>(parts) - 0.5;
  // The series' positions shown: from the first value of a part in the window.
  const std::size_t first =
      static_cast<std::size_t>(std::lower_bound(c.part_index.begin(), c.part_index.end(), first_part) -
                               c.part_index.begin());
  std::vector<bool> in_violation(c.values.size(), false);
  for (const SpcViolation& v : c.violations)
    for (std::size_t i = v.index; i <= v.last; ++i) in_violation[i] = true;
  std::vector<double> xs, ys;
  std::vector<bool> alarm;
  for (std::size_t i = first; i < c.values.size(); ++i) {
    xs.push_back(static_cast<double>(c.part_index[i]));
    ys.push_back(um(c.values[i]));
    alarm.push_back(in_violation[i]);
  }
  std::vector<std::pair<double, std::pair<const char*, std::string>>> lines;
  if (c.mean) lines.push_back({um(*c.mean), {"centre", "mean"}});
  if (c.ucl && c.sigma_within && *c.sigma_within > 0) {
    lines.push_back({um(*c.ucl), {"limit", "UCL"}});
    lines.push_back({um(*c.lcl), {"limit", "LCL"}});
  }
  panel(d, {80, 40, 600, 280}, x0, x1, xs, ys, alarm, "value", lines, "value [µm]");

  // Moving ranges, each drawn at the later of its two parts (its earlier
  // part may lie before the window).
  std::vector<double> mx, my;
  for (std::size_t i = std::max<std::size_t>(first, 1); i < c.values.size(); ++i) {
    mx.push_back(static_cast<double>(c.part_index[i]));
    my.push_back(std::abs(um(c.values[i]) - um(c.values[i - 1])));
  }
  std::vector<std::pair<double, std::pair<const char*, std::string>>> mr_lines;
  if (c.mr_mean) {
    mr_lines.push_back({um(*c.mr_mean), {"centre", "mean MR"}});
    mr_lines.push_back({um(*c.mr_ucl), {"limit", "UCL"}});
  }
  panel(d, {80, 390, 600, 110}, x0, x1, mx, my, std::vector<bool>(mx.size(), false), "mr", mr_lines, "MR [µm]");
  return d;
}

}  // namespace furrow
