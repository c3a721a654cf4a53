#include <doctest/doctest.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>

#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "render/colour_scale.hpp"
#include "render/part_views.hpp"
#include "report/part_outlines.hpp"
#include "report/region_map_figure.hpp"

using namespace furrow;

namespace {

// Pixels painted with `c` under some light: the figure shades a colour by
// one factor in [0.45, 1] on all three channels (PartViewsFigure::shaded).
int pixels_of(const cv::Mat& img, const Rgb& c) {
  std::vector<Rgb> shades;
  for (int k = 0; k <= 1000; ++k) shades.push_back(PartViewsFigure::shaded(c, static_cast<float>(k / 1000.0)));
  std::sort(shades.begin(), shades.end());
  int n = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      n += std::binary_search(shades.begin(), shades.end(), Rgb{p[2], p[1], p[0]});
    }
  return n;
}

}  // namespace

TEST_CASE("the region map paints exactly the classes of the partition") {
  // two_face: a concave valley wall next to a convex crown, saddle strips
  // along their outer edges - and nothing planar.
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/two_face.json");
  PartitionOptions options;
  options.grid = GridSize{60, 40};
  const RegionMap map = partition_part(part, options).map;
  bool present[kCurvatureClassCount] = {false, false, false, false};
  for (const Region& r : map.regions) present[static_cast<int>(r.curvature_class)] = true;
  REQUIRE(present[static_cast<int>(CurvatureClass::concave)]);
  REQUIRE(present[static_cast<int>(CurvatureClass::convex)]);
  REQUIRE(present[static_cast<int>(CurvatureClass::saddle)]);
  REQUIRE_FALSE(present[static_cast<int>(CurvatureClass::planar)]);

  const std::vector<unsigned char> png = region_map_png("two faces", part, map);
  CHECK(png == region_map_png("two faces", part, map));  // deterministic
  const cv::Mat img = cv::imdecode(png, cv::IMREAD_COLOR);
  REQUIRE_FALSE(img.empty());
  for (int k = 0; k < kCurvatureClassCount; ++k) {
    const char* name = to_string(static_cast<CurvatureClass>(k));
    const int n = pixels_of(img, curvature_class_colour(name));
    INFO(name << ": " << n << " pixels");
    if (present[k])
      CHECK(n > 2000);  // regions' worth of area, not a legend swatch (18 x 14)
    else
      CHECK(n == 0);
  }
}

TEST_CASE("outlines follow the face boundary on the surface") {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const std::vector<Outline> xy = face_outlines_xy(part, 8);
  REQUIRE(xy.size() == 1);
  // Closed, 4 sides of 8 pieces, every vertex a boundary point of the surface
  // (the mould spans 0..100 x 0..80 mm, its border on that rectangle).
  REQUIRE(xy[0].size() == 33);
  CHECK((xy[0].front() - xy[0].back()).norm() == 0);
  for (const Eigen::Vector2d& p : xy[0]) {
    const double to_edge = std::min({std::fabs(p.x()), std::fabs(p.x() - 100), std::fabs(p.y()), std::fabs(p.y() - 80)});
    CHECK(to_edge < 1e-9);
  }
  const ParameterDomain& d = part.faces[0].domain();
  const Outline box = uv_box_outline_xy(part.faces[0], Eigen::AlignedBox2d(Eigen::Vector2d(d.u0 - 1, d.v0), Eigen::Vector2d(d.u1, d.v1 + 5)), 4);
  // Clamped to the domain: the same rectangle as the face outline.
  for (const Eigen::Vector2d& p : box) {
    const double to_edge = std::min({std::fabs(p.x()), std::fabs(p.x() - 100), std::fabs(p.y()), std::fabs(p.y() - 80)});
    CHECK(to_edge < 1e-9);
  }
}
