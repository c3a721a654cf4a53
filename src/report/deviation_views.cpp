#include "report/deviation_views.hpp"

#include <cmath>

#include "render/part_views.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

std::vector<unsigned char> deviation_views_png(const ComparisonDocument& doc, const Part& part, double range,
                                               const std::string& named) {
  const Rgb surface{205, 205, 205}, not_evaluated{150, 150, 150};
  const SurfacePainter grey = [surface](std::size_t, const Eigen::Vector2d&) { return SurfacePaint{surface, -1}; };
  const std::string title =
      named.empty() ? "Measured points, " + std::to_string(doc.points.size()) + " at their foot points" : named;
  PartViewsFigure fig = draw_part_views(title, part, grey,
                                        {{surface, "part surface"}, {not_evaluated, "not evaluated"}});
  cv::Mat img(fig.height, fig.width, CV_8UC3, fig.bgr.data());
  const DeviationScale scale{range};
  const int dot = doc.points.size() > 5000 ? 2 : 3;
  for (const ViewPanel& panel : fig.panels) {
    cv::Mat view = img(cv::Rect(panel.left, panel.top, panel.raster.width, panel.raster.height));
    const double tolerance = 1.5 / panel.raster.camera.scale;
    for (const ComparisonDocument::Point& p : doc.points) {
      const Eigen::Vector2d at = panel.raster.camera.to_pixel(p.foot);
      const cv::Point c(static_cast<int>(std::lround(at.x())), static_cast<int>(std::lround(at.y())));
      if (!panel.raster.visible(p.foot, tolerance)) {
        cv::circle(view, c, dot, plot::bgr(not_evaluated), 1, cv::LINE_AA);
        continue;
      }
      const Rgb colour = p.evaluated ? scale.colour(p.deviation) : not_evaluated;
      cv::circle(view, c, dot, plot::bgr(colour), cv::FILLED, cv::LINE_AA);
      // A thin grey edge keeps a near-white (in tolerance) dot visible on the grey surface.
      if (!p.evaluated || p.in_tolerance == false)
        cv::circle(view, c, dot + 1, plot::kInk, 1, cv::LINE_AA);
      else
        cv::circle(view, c, dot, cv::Scalar(110, 110, 110), 1, cv::LINE_AA);
    }
  }
  const cv::Rect bar(fig.legend_left + 44, fig.legend_bottom + 40, 18, 260);  // room for "-tol" on its left
  plot::draw_colour_bar(img, bar, scale, doc.options.tolerance.lower(), doc.options.tolerance.upper(),
                        "deviation [um]");
  return part_views_png(fig);
}

}  // namespace furrow
