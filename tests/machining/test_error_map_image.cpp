// The error-map picture's markers: drawn where their (u, v) is coloured.
#include <doctest/doctest.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/primitives.hpp"
#include "machining/prediction/error_map_image.hpp"

using namespace furrow;

namespace {

cv::Mat decode(const std::string& png) {
  const std::vector<unsigned char> bytes(png.begin(), png.end());
  return cv::imdecode(bytes, cv::IMREAD_COLOR);
}

// A 60 x 30 mm plane whose map is zero except one sample.
struct OneSample {
  Part part;
  ErrorMap map;
  int i0 = 15, j0 = 22;
  OneSample() {
    part.faces.emplace_back("plate", make_plane({0, 0, 0}, {60, 0, 0}, {0, 30, 0}));
    FaceErrorMap m;
    m.face = 0;
    m.domain = part.faces[0].domain();
    m.cells_u = m.nu = 60;
    m.cells_v = m.nv = 30;
    m.error.assign(60 * 30, 0.0f);
    m.status.assign(60 * 30, ErrorCellStatus::reached);
    m.error[m.index(i0, j0)] = 0.02f;
    map.faces.push_back(m);
  }
};

}  // namespace

TEST_CASE("error map picture: a marker rings the sample at its (u, v), off the face it is not drawn") {
  const OneSample s;
  ErrorImageOptions plain;
  const cv::Mat a = decode(error_map_png(s.part, s.map, plain));
  REQUIRE(!a.empty());
  // Where the one red sample is, left of the colour bar (whose top is as red).
  double rx = 0, ry = 0;
  int red = 0;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols - 150; ++x) {
      const cv::Vec3b c = a.at<cv::Vec3b>(y, x);
      if (c[2] > 150 && c[1] < 60 && c[0] < 60) rx += x, ry += y, ++red;
    }
  REQUIRE(red > 50);  // a 15 x 15 pixel block at 900 pixels for 60 samples
  rx /= red, ry /= red;

  ErrorImageOptions marked = plain;
  const FaceErrorMap& m = s.map.faces[0];
  marked.markers.push_back({0, {m.u(s.i0), m.v(s.j0)}, "C"});
  const cv::Mat b = decode(error_map_png(s.part, s.map, marked));
  REQUIRE(b.size() == a.size());
  // The ring (outer radius 8.5 px) is symmetric about its centre: the
  // changed pixels near the red block average to it; the label starts
  // 10 px to the right, outside the window.
  double cx = 0, cy = 0;
  int changed = 0;
  for (int y = static_cast<int>(ry) - 9; y <= static_cast<int>(ry) + 9; ++y)
    for (int x = static_cast<int>(rx) - 9; x <= static_cast<int>(rx) + 9; ++x)
      if (a.at<cv::Vec3b>(y, x) != b.at<cv::Vec3b>(y, x)) cx += x, cy += y, ++changed;
  REQUIRE(changed > 20);
  CHECK(std::fabs(cx / changed - rx) < 1.5);
  CHECK(std::fabs(cy / changed - ry) < 1.5);
  // The label is drawn too: something changed right of the ring.
  int label = 0;
  for (int y = static_cast<int>(ry) - 20; y <= static_cast<int>(ry); ++y)
    for (int x = static_cast<int>(rx) + 10; x <= static_cast<int>(rx) + 25; ++x)
      label += a.at<cv::Vec3b>(y, x) != b.at<cv::Vec3b>(y, x);
  CHECK(label > 5);

  // Outside the face's domain, or on a face the map does not have: nothing.
  ErrorImageOptions off = plain;
  off.markers.push_back({0, {m.domain.u1 + 0.1 * m.domain.width_u(), m.v(3)}, "X"});
  off.markers.push_back({3, {m.u(3), m.v(3)}, "Y"});
  CHECK(error_map_png(s.part, s.map, off) == error_map_png(s.part, s.map, plain));
}

TEST_CASE("error map picture: each note is a line under the legend") {
  const OneSample s;
  ErrorImageOptions plain, noted;
  noted.notes = {"along the passes (per step): largest furrow 10.0 um (F)", "between passes: cusp 5.0 um (C)"};
  const cv::Mat a = decode(error_map_png(s.part, s.map, plain));
  const cv::Mat b = decode(error_map_png(s.part, s.map, noted));
  REQUIRE(a.cols == b.cols);
  CHECK(b.rows == a.rows + 2 * 20);
  // The picture above the notes is unchanged.
  CHECK(cv::norm(a, b(cv::Rect(0, 0, a.cols, a.rows)), cv::NORM_INF) == 0);
}
