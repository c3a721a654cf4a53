#pragma once
// A figure of a whole part as a drawing shows it: four orthographic views
// (top, front, right side, isometric; part_raster.hpp) at one common scale,
// hidden surfaces removed, each face painted per pixel by a caller's
// function of (face, u, v) and shaded by the light it catches, with
// silhouettes, face edges and the borders between painted regions drawn
// where they are seen, a scale bar per view, labels at visible points and a
// legend. This is how the partition, the plan and the report show a part
// of any number of faces: a 140-face part is one picture, not 140 (u, v)
// tiles.
//
// Lines are found in the picture itself: a pixel whose right or lower
// neighbour shows another face (grey line), another painted region (dark
// line) or the background, or lies much nearer or farther on the same face
// (a fold: a depth step of more than 25 pixels' worth), is drawn as a line.
// So every line is exactly where the visible surface changes, at the
// figure's resolution, and nothing hidden is drawn.
//
// The pixels are B, G, R bytes (OpenCV's order) so callers can draw their
// own marks on top (plan points, tour) through the panels' cameras and
// rasters before encoding the PNG. Deterministic.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "render/colour_scale.hpp"
#include "render/part_raster.hpp"

namespace furrow {

// What a face shows at (u, v): its colour before shading, and a key that is
// the same over one painted region (a region id; -1 for none). Borders are
// drawn where the key changes.
struct SurfacePaint {
  Rgb colour{200, 200, 200};
  std::int64_t key = -1;
};
using SurfacePainter = std::function<SurfacePaint(std::size_t face, const Eigen::Vector2d& uv)>;

struct LegendEntry {
  Rgb colour;
  std::string text;
};

// A text placed at a point of the part in every view that sees the point
// and shows at least `min_pixels` pixels of `key` (so a sliver seen edge-on
// gets no label), unless it would overlap a label placed before it in that
// view (labels are placed in the order given).
struct ViewLabel {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  std::string text;
  std::int64_t key = -1;
  int min_pixels = 200;
};

struct ViewPanel {
  ViewDirection direction = ViewDirection::top;
  int left = 0, top = 0;  // where the raster's pixel (0, 0) is in the figure
  PartRaster raster;
  // The figure pixel of a part point in this panel.
  Eigen::Vector2d to_figure(const Eigen::Vector3d& p) const {
    return raster.camera.to_pixel(p) + Eigen::Vector2d(left, top);
  }
};

struct PartViewsFigure {
  int width = 0, height = 0;
  std::vector<unsigned char> bgr;  // width * height * 3
  std::vector<ViewPanel> panels;   // top, front, side, iso
  // The legend column's left edge and the first free row below its
  // entries, where a caller may add its own key (a colour bar).
  int legend_left = 0, legend_bottom = 0;
  // The shaded colour a pixel of `base` colour gets under light `light`
  // (what the panels paint): exposed so a test can check every pixel.
  static Rgb shaded(const Rgb& base, float light);
};

// The four panels (top, front, side, iso) of a part at one common scale,
// placed in the figure and rasterized, before anything is painted on them.
// Rasterizing is most of a figure's cost (every face tessellated and cut by
// its trim, once per view) and does not depend on the paint, so a caller
// that draws several figures of one part (plan.png and coverage.png)
// computes the panels once and draws each figure from a copy: the figures
// are the same bytes as when each rasterizes the part itself.
struct PartViewPanels {
  std::vector<ViewPanel> panels;  // top, front, side, iso
};

// Throws std::invalid_argument for a part without faces.
PartViewPanels part_view_panels(const Part& part);

// Throws std::invalid_argument for a part without faces.
PartViewsFigure draw_part_views(const std::string& title, const Part& part, const SurfacePainter& paint,
                                const std::vector<LegendEntry>& legend, const std::vector<ViewLabel>& labels = {});
// The same figure on panels already made (taken by value: pass a copy to
// draw another figure from them, or move them into the last one).
PartViewsFigure draw_part_views(const std::string& title, PartViewPanels views, const SurfacePainter& paint,
                                const std::vector<LegendEntry>& legend, const std::vector<ViewLabel>& labels = {});

// PNG bytes of the figure (render/png.hpp).
std::vector<unsigned char> part_views_png(const PartViewsFigure& figure);

}  // namespace furrow
