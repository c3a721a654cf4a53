#include "inspection/point_subsets.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace furrow {

namespace {

double median_of(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::vector<std::size_t> stride(const std::vector<std::size_t>& from, std::size_t max) {
  std::vector<std::size_t> out;
  if (max == 0) return out;
  const std::size_t step = (from.size() + max - 1) / max;
  for (std::size_t k = 0; k < from.size(); k += std::max<std::size_t>(step, 1)) out.push_back(from[k]);
  return out;
}

// One representative (the lowest index) per occupied cell, in index order.
std::vector<std::size_t> one_per_cell(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<std::size_t>& from, const Eigen::Vector3d& origin,
                                      double cell) {
  // Cells along an axis are counted in 21 bits (the box is at most 2^20
  // cells wide, see spread_subset), so keys of cells in the box never collide.
  std::unordered_map<std::uint64_t, std::size_t> first;
  first.reserve(from.size());
  for (std::size_t i : from) {
    const Eigen::Vector3d c = ((points[i] - origin) / cell).array().floor();
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a)  // NaN goes to cell 0 (fmax), far points to the edge cells
      key = key << 21 | static_cast<std::uint64_t>(std::clamp(std::fmax(c[a], 0.0), 0.0, double((1 << 21) - 1)));
    first.emplace(key, i);  // `from` is in index order: the first stays
  }
  std::vector<std::size_t> out;
  out.reserve(first.size());
  for (const auto& [key, i] : first) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<std::size_t> points_near_the_bulk(const std::vector<Eigen::Vector3d>& points, double reach) {
  std::vector<std::size_t> finite;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite()) finite.push_back(i);
  if (finite.empty()) return finite;
  Eigen::Vector3d centre;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> coordinate;
    coordinate.reserve(finite.size());
    for (std::size_t i : finite) coordinate.push_back(points[i][a]);
    centre[a] = median_of(std::move(coordinate));
  }
  std::vector<std::size_t> out;
  // Compared per axis first: (p - centre).norm() would overflow for points
  // beyond 1e154 and is not needed to reject them.
  for (std::size_t i : finite) {
    const Eigen::Vector3d d = points[i] - centre;
    if (d.cwiseAbs().maxCoeff() <= reach && d.norm() <= reach) out.push_back(i);
  }
  return out;
}

std::vector<std::size_t> spread_subset(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<std::size_t>& from, std::size_t max) {
  if (from.size() <= max) return from;
  if (max == 0) return {};
  // The box of the middle 98 % per axis: a few far or non-finite points
  // must not blow the cells up (they land in the edge cells instead).
  Eigen::AlignedBox3d box;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> coordinate;
    coordinate.reserve(from.size());
    for (std::size_t i : from)
      if (std::isfinite(points[i][a])) coordinate.push_back(points[i][a]);
    if (coordinate.empty()) return stride(from, max);
    std::sort(coordinate.begin(), coordinate.end());
    const std::size_t cut = coordinate.size() / 100;
    box.min()[a] = coordinate[cut];
    box.max()[a] = coordinate[coordinate.size() - 1 - cut];
  }
  const double size = box.sizes().maxCoeff();
  if (!(size > 0) || !std::isfinite(size)) return stride(from, max);
  // Surfaces fill cells by area: start with about `max` cells over the box's
  // largest face and halve the cell area until enough cells are occupied.
  double cell = size / std::sqrt(static_cast<double>(max));
  std::vector<std::size_t> cells = one_per_cell(points, from, box.min(), cell);
  for (int refine = 0; refine < 12 && cells.size() < max; ++refine) {
    cell /= std::sqrt(2.0);
    if (size / cell > double(1 << 20)) break;
    cells = one_per_cell(points, from, box.min(), cell);
  }
  return cells.size() > max ? stride(cells, max) : cells;
}

}  // namespace furrow
