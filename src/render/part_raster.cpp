#include "render/part_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/surface_grid.hpp"

namespace furrow {

const char* to_string(ViewDirection direction) {
  switch (direction) {
    case ViewDirection::top:
      return "top";
    case ViewDirection::front:
      return "front";
    case ViewDirection::side:
      return "side";
    case ViewDirection::iso:
      return "iso";
  }
  return "?";
}

const char* view_caption(ViewDirection direction) {
  switch (direction) {
    case ViewDirection::top:
      return "top (x right, y up)";
    case ViewDirection::front:
      return "front (x right, z up)";
    case ViewDirection::side:
      return "right side (y right, z up)";
    case ViewDirection::iso:
      return "isometric (from +x -y +z)";
  }
  return "?";
}

Eigen::Matrix3d view_frame(ViewDirection direction) {
  Eigen::Matrix3d f;
  switch (direction) {
    case ViewDirection::top:
      f << 1, 0, 0, 0, 1, 0, 0, 0, 1;
      break;
    case ViewDirection::front:
      f << 1, 0, 0, 0, 0, 1, 0, -1, 0;
      break;
    case ViewDirection::side:
      f << 0, 1, 0, 0, 0, 1, 1, 0, 0;
      break;
    case ViewDirection::iso: {
      const Eigen::Vector3d toward = Eigen::Vector3d(1, -1, 1).normalized();
      const Eigen::Vector3d up = Eigen::Vector3d(-1, 1, 2).normalized();  // +z less its part along `toward`
      f.row(0) = up.cross(toward);
      f.row(1) = up;
      f.row(2) = toward;
      break;
    }
  }
  return f;
}

Eigen::Vector2d ViewCamera::to_pixel(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d s = frame * p;
  return {origin.x() + scale * s.x(), origin.y() - scale * s.y()};
}

double ViewCamera::depth(const Eigen::Vector3d& p) const { return frame.row(2).dot(p); }

namespace {

// The box's extent on the screen's right and up axes.
Eigen::AlignedBox2d screen_extent(const Eigen::Matrix3d& frame, const Eigen::AlignedBox3d& box) {
  Eigen::AlignedBox2d out;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d s = frame * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
    out.extend(Eigen::Vector2d(s.x(), s.y()));
  }
  return out;
}

struct Vertex {
  Eigen::Vector2d xy;  // pixel
  double depth = 0;
  Eigen::Vector2d uv;
  float light = 0;
};

double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

// Scan-converts one triangle: every pixel whose centre it covers (edges
// included) and where it is nearer than what is there already.
void fill_triangle(PartRaster& r, const Vertex& a, const Vertex& b, const Vertex& c, std::int32_t face,
                   const Trim* trim) {
  const double area = edge(a.xy, b.xy, c.xy);
  if (!(std::abs(area) > 1e-12)) return;
  const double x_lo = std::min({a.xy.x(), b.xy.x(), c.xy.x()}), x_hi = std::max({a.xy.x(), b.xy.x(), c.xy.x()});
  const double y_lo = std::min({a.xy.y(), b.xy.y(), c.xy.y()}), y_hi = std::max({a.xy.y(), b.xy.y(), c.xy.y()});
  // Clamped in double first: a face reaching far beyond the view (an
  // untrimmed surface around a small trimmed patch) must not overflow int.
  if (!(x_hi >= 0 && y_hi >= 0 && x_lo <= r.width && y_lo <= r.height)) return;
  const int x0 = static_cast<int>(std::max(0.0, std::ceil(x_lo - 0.5)));
  const int x1 = static_cast<int>(std::min(r.width - 1.0, std::floor(x_hi - 0.5)));
  const int y0 = static_cast<int>(std::max(0.0, std::ceil(y_lo - 0.5)));
  const int y1 = static_cast<int>(std::min(r.height - 1.0, std::floor(y_hi - 0.5)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      const double wa = edge(b.xy, c.xy, p) / area, wb = edge(c.xy, a.xy, p) / area, wc = edge(a.xy, b.xy, p) / area;
      if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
      const double d = wa * a.depth + wb * b.depth + wc * c.depth;
      const std::size_t i = r.index(x, y);
      if (!(d > r.depth[i])) continue;
      const Eigen::Vector2d uv = wa * a.uv + wb * b.uv + wc * c.uv;
      if (trim && !trim->contains(uv)) continue;
      r.depth[i] = d;
      r.face[i] = face;
      r.uv[i] = uv;
      r.light[i] = static_cast<float>(wa * a.light + wb * b.light + wc * c.light);
    }
}

// Grid lines per direction for one face: about one every two pixels of the
// face's longest projected parameter line, at least 2 and at most 1024.
std::pair<int, int> tessellation(const Face& face, const ViewCamera& camera) {
  const ParameterDomain& d = face.domain();
  constexpr int kProbe = 8;
  Eigen::Vector2d pts[kProbe + 1][kProbe + 1];
  for (int i = 0; i <= kProbe; ++i)
    for (int j = 0; j <= kProbe; ++j)
      pts[i][j] = camera.to_pixel(face.surface().point(d.u0 + d.width_u() * i / kProbe, d.v0 + d.width_v() * j / kProbe));
  double along_u = 0, along_v = 0;
  for (int k = 0; k <= kProbe; ++k) {
    double lu = 0, lv = 0;
    for (int s = 0; s < kProbe; ++s) {
      lu += (pts[s + 1][k] - pts[s][k]).norm();
      lv += (pts[k][s + 1] - pts[k][s]).norm();
    }
    along_u = std::max(along_u, lu);
    along_v = std::max(along_v, lv);
  }
  auto lines = [](double pixels) {
    if (!std::isfinite(pixels)) return 1024;  // a face beyond any scale: the finest tessellation
    return static_cast<int>(std::clamp(std::ceil(pixels / 2), 2.0, 1024.0));
  };
  return {lines(along_u), lines(along_v)};
}

}  // namespace

double fitting_scale(ViewDirection direction, const Eigen::AlignedBox3d& box, int width, int height, int margin) {
  const Eigen::Vector2d size = screen_extent(view_frame(direction), box).sizes().cwiseMax(1e-9);
  const double w = std::max(1, width - 2 * margin), h = std::max(1, height - 2 * margin);
  return std::min(w / size.x(), h / size.y());
}

ViewCamera centred_camera(ViewDirection direction, const Eigen::AlignedBox3d& box, int width, int height,
                          double scale) {
  ViewCamera c;
  c.frame = view_frame(direction);
  c.scale = scale;
  const Eigen::Vector2d middle = screen_extent(c.frame, box).center();
  c.origin = Eigen::Vector2d(0.5 * width - scale * middle.x(), 0.5 * height + scale * middle.y());
  return c;
}

bool PartRaster::visible(const Eigen::Vector3d& p, double tolerance) const {
  const Eigen::Vector2d xy = camera.to_pixel(p);
  if (!(xy.x() >= 0 && xy.y() >= 0 && xy.x() < width && xy.y() < height)) return false;  // NaN too
  const int x = static_cast<int>(xy.x()), y = static_cast<int>(xy.y());
  const double d = camera.depth(p);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      if (depth[index(nx, ny)] <= d + tolerance) return true;
    }
  return false;
}

PartRaster rasterize_part(const Part& part, const ViewCamera& camera, int width, int height) {
  PartRaster r;
  r.width = width;
  r.height = height;
  r.camera = camera;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  r.depth.assign(n, -std::numeric_limits<double>::infinity());
  r.face.assign(n, -1);
  r.uv.assign(n, Eigen::Vector2d::Zero());
  r.light.assign(n, 0.0f);
  // Light from the viewer's upper left, in the part's frame.
  const Eigen::Vector3d light = camera.frame.transpose() * Eigen::Vector3d(-0.35, 0.45, 1.0).normalized();

  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const Face& face = part.faces[f];
    const ParameterDomain& d = face.domain();
    const auto [nu, nv] = tessellation(face, camera);
    std::vector<double> us(static_cast<std::size_t>(nu) + 1), vs(static_cast<std::size_t>(nv) + 1);
    for (int i = 0; i <= nu; ++i) us[static_cast<std::size_t>(i)] = i == nu ? d.u1 : d.u0 + d.width_u() * i / nu;
    for (int j = 0; j <= nv; ++j) vs[static_cast<std::size_t>(j)] = j == nv ? d.v1 : d.v0 + d.width_v() * j / nv;
    const SurfaceGrid grid(face.surface(), us, vs, 1);
    SurfaceGridScratch scratch;
    std::vector<SurfaceDerivatives> row(us.size());
    std::vector<Vertex> vertex(us.size() * vs.size());
    std::vector<char> kept(vertex.size(), 1);
    const Trim& trim = face.trim();
    for (int j = 0; j <= nv; ++j) {
      grid.evaluate_row(j, row.data(), scratch);
      for (int i = 0; i <= nu; ++i) {
        const SurfaceDerivatives& s = row[static_cast<std::size_t>(i)];
        Vertex& v = vertex[static_cast<std::size_t>(j) * us.size() + i];
        v.xy = camera.to_pixel(s.S);
        v.depth = camera.depth(s.S);
        v.uv = Eigen::Vector2d(us[static_cast<std::size_t>(i)], vs[static_cast<std::size_t>(j)]);
        const Eigen::Vector3d normal = s.Su.cross(s.Sv);
        const double length = normal.norm();
        // Two-sided: a face seen from its back (inside a bore) is lit too.
        v.light = length > 0 ? static_cast<float>(std::abs(normal.dot(light)) / length) : 0.6f;
        if (!trim.empty()) kept[static_cast<std::size_t>(j) * us.size() + i] = trim.contains(v.uv);
      }
    }
    const double half_diagonal = 0.5 * std::hypot(d.width_u() / nu, d.width_v() / nv);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const std::size_t k00 = static_cast<std::size_t>(j) * us.size() + i, k10 = k00 + 1, k01 = k00 + us.size(),
                          k11 = k01 + 1;
        const Trim* test = nullptr;
        if (!trim.empty()) {
          // Decided for the whole quad unless a loop comes within its reach.
          const int inside = kept[k00] + kept[k10] + kept[k01] + kept[k11];
          const Eigen::Vector2d middle = 0.25 * (vertex[k00].uv + vertex[k10].uv + vertex[k01].uv + vertex[k11].uv);
          const bool clear = !trim.edge_near(middle, half_diagonal * (1 + 1e-9));  // banded: cheap
          if (clear && inside == 0) continue;
          if (!(clear && inside == 4)) test = &trim;
        }
        const auto id = static_cast<std::int32_t>(f);
        fill_triangle(r, vertex[k00], vertex[k10], vertex[k11], id, test);
        fill_triangle(r, vertex[k00], vertex[k11], vertex[k01], id, test);
      }
  }
  return r;
}

}  // namespace furrow
