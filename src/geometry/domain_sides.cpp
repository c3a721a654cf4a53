#include "geometry/domain_sides.hpp"

#include <cmath>

namespace furrow {

unsigned domain_sides(const ParameterDomain& d, const Eigen::Vector2d& uv, double tol) {
  unsigned sides = 0;
  const double tu = tol * d.width_u(), tv = tol * d.width_v();
  if (std::abs(uv.x() - d.u0) <= tu) sides |= kSideUMin;
  else if (std::abs(uv.x() - d.u1) <= tu) sides |= kSideUMax;
  if (std::abs(uv.y() - d.v0) <= tv) sides |= kSideVMin;
  else if (std::abs(uv.y() - d.v1) <= tv) sides |= kSideVMax;
  return sides;
}

Eigen::Vector2d side_uv(const ParameterDomain& d, unsigned side, double t) {
  switch (side) {
    case kSideUMin: return {d.u0, t};
    case kSideUMax: return {d.u1, t};
    case kSideVMin: return {t, d.v0};
    default: return {t, d.v1};
  }
}

std::pair<double, double> side_range(const ParameterDomain& d, unsigned side) {
  return runs_along_v(side) ? std::pair{d.v0, d.v1} : std::pair{d.u0, d.u1};
}

}  // namespace furrow
