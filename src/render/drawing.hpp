#pragma once
// One description of a figure, two back ends: a Drawing is a list of
// primitives (lines, polylines, filled polygons, circles, rectangles, text)
// in pixel coordinates (origin top left, y down, like SVG and images), and
// it is turned either into SVG text (render/svg.hpp: crisp at any zoom, text
// selectable, real glyphs such as "µm") or into a raster image
// (render/drawing_raster.hpp: PNG, for very large maps and figure files).
// Why one description: a figure is written once, so the vector and the
// raster version cannot drift apart.
//
// Text is UTF-8; the raster back end has only ASCII glyphs (OpenCV's Hershey
// font) and writes "u" for "µ". Font sizes are in pixels (the SVG
// font-size); a baseline position anchors text at its start, middle or end.
// Items may carry a CSS class and data-* attributes, which only the SVG
// keeps (so tests and scripts can find, e.g., a point's label by its id).
// Deterministic: the same calls give the same SVG bytes and the same pixels.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/colour_scale.hpp"

namespace furrow {

enum class TextAnchor { start, middle, end };

struct DrawItem {
  enum class Kind { line, polyline, polygon, circle, rect, text };
  Kind kind = Kind::line;
  // line: 2 points; polyline/polygon: the vertices; circle: the centre;
  // rect: two opposite corners; text: the anchor on the baseline.
  std::vector<Eigen::Vector2d> points;
  double radius = 0;                // circle [px]
  std::optional<Rgb> fill;          // none: not filled
  std::optional<Rgb> stroke;        // none: no outline
  double stroke_width = 1;          // [px]
  double opacity = 1;               // of the fill, in [0, 1]
  std::string text;                 // UTF-8
  double font_size = 12;            // [px]
  TextAnchor anchor = TextAnchor::start;
  bool vertical = false;            // text turned 90 degrees counter-clockwise
  bool bold = false;
  std::string css_class;                                   // SVG only
  std::vector<std::pair<std::string, std::string>> data;   // SVG data-NAME="value"
};

class Drawing {
 public:
  // Preconditions: width, height > 0. The background is white.
  Drawing(int width, int height) : width_(width), height_(height) {}
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<DrawItem>& items() const { return items_; }

  // Each returns the item, so a caller can add a class or data attributes.
  DrawItem& line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, double width = 1);
  DrawItem& polyline(const std::vector<Eigen::Vector2d>& points, const Rgb& colour, double width = 1);
  DrawItem& polygon(const std::vector<Eigen::Vector2d>& points, const Rgb& fill, double opacity = 1,
                    std::optional<Rgb> stroke = std::nullopt, double stroke_width = 1);
  DrawItem& circle(const Eigen::Vector2d& centre, double radius, std::optional<Rgb> fill,
                   std::optional<Rgb> stroke = std::nullopt, double stroke_width = 1);
  DrawItem& rect(const Eigen::Vector2d& corner, const Eigen::Vector2d& opposite, std::optional<Rgb> fill,
                 std::optional<Rgb> stroke = std::nullopt, double stroke_width = 1);
  DrawItem& text(const std::string& s, const Eigen::Vector2d& baseline, double font_size,
                 TextAnchor anchor = TextAnchor::start, const Rgb& colour = kInk);

  static constexpr Rgb kInk{35, 35, 35};
  static constexpr Rgb kPaper{255, 255, 255};

 private:
  int width_, height_;
  std::vector<DrawItem> items_;
};

}  // namespace furrow
