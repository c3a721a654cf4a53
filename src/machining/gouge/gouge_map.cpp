#include "machining/gouge/gouge_map.hpp"
#include "render/plot_canvas.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace furrow {

namespace {

constexpr int kPanel = 400;   // panel side for point maps and small grids [px]
constexpr int kMargin = 30;   // around panels, room for titles
constexpr int kLegend = 60;   // legend strip at the bottom

const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0);
const cv::Scalar kClear(200, 235, 200), kUnreachable(150, 150, 150), kDegenerate(0, 0, 0),
    kCrease(200, 0, 200), kFrame(80, 80, 80);

// BGR red from light (small excess) to dark (the largest).
cv::Scalar gouge_colour(double excess, double largest) {
  const double t = largest > 0 ? std::clamp(excess / largest, 0.0, 1.0) : 1.0;
  return cv::Scalar(170 * (1 - t), 170 * (1 - t), 255 - 90 * t);
}

cv::Scalar colour(const GougePoint& p, double largest) {
  switch (p.gouge.status) {
    case GougeStatus::clear: return kClear;
    case GougeStatus::gouge: return gouge_colour(p.gouge.max_excess, largest);
    case GougeStatus::unreachable: return kUnreachable;
    case GougeStatus::degenerate: return kDegenerate;
    case GougeStatus::concave_crease: return kCrease;
  }
  return kWhite;
}

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.45) {
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, kBlack, 1, cv::LINE_AA);
}

}  // namespace

std::string gouge_map_png(const Part& part, const Cutter& cutter,
                          const std::vector<GougePoint>& points, int grid) {
  const int cell = grid > 0 ? std::max(1, kPanel / grid) : 0;
  const int side = grid > 0 ? grid * cell : kPanel;
  const int faces = static_cast<int>(part.faces.size());
  const int width = std::max(faces * (side + kMargin) + kMargin, 560);
  const int height = side + 2 * kMargin + kLegend;
  cv::Mat img(height, width, CV_8UC3, kWhite);

  double largest = 0;
  std::vector<int> gouges(part.faces.size(), 0), counts(part.faces.size(), 0);
  for (const GougePoint& p : points) {
    ++counts[p.site.face];
    if (p.gouge.gouges()) {
      largest = std::max(largest, p.gouge.max_excess);
      ++gouges[p.site.face];
    }
  }
  for (const GougePoint& p : points) {
    const int x0 = kMargin + static_cast<int>(p.site.face) * (side + kMargin);
    const int y0 = kMargin;
    const cv::Scalar c = colour(p, largest);
    if (grid > 0 && p.site.grid_i >= 0) {
      // Node (i, j) fills its cell; v up.
      const int x = x0 + p.site.grid_i * cell, y = y0 + (grid - 1 - p.site.grid_j) * cell;
      cv::rectangle(img, cv::Rect(x, y, cell, cell), c, cv::FILLED);
    } else {
      const ParameterDomain& d = part.faces[p.site.face].domain();
      const double fu = (p.site.uv.x() - d.u0) / d.width_u(), fv = (p.site.uv.y() - d.v0) / d.width_v();
      const cv::Point at(x0 + static_cast<int>(fu * (side - 1)), y0 + static_cast<int>((1 - fv) * (side - 1)));
      cv::circle(img, at, 3, c, cv::FILLED, cv::LINE_8);
    }
  }
  for (int f = 0; f < faces; ++f) {
    const int x0 = kMargin + f * (side + kMargin);
    cv::rectangle(img, cv::Rect(x0 - 1, kMargin - 1, side + 2, side + 2), kFrame, 1);
    char title[200];
    std::snprintf(title, sizeof title, "%s: %d of %d gouge", part.faces[f].name().c_str(), gouges[f], counts[f]);
    text(img, title, cv::Point(x0, kMargin - 10));
    text(img, "u", cv::Point(x0 + side - 10, kMargin + side + 15), 0.4);
    text(img, "v", cv::Point(x0 - 14, kMargin + 10), 0.4);
  }
  const int ly = kMargin + side + 35;
  int lx = kMargin;
  const std::pair<cv::Scalar, const char*> legend[] = {
      {kClear, "clear"}, {gouge_colour(1, 2), "gouge"}, {gouge_colour(1, 1), "largest excess"},
      {kUnreachable, "unreachable"}, {kCrease, "concave crease"}};
  for (const auto& [c, label] : legend) {
    cv::rectangle(img, cv::Rect(lx, ly - 10, 12, 12), c, cv::FILLED);
    text(img, label, cv::Point(lx + 16, ly), 0.4);
    lx += 30 + 8 * static_cast<int>(std::string(label).size());
  }
  char tool[160];
  std::snprintf(tool, sizeof tool, "tool %s, largest excess %.4g /mm", cutter.name().c_str(), largest);
  text(img, tool, cv::Point(kMargin, ly + 20), 0.4);

  const std::vector<unsigned char> png = plot::encode_png(img);
  return std::string(png.begin(), png.end());
}

}  // namespace furrow
