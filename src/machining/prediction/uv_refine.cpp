#include "machining/prediction/uv_refine.hpp"

#include <algorithm>

#include "base/scalar_search.hpp"

namespace furrow {

double refine_uv_by_axes(const std::function<double(const Eigen::Vector2d&)>& cost,
                         const ParameterDomain& domain, const Eigen::Vector2d& half, double value,
                         Eigen::Vector2d& uv, const UvRefineOptions& options) {
  for (int round = 0; round < options.rounds; ++round) {
    const double before = value;
    for (int axis = 0; axis < 2; ++axis) {
      const double lo = std::max(axis == 0 ? domain.u0 : domain.v0, uv[axis] - half[axis]);
      const double hi = std::min(axis == 0 ? domain.u1 : domain.v1, uv[axis] + half[axis]);
      Eigen::Vector2d trial = uv;
      const ScalarSearchResult r = minimize_unimodal(
          [&](double t) {
            trial[axis] = t;
            return cost(trial);
          },
          lo, hi, {half[axis] * options.relative_tolerance, options.max_iterations});
      if (r.value < value) {
        value = r.value;
        uv[axis] = r.x;
      }
    }
    if (options.stall >= 0 && !(before - value > options.stall)) break;
  }
  return value;
}

}  // namespace furrow
