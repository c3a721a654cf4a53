#include "planning/low_discrepancy.hpp"

#include <algorithm>
#include <cmath>

namespace furrow {

double radical_inverse(std::uint64_t index, unsigned base) {
  const double inverse_base = 1.0 / base;
  double factor = inverse_base, value = 0;
  while (index > 0) {
    value += static_cast<double>(index % base) * factor;
    index /= base;
    factor *= inverse_base;
  }
  return value;
}

namespace {

// [0, 1) from the top 53 bits of a 64-bit draw: independent of the
// library's distribution implementation, so a seed means the same plan
// everywhere.
double unit_draw(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double wrap(double x) {
  x -= std::floor(x);
  return x < 1.0 ? x : 0.0;  // x = 1 - tiny can round to 1
}

}  // namespace

Eigen::Vector2d rotation_from_seed(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const double a = unit_draw(rng);
  return {a, unit_draw(rng)};
}

Eigen::Vector2d rotate(const Eigen::Vector2d& p, const Eigen::Vector2d& shift) {
  return {wrap(p.x() + shift.x()), wrap(p.y() + shift.y())};
}

Eigen::Vector2d halton_point(std::uint64_t index) {
  return {radical_inverse(index, 2), radical_inverse(index, 3)};
}

std::vector<Eigen::Vector2d> hammersley_set(std::size_t n) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    points.emplace_back((static_cast<double>(i) + 0.5) / static_cast<double>(n), radical_inverse(i, 2));
  return points;
}

Eigen::Vector2i strata_for(std::size_t n, double aspect) {
  n = std::max<std::size_t>(n, 1);
  aspect = std::isfinite(aspect) && aspect > 0 ? aspect : 1.0;
  const double nx_real = std::sqrt(static_cast<double>(n) * aspect);
  const int nx = std::max(1, static_cast<int>(std::lround(nx_real)));
  const int ny = std::max(1, static_cast<int>((n + nx - 1) / static_cast<std::size_t>(nx)));
  return {nx, ny};
}

std::vector<Eigen::Vector2d> grid_set(const Eigen::Vector2i& strata) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<std::size_t>(strata.x()) * strata.y());
  for (int j = 0; j < strata.y(); ++j)
    for (int i = 0; i < strata.x(); ++i)
      points.emplace_back((i + 0.5) / strata.x(), (j + 0.5) / strata.y());
  return points;
}

std::vector<Eigen::Vector2d> stratified_set(const Eigen::Vector2i& strata, std::mt19937_64& rng) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<std::size_t>(strata.x()) * strata.y());
  for (int j = 0; j < strata.y(); ++j)
    for (int i = 0; i < strata.x(); ++i) {
      const double a = unit_draw(rng);
      const double b = unit_draw(rng);
      points.emplace_back(std::min((i + a) / strata.x(), std::nextafter(1.0, 0.0)),
                          std::min((j + b) / strata.y(), std::nextafter(1.0, 0.0)));
    }
  return points;
}

Eigen::Vector2d random_point(std::mt19937_64& rng) {
  const double a = unit_draw(rng);
  return {a, unit_draw(rng)};
}

}  // namespace furrow
