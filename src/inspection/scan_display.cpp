// The display sample and histogram of a scan (contract in scan_display.hpp).
#include "inspection/scan_display.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "inspection/scan_comparison.hpp"

namespace furrow {

namespace {

constexpr int kMaxGridPasses = 200;

// 0.1 um: far below what a colour shows, and the sample's JSON stays short.
double round_coordinate(double x) { return std::round(x * 1e4) / 1e4; }

// Occupied voxels of edge h, each with its worst point (index into `points`).
std::vector<std::size_t> worst_per_voxel(const std::vector<Eigen::Vector3d>& points, const std::vector<float>& dev,
                                         const Eigen::Vector3d& low, double h) {
  std::unordered_map<std::uint64_t, std::size_t> cells;
  cells.reserve(points.size() / 4 + 16);
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
      // At most 2^21 cells per axis: the first grid has about 8 sqrt(cap)
      // cells along the extent, far fewer.
      const double cell = std::floor((points[k][a] - low[a]) / h);
      key = (key << 21) | static_cast<std::uint64_t>(std::clamp(cell, 0.0, 2097151.0));
    }
    const auto [it, inserted] = cells.emplace(key, k);
    if (!inserted && std::fabs(dev[k]) > std::fabs(dev[it->second])) it->second = k;
  }
  std::vector<std::size_t> kept;
  kept.reserve(cells.size());
  for (const auto& cell : cells) kept.push_back(cell.second);
  std::sort(kept.begin(), kept.end());  // file order, whatever the hash order
  return kept;
}

}  // namespace

ScanDisplay scan_display(const ScanComparison& c, const ScanCloud& cloud, std::size_t cap) {
  ScanDisplay d;
  d.cap = std::max<std::size_t>(cap, 1);
  std::vector<std::size_t> index;
  std::vector<Eigen::Vector3d> points;
  std::vector<float> dev;
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    if (c.status[i] != ScanPointStatus::evaluated) continue;
    index.push_back(i);
    // As the deviation cloud writes it (scan_deviation_cloud.cpp).
    points.push_back(c.registration.transform * (cloud.points[i] - c.pre.origin));
    dev.push_back(c.deviation[i]);
  }
  std::vector<std::size_t> kept;
  if (points.size() <= d.cap) {
    kept.resize(points.size());
    for (std::size_t k = 0; k < kept.size(); ++k) kept[k] = k;
  } else {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : points) box.extend(p);
    // A surface of extent L holds about (L / h)^2 voxels: start at a quarter
    // of the edge that would give the cap on a flat square, then grow by the
    // square root of the excess (at least 5 %) until under the cap.
    double h = std::max(box.diagonal().norm(), 1e-9) / std::sqrt(static_cast<double>(d.cap)) / 4;
    for (int pass = 0; pass < kMaxGridPasses; ++pass) {
      kept = worst_per_voxel(points, dev, box.min(), h);
      d.grid_passes = static_cast<std::size_t>(pass) + 1;
      d.voxel = h;
      if (kept.size() <= d.cap) break;
      h *= std::max(1.05, std::sqrt(static_cast<double>(kept.size()) / static_cast<double>(d.cap)));
    }
    // 200 passes grow the edge by at least 1.05^200 = 17 000 times, beyond
    // the extent: one voxel per corner at most; a cap under 8 may still be
    // exceeded there, so the list is cut to its first `cap` points.
    if (kept.size() > d.cap) kept.resize(d.cap);
  }
  for (const std::size_t k : kept) {
    d.index.push_back(index[k]);
    const Eigen::Vector3d& p = points[k];
    d.points.emplace_back(round_coordinate(p.x()), round_coordinate(p.y()), round_coordinate(p.z()));
    d.deviation.push_back(dev[k]);
  }
  return d;
}

ScanHistogram scan_histogram(const ScanComparison& c, int bins) {
  ScanHistogram h;
  bins = std::max(bins, 1);
  double lo = std::min(c.tolerance.lower(), 0.0), hi = std::max(c.tolerance.upper(), 0.0);
  for (std::size_t i = 0; i < c.status.size(); ++i)
    if (c.status[i] == ScanPointStatus::evaluated) {
      lo = std::min(lo, static_cast<double>(c.deviation[i]));
      hi = std::max(hi, static_cast<double>(c.deviation[i]));
    }
  const double pad = 0.05 * std::max(hi - lo, 1e-6);
  lo -= pad;
  hi += pad;
  for (int k = 0; k <= bins; ++k) h.edges.push_back(k == bins ? hi : lo + (hi - lo) * k / bins);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (std::size_t i = 0; i < c.status.size(); ++i) {
    if (c.status[i] != ScanPointStatus::evaluated) continue;
    const double v = c.deviation[i];
    // The bin by the edges as written, not by arithmetic: a recount from
    // the file's edges gives the same bin.
    const auto above = std::upper_bound(h.edges.begin(), h.edges.end(), v);
    const long k = std::clamp<long>(static_cast<long>(above - h.edges.begin()) - 1, 0, bins - 1);
    ++h.counts[static_cast<std::size_t>(k)];
  }
  return h;
}

}  // namespace furrow
