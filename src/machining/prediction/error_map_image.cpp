#include "machining/prediction/error_map_image.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "base/number_text.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

const cv::Vec3b kNotReached(215, 215, 215);  // BGR
const cv::Vec3b kNotMachinable(110, 110, 110);
const cv::Vec3b kOutside(255, 255, 255);

// Diverging blue - white - red for t in [-1, 1].
cv::Vec3b colour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const double a = std::fabs(t);
  // From white to a saturated end colour (red (200, 30, 30) or blue (30, 60, 200) in RGB).
  const double r_end = t > 0 ? 200 : 30, g_end = t > 0 ? 30 : 60, b_end = t > 0 ? 30 : 200;
  auto mix = [a](double end) { return static_cast<unsigned char>(std::lround(255 + a * (end - 255))); };
  return cv::Vec3b(mix(b_end), mix(g_end), mix(r_end));
}

cv::Mat face_image(const FaceErrorMap& m, double aspect, const ErrorImageOptions& o) {
  // aspect = surface length along v / along u.
  const int w = aspect <= 1 ? o.max_side : std::max(8, static_cast<int>(std::lround(o.max_side / aspect)));
  const int h = aspect <= 1 ? std::max(8, static_cast<int>(std::lround(o.max_side * aspect))) : o.max_side;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = std::min(m.nu - 1, static_cast<int>((x + 0.5) * m.nu / w));
      const int j = std::min(m.nv - 1, static_cast<int>((h - 1 - y + 0.5) * m.nv / h));  // v up
      const std::size_t k = m.index(i, j);
      cv::Vec3b c = kOutside;
      switch (m.status[k]) {
        case ErrorCellStatus::reached: c = colour(m.error[k] / o.scale); break;
        case ErrorCellStatus::not_reached: c = kNotReached; break;
        case ErrorCellStatus::not_machinable: c = kNotMachinable; break;
        case ErrorCellStatus::outside: break;
      }
      img.at<cv::Vec3b>(y, x) = c;
    }
  cv::rectangle(img, cv::Point(0, 0), cv::Point(w - 1, h - 1), cv::Scalar(60, 60, 60), 1);
  return img;
}

// Legend labels: the zero as "0".
std::string micrometres(double mm) {
  const std::string s = signed_fixed(mm * 1000, 1);
  return s == "0.0" ? "0" : s;
}

}  // namespace

std::string error_map_png(const Part& part, const ErrorMap& map, const ErrorImageOptions& o) {
  if (!(o.scale > 0) || !std::isfinite(o.scale)) throw std::invalid_argument("error map image: scale must be positive");
  const int margin = 30, title = 34, bar_w = 24, bar_labels = 90;
  std::vector<cv::Mat> pictures;
  int width = margin, height = 0;
  for (const FaceErrorMap& m : map.faces) {
    const Eigen::Vector2d len = face_extent_lengths(part.faces[m.face]);
    const double aspect = len.x() > 0 ? len.y() / len.x() : 1.0;
    pictures.push_back(face_image(m, aspect, o));
    width += pictures.back().cols + margin;
    height = std::max(height, pictures.back().rows);
  }
  const int bar_h = std::max(height, 200);
  const int note_h = 20;
  width += bar_w + bar_labels;
  cv::Mat canvas(title + bar_h + 2 * margin + note_h * static_cast<int>(o.notes.size()), width, CV_8UC3,
                 cv::Scalar(255, 255, 255));
  int x = margin;
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  for (std::size_t f = 0; f < pictures.size(); ++f) {
    const cv::Mat& pic = pictures[f];
    pic.copyTo(canvas(cv::Rect(x, title + margin, pic.cols, pic.rows)));
    cv::putText(canvas, part.faces[map.faces[f].face].name() + "  (u right, v up)", cv::Point(x, title + 8), font, 0.5,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    const ParameterDomain& d = map.faces[f].domain;
    for (const MapMarker& m : o.markers) {
      if (m.face != map.faces[f].face) continue;
      // The same pixel grid as face_image: u to the right, v up.
      const double fu = (m.uv.x() - d.u0) / d.width_u(), fv = (m.uv.y() - d.v0) / d.width_v();
      if (!(fu >= 0 && fu <= 1 && fv >= 0 && fv <= 1)) continue;
      const cv::Point c(x + static_cast<int>(std::lround(fu * (pic.cols - 1))),
                        title + margin + static_cast<int>(std::lround((1 - fv) * (pic.rows - 1))));
      cv::circle(canvas, c, 7, cv::Scalar(255, 255, 255), 3, cv::LINE_AA);
      cv::circle(canvas, c, 7, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
      cv::putText(canvas, m.label, c + cv::Point(10, -6), font, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    }
    x += pic.cols + margin;
  }
  // Colour bar: +scale at the top, -scale at the bottom.
  const int top = title + margin;
  for (int y = 0; y < bar_h; ++y) {
    const double t = 1.0 - 2.0 * (y + 0.5) / bar_h;
    cv::line(canvas, cv::Point(x, top + y), cv::Point(x + bar_w - 1, top + y), cv::Scalar(colour(t)), 1);
  }
  cv::rectangle(canvas, cv::Point(x, top), cv::Point(x + bar_w - 1, top + bar_h - 1), cv::Scalar(60, 60, 60), 1);
  for (int k = 0; k <= 4; ++k) {
    const int y = top + static_cast<int>(std::lround(k * (bar_h - 1) / 4.0));
    const double value = o.scale * (1.0 - k / 2.0);
    cv::line(canvas, cv::Point(x + bar_w, y), cv::Point(x + bar_w + 4, y), cv::Scalar(0, 0, 0), 1);
    cv::putText(canvas, micrometres(value), cv::Point(x + bar_w + 7, y + 5), font, 0.45, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
  }
  cv::putText(canvas, "error [um]", cv::Point(x - 10, title + 8), font, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  cv::putText(canvas, "+ material left, - overcut; grey: not reached", cv::Point(margin, top + bar_h + 22), font, 0.45,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  for (std::size_t k = 0; k < o.notes.size(); ++k)
    cv::putText(canvas, o.notes[k], cv::Point(margin, top + bar_h + 22 + note_h * static_cast<int>(k + 1)), font, 0.45,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  const std::vector<unsigned char> bytes = plot::encode_png(canvas);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace furrow
