// The 3D view's static figure (report/deviation_views.hpp): each measured
// point is a dot of its deviation's colour where the view sees its foot
// point. Oracle: the panels of the same four views (the cameras depend on
// the part alone) and DeviationScale's colour of each point's deviation.
#include <doctest/doctest.h>

#include <opencv2/imgcodecs.hpp>

#include "render/colour_scale.hpp"
#include "render/part_views.hpp"
#include "report/deviation_views.hpp"
#include "report_fixture.hpp"

using namespace furrow;

TEST_CASE("deviation views: every seen point is a dot of its deviation's colour at its foot") {
  const test::ReportFixture f = test::make_report_fixture();
  const double range = 0.1;
  const std::vector<unsigned char> png = deviation_views_png(f.doc, f.part, range);
  CHECK(png == deviation_views_png(f.doc, f.part, range));  // deterministic
  const cv::Mat img = cv::imdecode(png, cv::IMREAD_COLOR);
  const PartViewsFigure views = draw_part_views("", f.part, [](std::size_t, const Eigen::Vector2d&) {
    return SurfacePaint{};
  }, {});
  REQUIRE(img.cols == views.width);
  REQUIRE(img.rows == views.height);
  const DeviationScale scale{range};
  int checked = 0, matched = 0;
  for (const ViewPanel& panel : views.panels) {
    std::vector<Eigen::Vector2d> seen;
    for (const auto& p : f.doc.points)
      if (panel.raster.visible(p.foot, 1.5 / panel.raster.camera.scale)) seen.push_back(panel.to_figure(p.foot));
    for (const auto& p : f.doc.points) {
      if (!p.evaluated || !panel.raster.visible(p.foot, 1.5 / panel.raster.camera.scale)) continue;
      const Eigen::Vector2d at = panel.to_figure(p.foot);
      // Skip dots another dot may cover (drawn later, within 8 pixels).
      int close = 0;
      for (const Eigen::Vector2d& q : seen) close += (q - at).norm() < 8;
      if (close > 1) continue;
      ++checked;
      const cv::Vec3b got = img.at<cv::Vec3b>(static_cast<int>(std::lround(at.y())), static_cast<int>(std::lround(at.x())));
      const Rgb want = scale.colour(p.deviation);
      matched += std::abs(got[2] - want[0]) <= 2 && std::abs(got[1] - want[1]) <= 2 && std::abs(got[0] - want[2]) <= 2;
    }
  }
  CHECK(checked > 200);
  CHECK(matched == checked);
}
