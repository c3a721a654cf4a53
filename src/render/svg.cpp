#include "render/svg.hpp"

#include <cmath>
#include <cstdio>

#include "base/text_fields.hpp"

namespace furrow {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) v = 0;  // a figure never writes NaN; a degenerate point lands at 0
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string xml_escape(const std::string& text) { return markup_escape(text); }

std::string colour(const Rgb& c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

std::string paint(const DrawItem& it) {
  std::string s = " fill=\"" + (it.fill ? colour(*it.fill) : std::string("none")) + "\"";
  if (it.fill && it.opacity < 1) s += " fill-opacity=\"" + num(it.opacity) + "\"";
  if (it.stroke) {
    s += " stroke=\"" + colour(*it.stroke) + "\"";
    if (it.stroke_width != 1) s += " stroke-width=\"" + num(it.stroke_width) + "\"";
  }
  return s;
}

std::string attributes(const DrawItem& it) {
  std::string s;
  if (!it.css_class.empty()) s += " class=\"" + xml_escape(it.css_class) + "\"";
  for (const auto& [name, value] : it.data) s += " data-" + xml_escape(name) + "=\"" + xml_escape(value) + "\"";
  return s;
}

std::string points_attribute(const std::vector<Eigen::Vector2d>& points) {
  std::string s;
  for (const Eigen::Vector2d& p : points) {
    if (!s.empty()) s += ' ';
    s += num(p.x()) + "," + num(p.y());
  }
  return s;
}

}  // namespace

std::string to_svg(const Drawing& d, const std::string& title, const std::string& id) {
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  if (!id.empty()) out += " id=\"" + xml_escape(id) + "\"";
  out += " class=\"figure\" viewBox=\"0 0 " + std::to_string(d.width()) + " " + std::to_string(d.height()) +
         "\" width=\"" + std::to_string(d.width()) + "\" height=\"" + std::to_string(d.height()) +
         "\" role=\"img\" font-family=\"DejaVu Sans,Helvetica,Arial,sans-serif\">\n<title>" + xml_escape(title) +
         "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  for (const DrawItem& it : d.items()) {
    switch (it.kind) {
      case DrawItem::Kind::line:
        out += "<line x1=\"" + num(it.points[0].x()) + "\" y1=\"" + num(it.points[0].y()) + "\" x2=\"" +
               num(it.points[1].x()) + "\" y2=\"" + num(it.points[1].y()) + "\"" + paint(it) + attributes(it) + "/>\n";
        break;
      case DrawItem::Kind::polyline:
        out += "<polyline points=\"" + points_attribute(it.points) + "\"" + paint(it) + attributes(it) + "/>\n";
        break;
      case DrawItem::Kind::polygon:
        out += "<polygon points=\"" + points_attribute(it.points) + "\"" + paint(it) + attributes(it) + "/>\n";
        break;
      case DrawItem::Kind::circle:
        out += "<circle cx=\"" + num(it.points[0].x()) + "\" cy=\"" + num(it.points[0].y()) + "\" r=\"" +
               num(it.radius) + "\"" + paint(it) + attributes(it) + "/>\n";
        break;
      case DrawItem::Kind::rect: {
        const Eigen::Vector2d size = it.points[1] - it.points[0];
        out += "<rect x=\"" + num(it.points[0].x()) + "\" y=\"" + num(it.points[0].y()) + "\" width=\"" +
               num(size.x()) + "\" height=\"" + num(size.y()) + "\"" + paint(it) + attributes(it) + "/>\n";
        break;
      }
      case DrawItem::Kind::text: {
        const char* anchor = it.anchor == TextAnchor::middle ? "middle" : it.anchor == TextAnchor::end ? "end" : "start";
        const std::string x = num(it.points[0].x()), y = num(it.points[0].y());
        out += "<text x=\"" + x + "\" y=\"" + y + "\" font-size=\"" + num(it.font_size) + "\"";
        if (it.anchor != TextAnchor::start) out += std::string(" text-anchor=\"") + anchor + "\"";
        if (it.bold) out += " font-weight=\"bold\"";
        if (it.vertical) out += " transform=\"rotate(-90 " + x + " " + y + ")\"";
        out += " fill=\"" + colour(it.fill.value_or(Drawing::kInk)) + "\"" + attributes(it) + ">" +
               xml_escape(it.text) + "</text>\n";
        break;
      }
    }
  }
  return out + "</svg>\n";
}

}  // namespace furrow
