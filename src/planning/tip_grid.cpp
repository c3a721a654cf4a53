#include "planning/tip_grid.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace furrow {

namespace {

long axis_count(const IndexAxis& axis) {
  return static_cast<long>(std::floor((axis.max - axis.min) / axis.step + 1e-9)) + 1;
}

// A key equal for equal stylus directions: A in micro-degrees, and B turned
// into [0, 360) in micro-degrees (0 for a vertical stylus).
std::pair<long long, long long> direction_key(const TipAngles& t) {
  const long long a = std::llround(t.a * 1e6);
  if (a == 0 || a == 180000000) return {a, 0};
  long long b = std::llround(t.b * 1e6) % 360000000;
  if (b < 0) b += 360000000;
  return {a, b};
}

}  // namespace

long tip_grid_size(const ProbeHead& head) { return axis_count(head.a) * axis_count(head.b); }

std::vector<TipAngles> tip_grid(const ProbeHead& head) {
  std::map<std::pair<long long, long long>, TipAngles> named;
  for (const TipAngles& t : head.qualified) named.emplace(direction_key(t), t);
  const long na = axis_count(head.a), nb = axis_count(head.b);
  const bool zero_b = head.b.on_grid(0);
  std::map<std::pair<long long, long long>, bool> seen;
  std::vector<TipAngles> out;
  for (long i = 0; i < na; ++i) {
    const double a = head.a.min + static_cast<double>(i) * head.a.step;
    for (long j = 0; j < nb; ++j) {
      TipAngles t{a, head.b.min + static_cast<double>(j) * head.b.step};
      const auto key = direction_key(t);
      if (key.first == 0 || key.first == 180000000) t.b = zero_b ? 0.0 : head.b.min;
      if (!seen.emplace(key, true).second) continue;
      const auto q = named.find(key);
      out.push_back(q != named.end() ? q->second : t);
    }
  }
  return out;
}

std::optional<std::size_t> vertical_orientation(const std::vector<TipAngles>& grid) {
  for (std::size_t k = 0; k < grid.size(); ++k)
    if (grid[k].a == 0) return k;
  return std::nullopt;
}

}  // namespace furrow
