#include "geometry/trim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/error.hpp"

namespace furrow {

Trim::Trim(std::vector<UvLoop> loops, const std::string& field) : loops_(std::move(loops)) {
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const std::string where = field + "[" + std::to_string(l) + "]";
    if (loops_[l].size() < 3)
      throw InputError(where + ": a trim loop needs at least 3 (u,v) vertices, got " +
                       std::to_string(loops_[l].size()));
    for (std::size_t k = 0; k < loops_[l].size(); ++k)
      if (!loops_[l][k].allFinite())
        throw InputError(where + "[" + std::to_string(k) + "]: not a finite (u,v) pair");
  }
  build_bands();
}

void Trim::build_bands() {
  bands_.clear();
  if (loops_.empty()) return;
  std::size_t edges = 0;
  v_min_ = std::numeric_limits<double>::infinity();
  v_max_ = -v_min_;
  for (const auto& loop : loops_) {
    edges += loop.size();
    for (const auto& p : loop) {
      v_min_ = std::min(v_min_, p.y());
      v_max_ = std::max(v_max_, p.y());
    }
  }
  // About four edges per band on average keeps a query near O(1).
  const std::size_t count = std::clamp<std::size_t>(edges / 4, 1, 4096);
  band_height_ = std::max((v_max_ - v_min_) / static_cast<double>(count), 1e-300);
  bands_.assign(count, {});
  for (const auto& loop : loops_) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Edge e{loop[k], loop[(k + 1) % loop.size()]};
      const double lo = std::min(e.a.y(), e.b.y()), hi = std::max(e.a.y(), e.b.y());
      const auto first = static_cast<std::size_t>(
          std::clamp((lo - v_min_) / band_height_, 0.0, static_cast<double>(count - 1)));
      const auto last = static_cast<std::size_t>(
          std::clamp((hi - v_min_) / band_height_, 0.0, static_cast<double>(count - 1)));
      for (std::size_t b = first; b <= last; ++b) bands_[b].push_back(e);
    }
  }
}

bool Trim::contains(const Eigen::Vector2d& uv) const {
  if (loops_.empty()) return true;
  if (!(uv.y() >= v_min_ && uv.y() <= v_max_)) return false;
  const auto band = static_cast<std::size_t>(
      std::clamp((uv.y() - v_min_) / band_height_, 0.0, static_cast<double>(bands_.size() - 1)));
  bool inside = false;
  for (const Edge& e : bands_[band]) {
    // Half-open rule: an edge counts when it straddles the horizontal line
    // through uv, lower end included, upper end excluded.
    if ((e.a.y() > uv.y()) != (e.b.y() > uv.y())) {
      const double x = e.a.x() + (uv.y() - e.a.y()) * (e.b.x() - e.a.x()) / (e.b.y() - e.a.y());
      if (x > uv.x()) inside = !inside;
    }
  }
  return inside;
}

namespace {

// Nearest point of segment ab to p.
Eigen::Vector2d nearest_on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

}  // namespace

double Trim::distance_to_boundary(const Eigen::Vector2d& uv) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& loop : loops_)
    for (std::size_t k = 0; k < loop.size(); ++k)
      best = std::min(best, (nearest_on_segment(loop[k], loop[(k + 1) % loop.size()], uv) - uv).norm());
  return best;
}

std::optional<Trim::EdgePoint> Trim::edge_near(const Eigen::Vector2d& uv, double max_distance) const {
  if (loops_.empty() || !(uv.y() >= v_min_ - max_distance && uv.y() <= v_max_ + max_distance)) return std::nullopt;
  // An edge within max_distance overlaps [v - d, v + d], so it is in one of
  // the bands that interval touches.
  const double last_band = static_cast<double>(bands_.size() - 1);
  const auto first = static_cast<std::size_t>(std::clamp((uv.y() - max_distance - v_min_) / band_height_, 0.0, last_band));
  const auto last = static_cast<std::size_t>(std::clamp((uv.y() + max_distance - v_min_) / band_height_, 0.0, last_band));
  std::optional<EdgePoint> best;
  for (std::size_t b = first; b <= last; ++b)
    for (const Edge& e : bands_[b]) {
      const Eigen::Vector2d p = nearest_on_segment(e.a, e.b, uv);
      const double d = (p - uv).norm();
      if (d > max_distance || (best && d >= best->distance) || !((e.b - e.a).norm() > 0)) continue;
      best = EdgePoint{p, (e.b - e.a).normalized(), d};
    }
  return best;
}

}  // namespace furrow
