#include "render/drawing_raster.hpp"

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "render/png.hpp"

namespace furrow {

namespace {

// Hershey simplex at scale 1 is about as tall as a 31 px DejaVu Sans: the
// SVG and the PNG of a figure then have text of the same size.
constexpr double kPixelsPerHersheyScale = 31.0;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kShift = 4;  // sub-pixel bits for cv drawing calls

cv::Scalar bgr(const Rgb& c) { return cv::Scalar(c[2], c[1], c[0]); }
cv::Point fixed_point(const Eigen::Vector2d& p) {
  return {static_cast<int>(std::lround(p.x() * (1 << kShift))), static_cast<int>(std::lround(p.y() * (1 << kShift)))};
}
int thickness(double width) { return std::max(1, static_cast<int>(std::lround(width))); }

std::string ascii(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      out += s[i];
    } else if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xB5) {
      out += 'u';  // MICRO SIGN
      ++i;
    } else if (c == 0xCE && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xBC) {
      out += 'u';  // GREEK SMALL LETTER MU
      ++i;
    } else if ((c & 0xC0) != 0x80) {
      out += '?';  // first byte of another character; continuation bytes dropped
    }
  }
  return out;
}

void draw_text(cv::Mat& img, const DrawItem& it) {
  const std::string s = ascii(it.text);
  const double scale = it.font_size / kPixelsPerHersheyScale;
  const int weight = it.bold ? 2 : 1;
  const cv::Scalar ink = bgr(it.fill.value_or(Drawing::kInk));
  int baseline = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, weight, &baseline);
  const double shift = it.anchor == TextAnchor::middle ? size.width / 2.0 : it.anchor == TextAnchor::end ? size.width : 0.0;
  const Eigen::Vector2d at = it.points[0];
  if (!it.vertical) {
    cv::putText(img, s, {static_cast<int>(std::lround(at.x() - shift)), static_cast<int>(std::lround(at.y()))}, kFont,
                scale, ink, weight, cv::LINE_AA);
    return;
  }
  // Turned text: drawn on a strip, rotated counter-clockwise, pasted so the
  // baseline runs up the line x = at.x from at.y (minus the anchor shift).
  cv::Mat strip(size.height + baseline + 4, size.width + 4, img.type(), bgr(Drawing::kPaper));
  cv::putText(strip, s, {2, size.height + 1}, kFont, scale, ink, weight, cv::LINE_AA);
  cv::Mat rotated;
  cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  const int left = static_cast<int>(std::lround(at.x())) - (size.height + 1);
  const int bottom = static_cast<int>(std::lround(at.y() + shift)) + 2;
  cv::Rect target(left, bottom - rotated.rows, rotated.cols, rotated.rows);
  const cv::Rect clipped = target & cv::Rect(0, 0, img.cols, img.rows);
  if (clipped.area() > 0)
    rotated(cv::Rect(clipped.x - target.x, clipped.y - target.y, clipped.width, clipped.height)).copyTo(img(clipped));
}

}  // namespace

std::vector<unsigned char> to_png(const Drawing& d) {
  cv::Mat img(d.height(), d.width(), CV_8UC3, bgr(Drawing::kPaper));
  for (const DrawItem& it : d.items()) {
    std::vector<cv::Point> pts;
    for (const Eigen::Vector2d& p : it.points) pts.push_back(fixed_point(p));
    switch (it.kind) {
      case DrawItem::Kind::line:
        if (it.stroke) cv::line(img, pts[0], pts[1], bgr(*it.stroke), thickness(it.stroke_width), cv::LINE_AA, kShift);
        break;
      case DrawItem::Kind::polyline:
        if (it.stroke && pts.size() >= 2)
          cv::polylines(img, pts, false, bgr(*it.stroke), thickness(it.stroke_width), cv::LINE_AA, kShift);
        break;
      case DrawItem::Kind::polygon:
        if (pts.size() < 3) break;
        if (it.fill) {
          if (it.opacity >= 1) {
            cv::fillPoly(img, std::vector<std::vector<cv::Point>>{pts}, bgr(*it.fill), cv::LINE_AA, kShift);
          } else {
            cv::Mat layer = img.clone();
            cv::fillPoly(layer, std::vector<std::vector<cv::Point>>{pts}, bgr(*it.fill), cv::LINE_AA, kShift);
            cv::addWeighted(layer, it.opacity, img, 1 - it.opacity, 0, img);
          }
        }
        if (it.stroke) cv::polylines(img, pts, true, bgr(*it.stroke), thickness(it.stroke_width), cv::LINE_AA, kShift);
        break;
      case DrawItem::Kind::circle: {
        const int r = static_cast<int>(std::lround(it.radius * (1 << kShift)));
        if (it.fill) cv::circle(img, pts[0], r, bgr(*it.fill), cv::FILLED, cv::LINE_AA, kShift);
        if (it.stroke) cv::circle(img, pts[0], r, bgr(*it.stroke), thickness(it.stroke_width), cv::LINE_AA, kShift);
        break;
      }
      case DrawItem::Kind::rect: {
        // Integer pixel edges: colour-bar bands tile without seams.
        const cv::Point a(static_cast<int>(std::lround(it.points[0].x())), static_cast<int>(std::lround(it.points[0].y())));
        const cv::Point b(static_cast<int>(std::lround(it.points[1].x())) - 1,
                          static_cast<int>(std::lround(it.points[1].y())) - 1);
        if (it.fill) cv::rectangle(img, a, b, bgr(*it.fill), cv::FILLED);
        if (it.stroke) cv::rectangle(img, a, b, bgr(*it.stroke), thickness(it.stroke_width));
        break;
      }
      case DrawItem::Kind::text:
        draw_text(img, it);
        break;
    }
  }
  return encode_png(ImageRows{img.cols, img.rows, img.channels(), img.data, img.step, true});
}

}  // namespace furrow
