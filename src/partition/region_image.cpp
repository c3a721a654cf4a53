#include "partition/region_image.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "partition/face_grid.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

// The curvature-class colours every figure uses (render/colour_scale.hpp),
// in OpenCV's BGR order.
cv::Vec3b class_colour(CurvatureClass c) {
  const Rgb rgb = curvature_class_colour(to_string(c));
  return {rgb[2], rgb[1], rgb[0]};
}
const cv::Vec3b kTrimmedColour{222, 222, 222};
const cv::Vec3b kDegenerateColour{110, 110, 110};
const cv::Scalar kInk(30, 30, 30), kPaper(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kMargin = 14, kTitleHeight = 30, kLegendHeight = 40;

int panel_size(std::size_t faces) {
  if (faces <= 1) return 900;
  if (faces <= 4) return 560;
  if (faces <= 9) return 420;
  return 300;
}

void outlined_text(cv::Mat& img, const std::string& text, cv::Point at, double scale, int weight) {
  cv::putText(img, text, at, kFont, scale, kPaper, weight + 3, cv::LINE_AA);
  cv::putText(img, text, at, kFont, scale, kInk, weight, cv::LINE_AA);
}

// The face's cells as an image: rows = v from the top (v1) down, columns = u.
cv::Mat class_image(const FaceCells& cells, const RegionMap& map) {
  const RegionLabels& L = cells.labels;
  cv::Mat img(L.nv, L.nu, CV_8UC3);
  for (int i = 0; i < L.nu; ++i) {
    for (int j = 0; j < L.nv; ++j) {
      const int l = L.at(i, j);
      const unsigned char code = cells.cell_class[static_cast<std::size_t>(i) * L.nv + j];
      cv::Vec3b colour = code == kDegenerateCell ? kDegenerateColour : kTrimmedColour;
      if (l >= 0) {
        const Region& r = map.regions[static_cast<std::size_t>(cells.first_id + l)];
        colour = class_colour(r.curvature_class);
      }
      img.at<cv::Vec3b>(L.nv - 1 - j, i) = colour;
    }
  }
  return img;
}

void draw_panel(cv::Mat& canvas, cv::Rect plot, const Face& face, const RegionFace& info,
                const FaceCells& cells, const RegionMap& map, int face_index) {
  cv::Mat fill;
  cv::resize(class_image(cells, map), fill, plot.size(), 0, 0, cv::INTER_NEAREST);
  fill.copyTo(canvas(plot));
  const ParameterDomain& d = info.domain;
  constexpr int kShift = 4;  // sub-pixel precision for polylines
  const double scale = 1 << kShift;
  auto to_pixel = [&](const Eigen::Vector2d& uv) {
    const double x = plot.x + (uv.x() - d.u0) / d.width_u() * plot.width;
    const double y = plot.y + plot.height - (uv.y() - d.v0) / d.width_v() * plot.height;
    return cv::Point(static_cast<int>(std::lround(x * scale)), static_cast<int>(std::lround(y * scale)));
  };
  for (int id : info.regions) {
    for (const BorderLoop& loop : map.regions[static_cast<std::size_t>(id)].border) {
      std::vector<cv::Point> pts;
      pts.reserve(loop.uv.size());
      for (const Eigen::Vector2d& p : loop.uv) pts.push_back(to_pixel(p));
      cv::polylines(canvas, pts, true, kInk, 1, cv::LINE_AA, kShift);
    }
  }
  cv::rectangle(canvas, plot, kInk, 1);
  const double text_scale = plot.width >= 500 ? 0.7 : 0.5;
  for (int id : info.regions) {
    const Region& r = map.regions[static_cast<std::size_t>(id)];
    const std::string text = std::to_string(id);
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, kFont, text_scale, 2, &baseline);
    const cv::Point c = to_pixel(r.interior_uv);
    outlined_text(canvas, text, {c.x / (1 << kShift) - size.width / 2, c.y / (1 << kShift) + size.height / 2},
                  text_scale, 2);
  }
  std::string title = "face " + std::to_string(face_index) + " \"" + face.name() + "\": " +
                      std::to_string(info.regions.size()) + " regions";
  cv::putText(canvas, title, {plot.x, plot.y - 10}, kFont, 0.5, kInk, 1, cv::LINE_AA);
  cv::putText(canvas, "u", {plot.x + plot.width - 10, plot.y + plot.height + 14}, kFont, 0.42, kInk, 1,
              cv::LINE_AA);
  cv::putText(canvas, "v", {plot.x - 11, plot.y + 10}, kFont, 0.42, kInk, 1, cv::LINE_AA);
}

void draw_legend(cv::Mat& canvas, int top) {
  struct Entry {
    cv::Vec3b colour;
    const char* text;
  };
  const Entry entries[] = {{class_colour(CurvatureClass::convex), "convex (bulges toward the tool)"},
                           {class_colour(CurvatureClass::concave), "concave"},
                           {class_colour(CurvatureClass::saddle), "saddle"},
                           {class_colour(CurvatureClass::planar), "planar"},
                           {kTrimmedColour, "trimmed"},
                           {kDegenerateColour, "degenerate"}};
  int x = kMargin;
  for (const Entry& e : entries) {
    const cv::Rect swatch(x, top + 12, 16, 16);
    cv::rectangle(canvas, swatch, cv::Scalar(e.colour[0], e.colour[1], e.colour[2]), cv::FILLED);
    cv::rectangle(canvas, swatch, kInk, 1);
    cv::putText(canvas, e.text, {x + 22, top + 25}, kFont, 0.45, kInk, 1, cv::LINE_AA);
    int baseline = 0;
    x += 22 + cv::getTextSize(e.text, kFont, 0.45, 1, &baseline).width + 18;
  }
}

}  // namespace

std::vector<unsigned char> region_image_png(const Part& part, const PartitionResult& result) {
  const std::size_t n = part.faces.size();
  if (result.cells.size() != n || result.map.faces.size() != n)
    throw std::logic_error("region image: the partition does not belong to the part");
  const int side = panel_size(n);
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = static_cast<int>((n + columns - 1) / columns);
  // Plot sizes first (aspect from the face's size on the surface, limited so
  // that a long thin face still gets a readable strip), then the layout.
  std::vector<cv::Size> plots;
  std::vector<int> row_height(static_cast<std::size_t>(rows), 0);
  for (std::size_t f = 0; f < n; ++f) {
    const FaceExtent e = face_extent(part.faces[f]);
    double aspect = (e.length_u > 0 && e.length_v > 0) ? e.length_u / e.length_v : 1.0;
    aspect = std::clamp(aspect, 0.25, 4.0);
    const int w = aspect >= 1 ? side : std::max(1, static_cast<int>(std::lround(side * aspect)));
    const int h = aspect >= 1 ? std::max(1, static_cast<int>(std::lround(side / aspect))) : side;
    plots.emplace_back(w, h);
    int& rh = row_height[f / static_cast<std::size_t>(columns)];
    rh = std::max(rh, h + kTitleHeight + 2 * kMargin);
  }
  std::vector<int> row_top(static_cast<std::size_t>(rows) + 1, 0);
  for (int r = 0; r < rows; ++r) row_top[r + 1] = row_top[r] + row_height[r];
  const int cell_w = side + 2 * kMargin;
  const int width = std::max(columns * cell_w, 760);
  cv::Mat canvas(row_top[rows] + kLegendHeight, width, CV_8UC3, kPaper);
  for (std::size_t f = 0; f < n; ++f) {
    const int col = static_cast<int>(f) % columns, row = static_cast<int>(f) / columns;
    const cv::Rect plot(col * cell_w + kMargin, row_top[row] + kMargin + kTitleHeight,
                        plots[f].width, plots[f].height);
    draw_panel(canvas, plot, part.faces[f], result.map.faces[f], result.cells[f], result.map,
               static_cast<int>(f));
  }
  draw_legend(canvas, row_top[rows]);
  const std::vector<unsigned char> png = plot::encode_png(canvas);
  return png;
}

}  // namespace furrow
