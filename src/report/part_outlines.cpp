#include "report/part_outlines.hpp"

#include <algorithm>

namespace furrow {

namespace {

Eigen::Vector2d xy_of(const Face& face, const Eigen::Vector2d& uv) {
  const Eigen::Vector3d p = face.surface().point(uv.x(), uv.y());
  return {p.x(), p.y()};
}

// The closed polyline through `corners` (not repeated), each edge cut into
// `samples` pieces and mapped by `map`.
template <class Map>
Outline closed_polyline(const std::vector<Eigen::Vector2d>& corners, int samples, Map&& map) {
  Outline out;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector2d& a = corners[k];
    const Eigen::Vector2d& b = corners[(k + 1) % corners.size()];
    for (int s = 0; s < samples; ++s) out.push_back(map(a + (b - a) * (static_cast<double>(s) / samples)));
  }
  if (!corners.empty()) out.push_back(out.front());
  return out;
}

std::vector<std::vector<Eigen::Vector2d>> boundary_loops(const Face& face) {
  if (!face.trim().empty()) {
    std::vector<std::vector<Eigen::Vector2d>> loops;
    for (const auto& loop : face.trim().loops()) loops.emplace_back(loop.begin(), loop.end());
    return loops;
  }
  const ParameterDomain& d = face.domain();
  return {{{d.u0, d.v0}, {d.u1, d.v0}, {d.u1, d.v1}, {d.u0, d.v1}}};
}

}  // namespace

std::vector<Outline> face_outlines_xy(const Part& part, int samples) {
  std::vector<Outline> out;
  for (const Face& face : part.faces)
    for (const auto& loop : boundary_loops(face)) {
      // A trim loop has many short edges already: fewer pieces per edge.
      const int pieces = loop.size() > 8 ? std::max(1, samples / 16) : samples;
      out.push_back(closed_polyline(loop, pieces, [&](const Eigen::Vector2d& uv) { return xy_of(face, uv); }));
    }
  return out;
}

std::vector<Outline> face_outlines_uv(const Face& face) {
  std::vector<Outline> out;
  for (const auto& loop : boundary_loops(face))
    out.push_back(closed_polyline(loop, 1, [](const Eigen::Vector2d& uv) { return uv; }));
  return out;
}

std::vector<Outline> region_borders_xy(const RegionMap& map) {
  std::vector<Outline> out;
  for (const Region& r : map.regions)
    for (const BorderLoop& loop : r.border) {
      Outline o;
      for (const Eigen::Vector3d& p : loop.xyz) o.emplace_back(p.x(), p.y());
      if (!o.empty()) o.push_back(o.front());
      out.push_back(std::move(o));
    }
  return out;
}

std::vector<Outline> region_borders_uv(const RegionMap& map, int face) {
  std::vector<Outline> out;
  for (const Region& r : map.regions) {
    if (r.face != face) continue;
    for (const BorderLoop& loop : r.border) {
      Outline o(loop.uv.begin(), loop.uv.end());
      if (!o.empty()) o.push_back(o.front());
      out.push_back(std::move(o));
    }
  }
  return out;
}

Outline uv_box_outline_xy(const Face& face, const Eigen::AlignedBox2d& box, int samples) {
  const ParameterDomain& d = face.domain();
  const Eigen::Vector2d lo(std::clamp(box.min().x(), d.u0, d.u1), std::clamp(box.min().y(), d.v0, d.v1));
  const Eigen::Vector2d hi(std::clamp(box.max().x(), d.u0, d.u1), std::clamp(box.max().y(), d.v0, d.v1));
  return closed_polyline({lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, samples,
                         [&](const Eigen::Vector2d& uv) { return xy_of(face, uv); });
}

}  // namespace furrow
