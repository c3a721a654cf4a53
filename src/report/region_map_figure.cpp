#include "report/region_map_figure.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "report/part_outlines.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

constexpr int kWidth = 900, kHeight = 640;
constexpr int kCells = 96;   // per face and direction: smooth enough at report size
constexpr int kShift = 4;    // sub-pixel bits for the filled cells

struct Cell {
  double z = 0;
  std::array<cv::Point, 4> corners;
  cv::Scalar colour;
};

cv::Point shifted(const plot::PlotArea& area, double x, double y) {
  const cv::Point2d p = area.to_pixel_exact(x, y);
  return {static_cast<int>(std::lround(p.x * (1 << kShift))), static_cast<int>(std::lround(p.y * (1 << kShift)))};
}

}  // namespace

std::vector<unsigned char> region_map_png(const std::string& title, const Part& part, const RegionMap& map) {
  // Surface nodes of every face, for the view's extent and the cells.
  std::vector<std::vector<Eigen::Vector3d>> nodes(part.faces.size());
  Eigen::AlignedBox2d bounds;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const ParameterDomain& d = part.faces[f].domain();
    for (int i = 0; i <= kCells; ++i)
      for (int j = 0; j <= kCells; ++j) {
        const Eigen::Vector3d p =
            part.faces[f].surface().point(d.u0 + d.width_u() * i / kCells, d.v0 + d.width_v() * j / kCells);
        nodes[f].push_back(p);
        bounds.extend(Eigen::Vector2d(p.x(), p.y()));
      }
  }
  if (bounds.isEmpty()) bounds.extend(Eigen::Vector2d(0, 0)).extend(Eigen::Vector2d(1, 1));
  const Eigen::Vector2d pad = 0.03 * bounds.sizes().cwiseMax(1e-9);
  cv::Mat img(kHeight, kWidth, CV_8UC3, plot::kPaper);
  plot::text(img, title, {20, 30}, 0.65);
  const plot::PlotArea area =
      plot::equal_aspect_area(cv::Rect(90, 55, kWidth - 90 - 190, kHeight - 55 - 70), bounds.min().x() - pad.x(),
                              bounds.max().x() + pad.x(), bounds.min().y() - pad.y(), bounds.max().y() + pad.y());
  area.draw_axes(img, "x [mm]", "y [mm]", false);

  std::vector<Cell> cells;
  std::map<std::string, int> classes_seen;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    const ParameterDomain& d = face.domain();
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j) {
        const double u = d.u0 + d.width_u() * (i + 0.5) / kCells, v = d.v0 + d.width_v() * (j + 0.5) / kCells;
        if (!face.contains(u, v)) continue;
        const std::optional<int> region = map.region_at(static_cast<int>(f), u, v);
        const char* cls = region ? to_string(map.regions[static_cast<std::size_t>(*region)].curvature_class) : "";
        if (region) classes_seen.emplace(cls, 0);
        Cell c;
        c.colour = plot::bgr(curvature_class_colour(cls));
        const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
        for (int k = 0; k < 4; ++k) {
          const Eigen::Vector3d& p = nodes[f][static_cast<std::size_t>(corner[k][0]) * (kCells + 1) + corner[k][1]];
          c.corners[static_cast<std::size_t>(k)] = shifted(area, p.x(), p.y());
          c.z += p.z() / 4;
        }
        cells.push_back(c);
      }
  }
  std::stable_sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.z < b.z; });
  for (const Cell& c : cells) cv::fillConvexPoly(img, c.corners.data(), 4, c.colour, cv::LINE_8, kShift);

  for (const Outline& o : face_outlines_xy(part)) {
    std::vector<cv::Point> pts;
    for (const auto& p : o) pts.push_back(area.to_pixel(p.x(), p.y()));
    cv::polylines(img, pts, false, cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
  }
  for (const Outline& o : region_borders_xy(map)) {
    std::vector<cv::Point> pts;
    for (const auto& p : o) pts.push_back(area.to_pixel(p.x(), p.y()));
    cv::polylines(img, pts, false, plot::kInk, 1, cv::LINE_AA);
  }
  for (const Region& r : map.regions) {
    const cv::Point at = area.to_pixel(r.interior_xyz.x(), r.interior_xyz.y());
    const std::string label = "R" + std::to_string(r.id);
    plot::text_centred(img, label, at, 0.45, plot::kPaper, 4);
    plot::text_centred(img, label, at, 0.45, plot::kInk, 1);
  }
  int y = 80;
  for (const auto& entry : classes_seen) {
    const cv::Rect swatch(kWidth - 175, y - 12, 18, 14);
    cv::rectangle(img, swatch, plot::bgr(curvature_class_colour(entry.first.c_str())), cv::FILLED);
    cv::rectangle(img, swatch, plot::kInk, 1);
    plot::text(img, entry.first, {kWidth - 150, y}, 0.45);
    y += 26;
  }
  return plot::encode_png(img);
}

}  // namespace furrow
