#include "planning/plan_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "render/colour_scale.hpp"
#include "render/plot_canvas.hpp"

namespace furrow {

namespace {

// The curvature-class colours every figure uses (render/colour_scale.hpp).
cv::Scalar class_colour(CurvatureClass c) { return plot::bgr(curvature_class_colour(to_string(c))); }
const cv::Scalar kOutside(215, 215, 215), kInk(30, 30, 30), kPaper(255, 255, 255);
const cv::Scalar kStraight(120, 40, 10), kOver(230, 190, 150), kMoved(0, 140, 255), kDropped(40, 40, 220);
const cv::Scalar kGouge(200, 40, 200);
constexpr int kCells = 96;
constexpr int kShift = 4;
constexpr int kSide = 900, kMargin = 30, kLegend = 66;

struct Quad {
  double z;
  std::size_t index;
  std::array<Eigen::Vector2d, 4> xy;
  cv::Scalar colour;
};

}  // namespace

std::vector<unsigned char> plan_image_png(const Part& part, const RegionMap& map, const PlanResult& result) {
  // Cells of every face with their region colour and mean height.
  std::vector<Quad> quads;
  Eigen::AlignedBox2d bounds;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    const ParameterDomain& d = face.domain();
    std::vector<Eigen::Vector3d> nodes(static_cast<std::size_t>(kCells + 1) * (kCells + 1));
    for (int i = 0; i <= kCells; ++i)
      for (int j = 0; j <= kCells; ++j) {
        const Eigen::Vector3d p = face.surface().point(d.u0 + d.width_u() * i / kCells, d.v0 + d.width_v() * j / kCells);
        nodes[static_cast<std::size_t>(i) * (kCells + 1) + j] = p;
        bounds.extend(Eigen::Vector2d(p.x(), p.y()));
      }
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j) {
        const double u = d.u0 + d.width_u() * (i + 0.5) / kCells, v = d.v0 + d.width_v() * (j + 0.5) / kCells;
        if (!face.contains(u, v)) continue;
        const std::optional<int> region = map.region_at(static_cast<int>(f), u, v);
        Quad q;
        q.index = quads.size();
        q.colour = region ? class_colour(map.regions[static_cast<std::size_t>(*region)].curvature_class) : kOutside;
        const Eigen::Vector3d* c[4] = {&nodes[static_cast<std::size_t>(i) * (kCells + 1) + j],
                                       &nodes[static_cast<std::size_t>(i + 1) * (kCells + 1) + j],
                                       &nodes[static_cast<std::size_t>(i + 1) * (kCells + 1) + j + 1],
                                       &nodes[static_cast<std::size_t>(i) * (kCells + 1) + j + 1]};
        q.z = 0;
        for (int k = 0; k < 4; ++k) {
          q.xy[static_cast<std::size_t>(k)] = {c[k]->x(), c[k]->y()};
          q.z += c[k]->z() / 4;
        }
        quads.push_back(q);
      }
  }
  if (bounds.isEmpty()) throw std::logic_error("plan image: the part has no faces");
  const Eigen::Vector2d size = bounds.sizes().cwiseMax(1e-9);
  const double scale = (kSide - 2 * kMargin) / std::max(size.x(), size.y());
  const int width = static_cast<int>(std::ceil(size.x() * scale)) + 2 * kMargin;
  const int height = static_cast<int>(std::ceil(size.y() * scale)) + 2 * kMargin + kLegend;
  cv::Mat canvas(std::max(height, 200), std::max(width, 640), CV_8UC3, kPaper);
  auto px = [&](double x, double y) {
    const double sx = kMargin + (x - bounds.min().x()) * scale;
    const double sy = kMargin + (bounds.max().y() - y) * scale;  // y up
    return cv::Point(static_cast<int>(std::lround(sx * (1 << kShift))), static_cast<int>(std::lround(sy * (1 << kShift))));
  };
  auto px3 = [&](const Eigen::Vector3d& p) { return px(p.x(), p.y()); };
  auto plain = [](cv::Point p) { return cv::Point(p.x >> kShift, p.y >> kShift); };

  std::stable_sort(quads.begin(), quads.end(), [](const Quad& a, const Quad& b) { return a.z < b.z; });
  for (const Quad& q : quads) {
    cv::Point pts[4];
    for (int k = 0; k < 4; ++k) pts[k] = px(q.xy[static_cast<std::size_t>(k)].x(), q.xy[static_cast<std::size_t>(k)].y());
    cv::fillConvexPoly(canvas, pts, 4, q.colour, cv::LINE_8, kShift);
  }
  for (const Region& region : map.regions)
    for (const BorderLoop& loop : region.border) {
      std::vector<cv::Point> pts;
      for (const Eigen::Vector3d& p : loop.xyz) pts.push_back(px3(p));
      cv::polylines(canvas, pts, true, kInk, 1, cv::LINE_AA, kShift);
    }
  // Tour.
  const std::vector<PlannedPoint>& points = result.plan.points;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const bool straight = result.moves[k].straight;
    cv::line(canvas, px3(points[k - 1].xyz), px3(points[k].xyz), straight ? kStraight : kOver, straight ? 1 : 1,
             cv::LINE_AA, kShift);
  }
  for (const PlanIssue& issue : result.issues) {
    if (issue.kind == PlanIssue::Kind::dropped) {
      const cv::Point c = plain(px3(issue.where));
      cv::line(canvas, c + cv::Point(-4, -4), c + cv::Point(4, 4), kDropped, 2, cv::LINE_AA);
      cv::line(canvas, c + cv::Point(-4, 4), c + cv::Point(4, -4), kDropped, 2, cv::LINE_AA);
    }
  }
  const int dot = points.size() > 1500 ? 1 : 2;
  for (const PlannedPoint& p : points) cv::circle(canvas, plain(px3(p.xyz)), dot, kInk, cv::FILLED, cv::LINE_AA);
  for (std::size_t k = 0; k < points.size() && k < result.point_sites.size(); ++k)
    if (!result.point_sites[k].empty()) {
      const cv::Point c = plain(px3(points[k].xyz));
      cv::rectangle(canvas, c - cv::Point(4, 4), c + cv::Point(4, 4), kGouge, 2, cv::LINE_AA);
    }
  for (const PlanIssue& issue : result.issues)
    if (issue.kind == PlanIssue::Kind::moved) {
      const auto it = std::find_if(points.begin(), points.end(), [&](const PlannedPoint& p) { return p.id == issue.point; });
      if (it != points.end()) cv::circle(canvas, plain(px3(it->xyz)), 5, kMoved, 2, cv::LINE_AA);
    }
  if (!points.empty()) {
    cv::circle(canvas, plain(px3(points.front().xyz)), 6, cv::Scalar(60, 170, 40), cv::FILLED, cv::LINE_AA);
    const cv::Point e = plain(px3(points.back().xyz));
    cv::rectangle(canvas, e - cv::Point(5, 5), e + cv::Point(5, 5), kDropped, cv::FILLED);
  }
  // Legend.
  const int top = canvas.rows - kLegend + 10;
  struct Entry {
    cv::Scalar colour;
    const char* text;
  };
  const Entry entries[] = {{class_colour(CurvatureClass::convex), "convex"},
                           {class_colour(CurvatureClass::concave), "concave"},
                           {class_colour(CurvatureClass::saddle), "saddle"},
                           {class_colour(CurvatureClass::planar), "planar"}, {kStraight, "straight move"}, {kOver, "over clearance plane"},
                           {kMoved, "moved"}, {kGouge, "on a gouge site"}, {kDropped, "dropped / last"}};
  int x = kMargin, y = top;
  for (const Entry& e : entries) {
    int baseline = 0;
    const int w = 19 + cv::getTextSize(e.text, cv::FONT_HERSHEY_SIMPLEX, 0.42, 1, &baseline).width;
    if (x + w > canvas.cols - kMargin) {  // wrap to a second row
      x = kMargin;
      y += 22;
    }
    cv::rectangle(canvas, cv::Rect(x, y, 14, 14), e.colour, cv::FILLED);
    cv::rectangle(canvas, cv::Rect(x, y, 14, 14), kInk, 1);
    cv::putText(canvas, e.text, {x + 19, y + 12}, cv::FONT_HERSHEY_SIMPLEX, 0.42, kInk, 1, cv::LINE_AA);
    x += w + 14;
  }
  const std::string title = std::to_string(points.size()) + " points, top view (x right, y up)";
  cv::putText(canvas, title, {kMargin, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk, 1, cv::LINE_AA);
  const std::vector<unsigned char> png = plot::encode_png(canvas);
  return png;
}

}  // namespace furrow
