#include "render/part_views.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "render/plot_canvas.hpp"
#include "render/png.hpp"

namespace furrow {

namespace {

constexpr int kPanelWidth = 520, kPanelHeight = 420, kPanelMargin = 26;
constexpr int kTitle = 40, kCaption = 22, kLegendWidth = 210;
const cv::Scalar kFaceEdge(110, 110, 110);

// The part's extent as drawn: points of every face kept by its trim, and
// its trim loops (a face's control net can reach far beyond what a trim
// keeps of it).
Eigen::AlignedBox3d drawn_box(const Part& part) {
  Eigen::AlignedBox3d box;
  constexpr int kSamples = 32;
  for (const Face& face : part.faces) {
    const ParameterDomain& d = face.domain();
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 0; j <= kSamples; ++j) {
        const double u = d.u0 + d.width_u() * i / kSamples, v = d.v0 + d.width_v() * j / kSamples;
        if (face.contains(u, v)) box.extend(face.surface().point(u, v));
      }
    for (const UvLoop& loop : face.trim().loops()) {
      const std::size_t step = std::max<std::size_t>(1, loop.size() / 256);
      for (std::size_t k = 0; k < loop.size(); k += step) box.extend(face.surface().point(loop[k].x(), loop[k].y()));
    }
  }
  return box;
}

// A 1-2-5 length near a quarter of the panel, in mm.
double scale_bar_length(double pixels_per_mm) {
  const double target = 0.25 * kPanelWidth / pixels_per_mm;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= target) return m * decade;
  return decade;
}

std::string length_text(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, mm >= 1 ? "%.0f mm" : "%.3g mm", mm);
  return buf;
}

void paint_panel(cv::Mat& img, const ViewPanel& panel, const SurfacePainter& paint,
                 std::map<std::int64_t, int>& key_pixels) {
  const PartRaster& r = panel.raster;
  std::vector<std::int64_t> keys(r.face.size(), -1);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t i = r.index(x, y);
      if (r.face[i] < 0) continue;
      const SurfacePaint s = paint(static_cast<std::size_t>(r.face[i]), r.uv[i]);
      keys[i] = s.key;
      ++key_pixels[s.key];
      const Rgb c = PartViewsFigure::shaded(s.colour, r.light[i]);
      img.at<cv::Vec3b>(panel.top + y, panel.left + x) = cv::Vec3b(c[2], c[1], c[0]);
    }
  // Lines where the visible surface changes (see the header).
  // [mm] of depth between neighbouring pixels of one face that is an
  // occlusion, not a steep slope (25 pixels: a slope within 2.3 degrees of
  // the line of sight).
  const double fold = 25.0 / r.camera.scale;
  auto mark = [&](std::size_t a, std::size_t b, int xa, int ya, int xb, int yb) {
    const bool fa = r.face[a] >= 0, fb = r.face[b] >= 0;
    if (!fa && !fb) return;
    const bool a_front = fa && (!fb || r.depth[a] >= r.depth[b]);
    const int x = a_front ? xa : xb, y = a_front ? ya : yb;
    cv::Scalar colour = plot::kInk;
    if (fa && fb) {
      if (r.face[a] == r.face[b]) {
        if (keys[a] == keys[b] && std::abs(r.depth[a] - r.depth[b]) <= fold) return;
      } else if (keys[a] == keys[b]) {
        colour = kFaceEdge;
      }
    }
    img.at<cv::Vec3b>(panel.top + y, panel.left + x) =
        cv::Vec3b(static_cast<unsigned char>(colour[0]), static_cast<unsigned char>(colour[1]),
                  static_cast<unsigned char>(colour[2]));
  };
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t i = r.index(x, y);
      if (x + 1 < r.width) {
        const std::size_t j = r.index(x + 1, y);
        if (r.face[i] != r.face[j] || keys[i] != keys[j] || std::abs(r.depth[i] - r.depth[j]) > fold)
          mark(i, j, x, y, x + 1, y);
      }
      if (y + 1 < r.height) {
        const std::size_t j = r.index(x, y + 1);
        if (r.face[i] != r.face[j] || keys[i] != keys[j] || std::abs(r.depth[i] - r.depth[j]) > fold)
          mark(i, j, x, y, x, y + 1);
      }
    }
}

void draw_scale_bar(cv::Mat& img, const ViewPanel& panel) {
  const double mm = scale_bar_length(panel.raster.camera.scale);
  const int length = static_cast<int>(std::lround(mm * panel.raster.camera.scale));
  const cv::Point a(panel.left + 12, panel.top + kPanelHeight - 12), b = a + cv::Point(length, 0);
  cv::line(img, a, b, plot::kInk, 2);
  cv::line(img, a + cv::Point(0, -5), a + cv::Point(0, 2), plot::kInk, 1);
  cv::line(img, b + cv::Point(0, -5), b + cv::Point(0, 2), plot::kInk, 1);
  plot::text(img, length_text(mm), b + cv::Point(8, 4), 0.4);
}

}  // namespace

Rgb PartViewsFigure::shaded(const Rgb& base, float light) {
  const double f = 0.45 + 0.55 * std::clamp(static_cast<double>(light), 0.0, 1.0);
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = static_cast<unsigned char>(std::lround(base[c] * f));
  return out;
}

PartViewPanels part_view_panels(const Part& part) {
  if (part.faces.empty()) throw std::invalid_argument("part views: the part has no faces");
  Eigen::AlignedBox3d box = drawn_box(part);
  if (box.isEmpty()) box = part.control_box();  // every sample trimmed away: show the nets' extent
  const ViewDirection directions[4] = {ViewDirection::top, ViewDirection::front, ViewDirection::side,
                                       ViewDirection::iso};
  double scale = std::numeric_limits<double>::infinity();
  for (ViewDirection d : directions)
    scale = std::min(scale, fitting_scale(d, box, kPanelWidth, kPanelHeight, kPanelMargin));
  PartViewPanels views;
  for (int k = 0; k < 4; ++k) {
    ViewPanel panel;
    panel.direction = directions[k];
    panel.left = (k % 2) * kPanelWidth;
    panel.top = kTitle + (k / 2) * (kCaption + kPanelHeight) + kCaption;
    panel.raster = rasterize_part(part, centred_camera(directions[k], box, kPanelWidth, kPanelHeight, scale),
                                  kPanelWidth, kPanelHeight);
    views.panels.push_back(std::move(panel));
  }
  return views;
}

PartViewsFigure draw_part_views(const std::string& title, const Part& part, const SurfacePainter& paint,
                                const std::vector<LegendEntry>& legend, const std::vector<ViewLabel>& labels) {
  return draw_part_views(title, part_view_panels(part), paint, legend, labels);
}

PartViewsFigure draw_part_views(const std::string& title, PartViewPanels views, const SurfacePainter& paint,
                                const std::vector<LegendEntry>& legend, const std::vector<ViewLabel>& labels) {
  if (views.panels.size() != 4) throw std::invalid_argument("part views: four panels expected");
  PartViewsFigure fig;
  fig.width = 2 * kPanelWidth + kLegendWidth;
  fig.height = kTitle + 2 * (kCaption + kPanelHeight);
  fig.bgr.assign(static_cast<std::size_t>(fig.width) * fig.height * 3, 255);
  cv::Mat img(fig.height, fig.width, CV_8UC3, fig.bgr.data());
  plot::text(img, title, {16, 26}, 0.6);
  for (ViewPanel& panel : views.panels) {
    std::map<std::int64_t, int> key_pixels;
    paint_panel(img, panel, paint, key_pixels);
    cv::rectangle(img, cv::Rect(panel.left + 2, panel.top, kPanelWidth - 4, kPanelHeight), plot::kGrid, 1);
    plot::text(img, view_caption(panel.direction), {panel.left + 8, panel.top - 6}, 0.45);
    draw_scale_bar(img, panel);
    const double tolerance = 1.5 / panel.raster.camera.scale;
    // In the given order, each where it overlaps no label already placed
    // in this view (dense views would otherwise print one over another).
    std::vector<cv::Rect> placed;
    for (const ViewLabel& label : labels) {
      const auto seen = key_pixels.find(label.key);
      if (seen == key_pixels.end() || seen->second < label.min_pixels) continue;
      if (!panel.raster.visible(label.at, tolerance)) continue;
      const Eigen::Vector2d at = panel.to_figure(label.at);
      const cv::Point p(static_cast<int>(std::lround(at.x())), static_cast<int>(std::lround(at.y())));
      int baseline = 0;
      const cv::Size size = cv::getTextSize(label.text, plot::kFont, 0.4, 4, &baseline);
      const cv::Rect box(p.x - size.width / 2 - 2, p.y - size.height / 2 - 2, size.width + 4, size.height + 4);
      if (std::any_of(placed.begin(), placed.end(), [&](const cv::Rect& r) { return (r & box).area() > 0; }))
        continue;
      placed.push_back(box);
      plot::text_centred(img, label.text, p, 0.4, plot::kPaper, 4);
      plot::text_centred(img, label.text, p, 0.4, plot::kInk, 1);
    }
  }
  fig.panels = std::move(views.panels);
  // Legend: the caller's entries, then what the lines mean.
  int y = kTitle + kCaption + 10;
  const int x = 2 * kPanelWidth + 14;
  for (const LegendEntry& e : legend) {
    cv::rectangle(img, cv::Rect(x, y, 18, 14), plot::bgr(e.colour), cv::FILLED);
    cv::rectangle(img, cv::Rect(x, y, 18, 14), plot::kInk, 1);
    plot::text(img, e.text, {x + 26, y + 12}, 0.42);
    y += 24;
  }
  const std::pair<cv::Scalar, const char*> lines[] = {{plot::kInk, "outline, region border"},
                                                      {kFaceEdge, "face edge"}};
  for (const auto& [colour, text] : lines) {
    cv::line(img, {x, y + 7}, {x + 18, y + 7}, colour, 2);
    plot::text(img, text, {x + 26, y + 12}, 0.42);
    y += 24;
  }
  fig.legend_left = x;
  fig.legend_bottom = y;
  return fig;
}

std::vector<unsigned char> part_views_png(const PartViewsFigure& figure) {
  ImageRows rows;
  rows.width = figure.width;
  rows.height = figure.height;
  rows.channels = 3;
  rows.data = figure.bgr.data();
  rows.stride = static_cast<std::size_t>(figure.width) * 3;
  rows.bgr = true;
  return encode_png(rows);
}

}  // namespace furrow
