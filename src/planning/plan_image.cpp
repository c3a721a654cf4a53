#include "planning/plan_image.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "partition/region_paint.hpp"
#include "render/part_views.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

const Rgb kStraight{10, 40, 120}, kOver{150, 190, 230}, kMoved{255, 140, 0}, kDropped{220, 40, 40};
const Rgb kGouge{200, 40, 200}, kFirst{40, 170, 60}, kHidden{150, 150, 150};

cv::Point pixel(const ViewPanel& panel, const Eigen::Vector3d& p) {
  const Eigen::Vector2d at = panel.to_figure(p);
  return {static_cast<int>(std::lround(at.x())), static_cast<int>(std::lround(at.y()))};
}

// The plan's marks in one panel; a point the view does not see is a grey ring.
void draw_marks(cv::Mat& img, const ViewPanel& panel, const PlanResult& result) {
  const cv::Rect clip(panel.left, panel.top, panel.raster.width, panel.raster.height);
  cv::Mat view = img(clip);
  const cv::Point shift(-panel.left, -panel.top);
  auto at = [&](const Eigen::Vector3d& p) { return pixel(panel, p) + shift; };
  const double tolerance = 1.5 / panel.raster.camera.scale;
  const std::vector<PlannedPoint>& points = result.plan.points;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const bool straight = result.moves[k].straight;
    cv::line(view, at(points[k - 1].xyz), at(points[k].xyz), plot::bgr(straight ? kStraight : kOver), 1, cv::LINE_AA);
  }
  for (const PlanIssue& issue : result.issues)
    if (issue.kind == PlanIssue::Kind::dropped) {
      const cv::Point c = at(issue.where);
      cv::line(view, c + cv::Point(-4, -4), c + cv::Point(4, 4), plot::bgr(kDropped), 2, cv::LINE_AA);
      cv::line(view, c + cv::Point(-4, 4), c + cv::Point(4, -4), plot::bgr(kDropped), 2, cv::LINE_AA);
    }
  const int dot = points.size() > 1500 ? 1 : 2;
  for (const PlannedPoint& p : points) {
    if (panel.raster.visible(p.xyz, tolerance))
      cv::circle(view, at(p.xyz), dot, plot::kInk, cv::FILLED, cv::LINE_AA);
    else
      cv::circle(view, at(p.xyz), dot + 1, plot::bgr(kHidden), 1, cv::LINE_AA);
  }
  for (std::size_t k = 0; k < points.size() && k < result.point_sites.size(); ++k)
    if (!result.point_sites[k].empty()) {
      const cv::Point c = at(points[k].xyz);
      cv::rectangle(view, c - cv::Point(4, 4), c + cv::Point(4, 4), plot::bgr(kGouge), 2, cv::LINE_AA);
    }
  for (const PlanIssue& issue : result.issues)
    if (issue.kind == PlanIssue::Kind::moved) {
      const auto it = std::find_if(points.begin(), points.end(), [&](const PlannedPoint& p) { return p.id == issue.point; });
      if (it != points.end()) cv::circle(view, at(it->xyz), 5, plot::bgr(kMoved), 2, cv::LINE_AA);
    }
  if (!points.empty()) {
    cv::circle(view, at(points.front().xyz), 6, plot::bgr(kFirst), cv::FILLED, cv::LINE_AA);
    const cv::Point e = at(points.back().xyz);
    cv::rectangle(view, e - cv::Point(5, 5), e + cv::Point(5, 5), plot::bgr(kDropped), cv::FILLED);
  }
}

}  // namespace

std::vector<unsigned char> plan_image_png(const Part& part, const RegionMap& map, const PlanResult& result) {
  return plan_image_png(map, result, part_view_panels(part));
}

std::vector<unsigned char> plan_image_png(const RegionMap& map, const PlanResult& result, PartViewPanels views) {
  std::vector<LegendEntry> legend = class_legend(map);
  const LegendEntry marks[] = {{kStraight, "straight move"},    {kOver, "over clearance plane"},
                               {Rgb{35, 35, 35}, "point"},      {kHidden, "point hidden in view"},
                               {kMoved, "moved"},               {kGouge, "on a gouge site"},
                               {kFirst, "first point"},         {kDropped, "dropped / last"}};
  legend.insert(legend.end(), std::begin(marks), std::end(marks));
  const std::string title = "Probe plan: " + std::to_string(result.plan.points.size()) + " points";
  PartViewsFigure fig = draw_part_views(title, std::move(views), region_map_painter(map), legend);
  cv::Mat img(fig.height, fig.width, CV_8UC3, fig.bgr.data());
  for (const ViewPanel& panel : fig.panels) draw_marks(img, panel, result);
  return part_views_png(fig);
}

}  // namespace furrow
