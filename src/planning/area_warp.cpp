#include "planning/area_warp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace furrow {

AreaWarp::AreaWarp(const Eigen::AlignedBox2d& box, int cells,
                   const std::function<double(double, double)>& density)
    : box_(box), cells_(cells) {
  if (cells < 1) throw std::invalid_argument("AreaWarp: cells must be at least 1");
  const int n = cells;
  const Eigen::Vector2d size = box.sizes();
  std::vector<double> w(static_cast<std::size_t>(n) * n);
  std::vector<double> column(static_cast<std::size_t>(n), 0.0);
  double total = 0;
  for (int i = 0; i < n; ++i) {
    const double u = box.min().x() + (i + 0.5) / n * size.x();
    for (int j = 0; j < n; ++j) {
      const double v = box.min().y() + (j + 0.5) / n * size.y();
      const double d = density(u, v);
      if (!std::isfinite(d) || d < 0) throw std::invalid_argument("AreaWarp: density must be finite and >= 0");
      w[static_cast<std::size_t>(i) * n + j] = d;
      column[static_cast<std::size_t>(i)] += d;
    }
    total += column[static_cast<std::size_t>(i)];
  }
  if (!(total > 0) || !std::isfinite(total)) throw std::invalid_argument("AreaWarp: the density is zero everywhere");
  u_cdf_.assign(static_cast<std::size_t>(n) + 1, 0.0);
  for (int i = 0; i < n; ++i) u_cdf_[i + 1] = u_cdf_[i] + column[i] / total;
  u_cdf_[n] = 1.0;
  v_cdf_.assign(static_cast<std::size_t>(n) * (n + 1), 0.0);
  for (int i = 0; i < n; ++i) {
    double* cdf = &v_cdf_[static_cast<std::size_t>(i) * (n + 1)];
    const double c = column[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j)
      cdf[j + 1] = c > 0 ? cdf[j] + w[static_cast<std::size_t>(i) * n + j] / c : (j + 1.0) / n;
    cdf[n] = 1.0;
  }
}

double AreaWarp::invert(const double* cdf, int n, double p) {
  p = std::clamp(p, 0.0, 1.0);
  // First node with cdf > p; the interval before it holds p. Zero-width
  // intervals (zero density) are never chosen because upper_bound skips them.
  const double* hi = std::upper_bound(cdf, cdf + n + 1, p);
  if (hi == cdf + n + 1) {  // p == 1: last interval with positive width
    int k = n;
    while (k > 0 && cdf[k - 1] >= 1.0) --k;
    return k;
  }
  const int k = static_cast<int>(hi - cdf) - 1;  // cdf[k] <= p < cdf[k+1]
  const double width = cdf[k + 1] - cdf[k];
  return k + (width > 0 ? (p - cdf[k]) / width : 0.0);
}

Eigen::Vector2d AreaWarp::map(const Eigen::Vector2d& st) const {
  const int n = cells_;
  const double x = invert(u_cdf_.data(), n, st.x());
  const int column = std::min(n - 1, static_cast<int>(x));
  const double y = invert(&v_cdf_[static_cast<std::size_t>(column) * (n + 1)], n, st.y());
  const Eigen::Vector2d size = box_.sizes();
  return {box_.min().x() + std::min(x / n, 1.0) * size.x(), box_.min().y() + std::min(y / n, 1.0) * size.y()};
}

}  // namespace furrow
