#pragma once
// An orthographic picture of a part with hidden surfaces removed: every face
// tessellated on a (u,v) grid fine for the view's scale and scan-converted
// into a depth buffer, so each pixel knows the nearest face it shows, the
// (u,v) there and how much light the surface catches.
//
// Why per-pixel (u,v) and not a colour per triangle: what a figure paints on
// the part (curvature class, region, deviation) is a function on the faces.
// Looked up per pixel, region borders and trim edges come out at the
// figure's resolution, not as the tessellation's stair steps; a quad that a
// trim loop crosses is tested against the trim pixel by pixel, so a drilled
// hole is round at any size.
//
// Views are the ones drawings use (looking at the part from outside):
//   top    looks down -z   (x right, y up)
//   front  looks along +y  (x right, z up)
//   side   looks along -x  (y right, z up), the right-hand side view
//   iso    looks along (-1, +1, -1), from the front-right-top corner
// Units: part millimetres; a camera maps them to pixels at one scale (equal
// aspect), pixel (0, 0) top left, y down. Deterministic: the same part and
// camera give the same buffers.
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

enum class ViewDirection { top, front, side, iso };
const char* to_string(ViewDirection direction);
// "top (x right, y up)" and so on: what a reader needs to orient the view.
const char* view_caption(ViewDirection direction);

struct ViewCamera {
  // Rows: the screen's right, the screen's up, toward the viewer (a
  // right-handed orthonormal frame of the part).
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
  double scale = 1;                             // pixels per mm
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // pixel of the part's origin

  Eigen::Vector2d to_pixel(const Eigen::Vector3d& p) const;  // continuous: pixel centres at k + 0.5
  double depth(const Eigen::Vector3d& p) const;             // toward the viewer [mm]: larger is nearer
};

Eigen::Matrix3d view_frame(ViewDirection direction);
// The largest scale at which `box` fits into width x height less `margin`
// pixels on every side, in that direction.
double fitting_scale(ViewDirection direction, const Eigen::AlignedBox3d& box, int width, int height, int margin);
// The camera that shows `box` centred in a width x height picture at `scale`.
ViewCamera centred_camera(ViewDirection direction, const Eigen::AlignedBox3d& box, int width, int height,
                          double scale);

struct PartRaster {
  int width = 0, height = 0;
  ViewCamera camera;
  // Row-major, width * height each. Background: face -1, depth -infinity.
  std::vector<double> depth;
  std::vector<std::int32_t> face;
  std::vector<Eigen::Vector2d> uv;
  std::vector<float> light;  // Lambert term |n . l| in [0, 1], l from the upper left of the viewer

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  bool covered(int x, int y) const { return face[index(x, y)] >= 0; }
  // True when a point on the part is not hidden in this view: at its pixel
  // or one next to it, no surface lies in front of it by more than
  // `tolerance` [mm] (a point on a face the view sees edge-on still counts).
  // False outside the picture.
  bool visible(const Eigen::Vector3d& p, double tolerance) const;
};

// Preconditions: width, height >= 1; the camera's frame orthonormal, scale > 0.
PartRaster rasterize_part(const Part& part, const ViewCamera& camera, int width, int height);

}  // namespace furrow
