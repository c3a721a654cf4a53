#include "planning/coverage_image.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <opencv2/imgproc.hpp>

#include "render/colour_scale.hpp"
#include "render/part_views.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

const Rgb kOutsideRegions{215, 215, 215}, kHiddenPoint{150, 150, 150};

}  // namespace

Rgb coverage_colour(CoverageState state) {
  switch (state) {
    case CoverageState::covered: return {90, 175, 90};
    case CoverageState::reachable_unplanned: return {240, 180, 40};
    case CoverageState::unreachable_narrow: return {150, 90, 200};
    case CoverageState::unreachable_access: return {215, 50, 50};
  }
  return kOutsideRegions;
}

namespace {

// The part's views with each region filled by `colour` of its coverage,
// the points drawn on top.
std::vector<unsigned char> draw_coverage(PartViewPanels views, const RegionMap& map, const PlanCoverage& coverage,
                                         const std::function<Rgb(const RegionCoverage&)>& colour,
                                         std::vector<LegendEntry> legend, const std::string& title,
                                         const std::vector<Eigen::Vector3d>& points) {
  // The state of each region id; a region the plan does not know is grey.
  std::vector<const RegionCoverage*> of_region(map.regions.size(), nullptr);
  for (const RegionCoverage& r : coverage.regions)
    if (r.region >= 0 && static_cast<std::size_t>(r.region) < of_region.size())
      of_region[static_cast<std::size_t>(r.region)] = &r;
  const SurfacePainter paint = [&](std::size_t face, const Eigen::Vector2d& uv) {
    const std::optional<int> id = map.region_at(static_cast<int>(face), uv.x(), uv.y());
    if (!id || !of_region[static_cast<std::size_t>(*id)]) return SurfacePaint{kOutsideRegions, id ? *id : -1};
    return SurfacePaint{colour(*of_region[static_cast<std::size_t>(*id)]), *id};
  };
  legend.push_back({Rgb{35, 35, 35}, "planned point"});
  PartViewsFigure fig = draw_part_views(title, std::move(views), paint, legend);
  cv::Mat img(fig.height, fig.width, CV_8UC3, fig.bgr.data());
  for (const ViewPanel& panel : fig.panels) {
    // Drawn within the panel, as plan.png draws its marks.
    cv::Mat view = img(cv::Rect(panel.left, panel.top, panel.raster.width, panel.raster.height));
    const double tolerance = 1.5 / panel.raster.camera.scale;
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector2d at = panel.to_figure(p);
      const cv::Point c(static_cast<int>(std::lround(at.x())) - panel.left,
                        static_cast<int>(std::lround(at.y())) - panel.top);
      if (panel.raster.visible(p, tolerance)) cv::circle(view, c, 1, plot::kInk, cv::FILLED, cv::LINE_AA);
      else cv::circle(view, c, 2, plot::bgr(kHiddenPoint), 1, cv::LINE_AA);
    }
  }
  return part_views_png(fig);
}

const char* const kStateNames[] = {"covered", "reachable, not planned", "too narrow for the ball",
                                   "out of the probe's reach"};

}  // namespace

Rgb setup_colour(int setup) {
  static const Rgb kSetups[] = {{90, 175, 90}, {70, 130, 210}, {40, 170, 170}, {160, 160, 50}, {210, 110, 170},
                                {150, 110, 70}};
  return kSetups[static_cast<std::size_t>(std::max(setup, 1) - 1) % 6];
}

std::vector<unsigned char> coverage_image_png(const Part& part, const RegionMap& map, const PlanResult& result,
                                              const PlanCoverage& coverage) {
  return coverage_image_png(map, result, coverage, part_view_panels(part));
}

std::vector<unsigned char> coverage_image_png(const RegionMap& map, const PlanResult& result,
                                              const PlanCoverage& coverage, PartViewPanels views) {
  bool present[4] = {false, false, false, false};
  for (const RegionCoverage& r : coverage.regions) present[static_cast<int>(r.state)] = true;
  std::vector<LegendEntry> legend;
  for (int k = 0; k < 4; ++k)
    if (present[k]) legend.push_back({coverage_colour(static_cast<CoverageState>(k)), kStateNames[k]});
  char title[160];
  std::snprintf(title, sizeof title, "Coverage: %.1f %% of %.0f mm2 measured, %d of %zu regions at their minimum",
                100 * coverage.area.share_covered(), coverage.area.total, coverage.regions_covered,
                coverage.regions.size());
  std::vector<Eigen::Vector3d> points;
  for (const PlannedPoint& p : result.plan.points) points.push_back(p.xyz);
  return draw_coverage(std::move(views), map, coverage, [](const RegionCoverage& r) { return coverage_colour(r.state); }, legend,
                       title, points);
}

std::vector<unsigned char> setups_coverage_image_png(const Part& part, const RegionMap& map,
                                                     const PlanCoverage& combined,
                                                     const std::vector<Eigen::Vector3d>& points) {
  return setups_coverage_image_png(map, combined, points, part_view_panels(part));
}

std::vector<unsigned char> setups_coverage_image_png(const RegionMap& map, const PlanCoverage& combined,
                                                     const std::vector<Eigen::Vector3d>& points,
                                                     PartViewPanels views) {
  int setups = 0;
  bool present[4] = {false, false, false, false};
  for (const RegionCoverage& r : combined.regions) {
    if (r.covered) setups = std::max(setups, r.setup);
    present[static_cast<int>(r.state)] = true;
  }
  std::vector<LegendEntry> legend;
  for (int k = 1; k <= setups; ++k) {
    bool used = false;
    for (const RegionCoverage& r : combined.regions) used = used || (r.covered && r.setup == k);
    if (used) legend.push_back({setup_colour(k), "covered in setup " + std::to_string(k)});
  }
  for (int k = 1; k < 4; ++k)
    if (present[k]) legend.push_back({coverage_colour(static_cast<CoverageState>(k)), kStateNames[k]});
  char title[160];
  std::snprintf(title, sizeof title, "Coverage over the setups: %.1f %% of %.0f mm2 measured, %d of %zu regions",
                100 * combined.area.share_covered(), combined.area.total, combined.regions_covered,
                combined.regions.size());
  return draw_coverage(
      std::move(views), map, combined,
      [](const RegionCoverage& r) { return r.covered ? setup_colour(r.setup) : coverage_colour(r.state); }, legend,
      title, points);
}

}  // namespace furrow
