// The z-buffer views of a part (render/part_raster.hpp) against ray casting:
// every pixel centre is a ray along the view direction, intersected
// analytically with planes and a sphere; the raster must show the nearest
// hit, with its depth and (u,v), and nothing where no ray hits. Pixels
// within a pixel of a drawn edge may go either way (a centre exactly on an
// edge belongs to both sides).
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "render/part_raster.hpp"
#include "render/part_views.hpp"

using namespace furrow;

namespace {

constexpr double kPi = 3.141592653589793;

// The point of the part under pixel centre (x + 0.5, y + 0.5) at depth d.
Eigen::Vector3d on_ray(const ViewCamera& c, int x, int y, double depth) {
  const double right = (x + 0.5 - c.origin.x()) / c.scale, up = (c.origin.y() - (y + 0.5)) / c.scale;
  return c.frame.transpose() * Eigen::Vector3d(right, up, depth);
}

// Where the ray of pixel (x, y) meets the plane origin + u e_u + v e_v,
// as (u, v, depth); nullopt when parallel.
std::optional<Eigen::Vector3d> ray_plane(const ViewCamera& c, int x, int y, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& eu, const Eigen::Vector3d& ev) {
  const Eigen::Vector3d a = on_ray(c, x, y, 0), dir = c.frame.row(2).transpose();  // a + t dir has depth t
  Eigen::Matrix3d m;
  m << eu, ev, -dir;
  if (std::abs(m.determinant()) < 1e-12) return std::nullopt;
  return m.partialPivLu().solve(a - origin);  // (u, v, t)
}

// Pixels whose centre lies within `band` pixels of the segment a-b.
double pixel_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

struct Square {
  Eigen::Vector3d origin, eu, ev;
};

double edge_distance(const ViewCamera& c, const Square& s, const Eigen::Vector2d& p) {
  const Eigen::Vector3d corners[4] = {s.origin, s.origin + s.eu, s.origin + s.eu + s.ev, s.origin + s.ev};
  double best = 1e300;
  for (int k = 0; k < 4; ++k) best = std::min(best, pixel_distance(p, c.to_pixel(corners[k]), c.to_pixel(corners[(k + 1) % 4])));
  return best;
}

}  // namespace

TEST_CASE("raster views: two stacked squares match ray casting in every view") {
  const Square low{{-40, -30, 0}, {80, 0, 0}, {0, 60, 0}};
  const Square high{{-10, -12, 8}, {25, 5, 0}, {-4, 20, 3}};  // tilted, over the middle of the low one
  Eigen::AlignedBox3d box(Eigen::Vector3d(-40, -30, 0), Eigen::Vector3d(40, 30, 11));
  // Both face orders: the nearer face must win whichever is drawn last.
  for (bool high_first : {false, true})
  for (ViewDirection dir : {ViewDirection::top, ViewDirection::front, ViewDirection::side, ViewDirection::iso}) {
    Part part;
    const Square* squares[2] = {high_first ? &high : &low, high_first ? &low : &high};
    for (const Square* sq : squares) part.faces.emplace_back("square", make_plane(sq->origin, sq->eu, sq->ev));
    const std::string view = to_string(dir);
    CAPTURE(view);
    CAPTURE(high_first);
    const double scale = fitting_scale(dir, box, 300, 220, 10);
    const ViewCamera camera = centred_camera(dir, box, 300, 220, scale);
    // A right-handed orthonormal frame.
    CHECK((camera.frame * camera.frame.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    CHECK(camera.frame.row(0).cross(camera.frame.row(1)).isApprox(camera.frame.row(2), 1e-12));
    const PartRaster r = rasterize_part(part, camera, 300, 220);
    int checked = 0, covered = 0;
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        int expected = -1;
        double depth = -1e300;
        Eigen::Vector2d uv = Eigen::Vector2d::Zero();
        bool near_edge = false;
        for (int f = 0; f < 2; ++f) {
          near_edge = near_edge || edge_distance(camera, *squares[f], p) < 1.0;
          const auto hit = ray_plane(camera, x, y, squares[f]->origin, squares[f]->eu, squares[f]->ev);
          if (!hit || (*hit)(0) < 0 || (*hit)(0) > 1 || (*hit)(1) < 0 || (*hit)(1) > 1) continue;
          if ((*hit)(2) > depth) {
            depth = (*hit)(2);
            expected = f;
            uv = hit->head<2>();
          }
        }
        if (near_edge) continue;
        ++checked;
        REQUIRE(r.face[r.index(x, y)] == expected);
        if (expected < 0) continue;
        ++covered;
        CHECK(std::abs(r.depth[r.index(x, y)] - depth) < 1e-9);
        CHECK((r.uv[r.index(x, y)] - uv).norm() < 1e-9);
      }
    CHECK(checked > 50000);
    // Front and side see the low square edge-on; the others see both faces.
    if (dir == ViewDirection::top || dir == ViewDirection::iso) CHECK(covered > 10000);
  }
}

TEST_CASE("raster views: a point hidden under another face is not visible, one beside it is") {
  Part part;
  part.faces.emplace_back("low", make_plane({-40, -30, 0}, {80, 0, 0}, {0, 60, 0}));
  part.faces.emplace_back("high", make_plane({-10, -10, 8}, {20, 0, 0}, {0, 20, 0}));
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-40, -30, 0), Eigen::Vector3d(40, 30, 8));
  const ViewCamera top = centred_camera(ViewDirection::top, box, 400, 300, fitting_scale(ViewDirection::top, box, 400, 300, 10));
  const PartRaster r = rasterize_part(part, top, 400, 300);
  const double tolerance = 1.5 / top.scale;
  CHECK(r.visible({0, 0, 8}, tolerance));      // on the high square
  CHECK_FALSE(r.visible({0, 0, 0}, tolerance));  // under it, 8 mm down
  CHECK(r.visible({-30, 20, 0}, tolerance));   // on the low square, in the open
  CHECK_FALSE(r.visible({500, 0, 0}, tolerance));  // outside the picture
  // The iso view looks from +x -y +z: the high square's +x side hides the
  // low square just beyond it, the -x side does not.
  const ViewCamera iso = centred_camera(ViewDirection::iso, box, 400, 300, fitting_scale(ViewDirection::iso, box, 400, 300, 10));
  const PartRaster ri = rasterize_part(part, iso, 400, 300);
  CHECK_FALSE(ri.visible({-12, 5, 0}, tolerance));  // under the square's left part, seen through it
  CHECK(ri.visible({20, -5, 0}, tolerance));
}

TEST_CASE("raster views: a drilled hole is round at the figure's resolution, not stair-stepped") {
  // A 100 x 80 plate with a 30 mm hole through it, the trim loop a fine
  // polygon as CAD import writes it.
  const double radius = 15;
  const Eigen::Vector2d centre_uv(0.4, 0.55);  // u along 100 mm, v along 80 mm
  UvLoop outer = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, hole;
  for (int k = 0; k < 720; ++k) {
    const double a = -2 * kPi * k / 720;  // clockwise: a hole
    hole.emplace_back(centre_uv.x() + radius / 100 * std::cos(a), centre_uv.y() + radius / 80 * std::sin(a));
  }
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 5}, {100, 0, 0}, {0, 80, 0}), Trim({outer, hole}));
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(100, 80, 5));
  const ViewCamera camera = centred_camera(ViewDirection::top, box, 500, 400, fitting_scale(ViewDirection::top, box, 500, 400, 10));
  const PartRaster r = rasterize_part(part, camera, 500, 400);
  const Eigen::Vector2d centre_px = camera.to_pixel({40, 44, 5});
  const double radius_px = radius * camera.scale;
  int in_hole = 0, wrong = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const double rho = (Eigen::Vector2d(x + 0.5, y + 0.5) - centre_px).norm();
      const bool hole_pixel = !r.covered(x, y) && rho < radius_px + 2;
      in_hole += hole_pixel;
      // The polygon lies within (1 - cos(pi/720)) r = 1.4 um of the circle:
      // far below a pixel, so a pixel is wrong only off the circle's band.
      if (rho < radius_px - 0.75 && r.covered(x, y)) ++wrong;
      if (rho > radius_px + 0.75 && rho < radius_px + 20 && !r.covered(x, y)) ++wrong;
    }
  CHECK(wrong == 0);
  // The hole's pixel count is its area, to its circumference.
  CHECK(std::abs(in_hole - kPi * radius_px * radius_px) < 2 * kPi * radius_px);
}

TEST_CASE("raster views: a sphere's silhouette is its circle in every view, its depth the front hit") {
  const double radius = 12;
  Part part;
  part.faces.emplace_back("sphere", make_sphere(radius, 0, 2 * kPi, -kPi / 2, kPi / 2));
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-radius), Eigen::Vector3d::Constant(radius));
  for (ViewDirection dir : {ViewDirection::top, ViewDirection::front, ViewDirection::side, ViewDirection::iso}) {
    const std::string view = to_string(dir);
    CAPTURE(view);
    const ViewCamera camera = centred_camera(dir, box, 240, 200, fitting_scale(dir, box, 240, 200, 8));
    const PartRaster r = rasterize_part(part, camera, 240, 200);
    const Eigen::Vector2d centre = camera.to_pixel(Eigen::Vector3d::Zero());
    const double radius_px = radius * camera.scale;
    int inside = 0;
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        const double rho = (Eigen::Vector2d(x + 0.5, y + 0.5) - centre).norm();
        if (rho < radius_px - 1) {
          REQUIRE(r.covered(x, y));
          ++inside;
          if (rho < 0.9 * radius_px) {
            const double mm = rho / camera.scale;
            // The tessellation's chords sag inside the sphere: by under 0.02 mm
            // here, a fifth of a pixel at these scales (5 to 8 pixels a mm).
            CHECK(std::abs(r.depth[r.index(x, y)] - std::sqrt(radius * radius - mm * mm)) < 0.02);
          }
        } else if (rho > radius_px + 1) {
          REQUIRE_FALSE(r.covered(x, y));
        }
      }
    CHECK(inside > 5000);
  }
}

TEST_CASE("part views: every pixel is its face's paint, shaded, or a line where the paint changes") {
  Part part;
  part.faces.emplace_back("low", make_plane({-40, -30, 0}, {80, 0, 0}, {0, 60, 0}));
  part.faces.emplace_back("dome", make_sphere(10, 0, 2 * kPi, 0.2, kPi / 2));
  // Two painted regions on the plate (u < 0.5 and beyond), one on the dome.
  const SurfacePainter paint = [](std::size_t face, const Eigen::Vector2d& uv) {
    if (face == 1) return SurfacePaint{Rgb{40, 120, 200}, 2};
    return uv.x() < 0.5 ? SurfacePaint{Rgb{230, 120, 40}, 0} : SurfacePaint{Rgb{90, 170, 90}, 1};
  };
  const PartViewsFigure fig = draw_part_views("test", part, paint, {});
  REQUIRE(fig.panels.size() == 4);
  int painted = 0, lines = 0;
  for (const ViewPanel& panel : fig.panels) {
    const PartRaster& r = panel.raster;
    auto key = [&](int x, int y) -> std::int64_t {
      if (x < 0 || y < 0 || x >= r.width || y >= r.height || !r.covered(x, y)) return -100;
      return paint(static_cast<std::size_t>(r.face[r.index(x, y)]), r.uv[r.index(x, y)]).key;
    };
    for (int y = 40; y < r.height - 40; ++y)  // clear of the caption, scale bar and frame
      for (int x = 4; x < r.width - 4; ++x) {
        if (!r.covered(x, y)) continue;
        const std::size_t at = (static_cast<std::size_t>(panel.top + y) * fig.width + panel.left + x) * 3;
        const Rgb got{fig.bgr[at + 2], fig.bgr[at + 1], fig.bgr[at]};
        const std::size_t i = r.index(x, y);
        const Rgb expected = PartViewsFigure::shaded(paint(static_cast<std::size_t>(r.face[i]), r.uv[i]).colour, r.light[i]);
        if (got == expected) {
          ++painted;
          continue;
        }
        // Otherwise a line: the paint, face or coverage changes next to it.
        ++lines;
        bool change = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) change = change || key(x + dx, y + dy) != key(x, y);
        const bool face_change = (x + 1 < r.width && r.face[r.index(x + 1, y)] != r.face[i]) ||
                                 (y + 1 < r.height && r.face[r.index(x, y + 1)] != r.face[i]) ||
                                 (x > 0 && r.face[r.index(x - 1, y)] != r.face[i]) ||
                                 (y > 0 && r.face[r.index(x, y - 1)] != r.face[i]);
        INFO(to_string(panel.direction) << " pixel " << x << "," << y);
        CHECK((change || face_change));
      }
  }
  CHECK(painted > 100000);
  CHECK(lines > 500);
  CHECK(lines < painted / 10);
  CHECK(part_views_png(fig) == part_views_png(draw_part_views("test", part, paint, {})));
}

TEST_CASE("part views: a huge surface of which the trim keeps a small square is drawn at the square's scale") {
  // A plane 1.8e6 mm wide trimmed to a 10 mm square near its middle: the
  // surface around the square projects some 1e8 pixels away.
  const double half = 9e5;  // within the coordinate limit (docs/formats.md "Limits")
  Part part;
  const double a = 0.5 - 5 / (2 * half), b = 0.5 + 5 / (2 * half);
  part.faces.emplace_back("square", make_plane({-half, -half, 3}, {2 * half, 0, 0}, {0, 2 * half, 0}),
                          Trim({{{a, a}, {b, a}, {b, b}, {a, b}}}));
  const PartViewsFigure fig = draw_part_views("huge", part, [](std::size_t, const Eigen::Vector2d&) {
    return SurfacePaint{Rgb{200, 100, 50}, 0};
  }, {});
  const PartRaster& top = fig.panels[0].raster;
  int covered = 0;
  for (int y = 0; y < top.height; ++y)
    for (int x = 0; x < top.width; ++x) covered += top.covered(x, y);
  // The square fills the panel less its margin (the views share one scale,
  // set by the view that needs the most room).
  const double side = 10 * top.camera.scale;
  CHECK(covered == doctest::Approx(side * side).epsilon(0.05));
  CHECK(side > 200);
}
