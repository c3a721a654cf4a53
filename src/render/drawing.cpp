#include "render/drawing.hpp"

namespace furrow {

DrawItem& Drawing::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, double width) {
  DrawItem it;
  it.kind = DrawItem::Kind::line;
  it.points = {a, b};
  it.stroke = colour;
  it.stroke_width = width;
  items_.push_back(std::move(it));
  return items_.back();
}

DrawItem& Drawing::polyline(const std::vector<Eigen::Vector2d>& points, const Rgb& colour, double width) {
  DrawItem it;
  it.kind = DrawItem::Kind::polyline;
  it.points = points;
  it.stroke = colour;
  it.stroke_width = width;
  items_.push_back(std::move(it));
  return items_.back();
}

DrawItem& Drawing::polygon(const std::vector<Eigen::Vector2d>& points, const Rgb& fill, double opacity,
                           std::optional<Rgb> stroke, double stroke_width) {
  DrawItem it;
  it.kind = DrawItem::Kind::polygon;
  it.points = points;
  it.fill = fill;
  it.opacity = opacity;
  it.stroke = stroke;
  it.stroke_width = stroke_width;
  items_.push_back(std::move(it));
  return items_.back();
}

DrawItem& Drawing::circle(const Eigen::Vector2d& centre, double radius, std::optional<Rgb> fill,
                          std::optional<Rgb> stroke, double stroke_width) {
  DrawItem it;
  it.kind = DrawItem::Kind::circle;
  it.points = {centre};
  it.radius = radius;
  it.fill = fill;
  it.stroke = stroke;
  it.stroke_width = stroke_width;
  items_.push_back(std::move(it));
  return items_.back();
}

DrawItem& Drawing::rect(const Eigen::Vector2d& corner, const Eigen::Vector2d& opposite, std::optional<Rgb> fill,
                        std::optional<Rgb> stroke, double stroke_width) {
  DrawItem it;
  it.kind = DrawItem::Kind::rect;
  it.points = {corner.cwiseMin(opposite), corner.cwiseMax(opposite)};
  it.fill = fill;
  it.stroke = stroke;
  it.stroke_width = stroke_width;
  items_.push_back(std::move(it));
  return items_.back();
}

DrawItem& Drawing::text(const std::string& s, const Eigen::Vector2d& baseline, double font_size,
                        TextAnchor anchor, const Rgb& colour) {
  DrawItem it;
  it.kind = DrawItem::Kind::text;
  it.points = {baseline};
  it.text = s;
  it.font_size = font_size;
  it.anchor = anchor;
  it.fill = colour;
  items_.push_back(std::move(it));
  return items_.back();
}

}  // namespace furrow
