#include "inspection/outlier_detection.hpp"


#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/point_search.hpp"
#include "inspection/registration.hpp"

namespace furrow {

namespace {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

OutlierVerdict classify_deviations(const std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<double>& deviation,
                                   const std::vector<bool>& usable, const OutlierRule& rule,
                                   std::vector<OutlierReason>& reasons) {
  OutlierVerdict v;
  // Sized exactly: at a million points every spare byte per point is a
  // megabyte of the registration's peak (docs/registration.md "Memory").
  std::size_t count = 0;
  for (std::size_t i = 0; i < deviation.size(); ++i) count += usable[i];
  std::vector<double> d;
  std::vector<std::size_t> index;  // usable point -> original index
  d.reserve(count);
  index.reserve(count);
  for (std::size_t i = 0; i < deviation.size(); ++i)
    if (usable[i]) {
      d.push_back(deviation[i]);
      index.push_back(i);
    }
  if (d.empty()) return v;
  v.median = median_of(d);
  std::vector<double> spread(d.size());
  for (std::size_t k = 0; k < d.size(); ++k) spread[k] = std::abs(d[k] - v.median);
  v.robust_sigma = 1.4826 * median_of(spread);
  v.limit = std::max(rule.sigmas * v.robust_sigma, rule.floor);

  std::vector<bool> large(d.size());
  std::size_t large_count = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    large[k] = spread[k] > v.limit;
    large_count += large[k];
    reasons[index[k]] = OutlierReason::none;
  }
  if (large_count == 0) return v;
  spread = std::vector<double>();

  std::vector<Eigen::Vector3d> evaluated(d.size());
  for (std::size_t k = 0; k < d.size(); ++k) evaluated[k] = positions[index[k]];
  const PointSearch search(std::move(evaluated));
  // Agreeing neighbours of each large point: large too, on the same side
  // and alike - within the limit of its value, or within a factor
  // kAlikeRatio of its excess over the median - among its six nearest within
  // the radius. The ratio is there because a real gouge is graded: deep ones
  // have neighbouring points differing by far more than the limit, and the
  // limit alone declared their points blunders one by one. A blunder on or
  // next to a real deviation differs from it by its own unrelated size and
  // mostly stays a blunder.
  // agree[s]: the s-th large point's agreeing neighbours (large points only).
  std::vector<std::vector<std::size_t>> agree(large_count);
  for (std::size_t k = 0, s = 0; k < d.size(); ++k) {
    if (!large[k]) continue;
    std::vector<std::size_t>& mine = agree[s++];
    for (const PointNeighbour& near : search.nearest(positions[index[k]], 7)) {  // self + 6
      const std::size_t j = near.index;
      if (j == k || near.distance > rule.radius || !large[j]) continue;
      const double a = d[j] - v.median, b = d[k] - v.median;
      const bool alike = std::abs(a - b) <= v.limit ||
                         std::max(std::abs(a), std::abs(b)) <= kAlikeRatio * std::min(std::abs(a), std::abs(b));
      if (a * b > 0 && alike) mine.push_back(j);
    }
  }
  // Cores have `confirm` agreeing neighbours; a large point agreeing with a
  // core belongs to the same real deviation (its rim).
  std::vector<bool> core(d.size(), false);
  for (std::size_t k = 0, s = 0; k < d.size(); ++k)
    if (large[k]) core[k] = static_cast<int>(agree[s++].size()) >= rule.confirm;
  for (std::size_t k = 0, s = 0; k < d.size(); ++k) {
    if (!large[k]) continue;
    const std::vector<std::size_t>& mine = agree[s++];
    bool real = core[k];
    for (std::size_t j : mine) real = real || core[j];
    reasons[index[k]] = real ? OutlierReason::large_deviation : OutlierReason::blunder;
  }
  return v;
}

}  // namespace furrow
