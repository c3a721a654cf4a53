#include "inspection/tolerance_zone.hpp"

#include <cmath>

#include "base/error.hpp"

namespace furrow {

std::string ToleranceZone::disposition() const {
  if (outside == width / 2) return "bilateral";
  if (outside == width) return "unilateral outside";
  if (outside == 0) return "unilateral inside";
  return "unequal";
}

ToleranceZone ToleranceZone::make(double width, double outside, const std::string& where) {
  if (!std::isfinite(width) || !(width > 0))
    throw InputError(where + ": the tolerance must be a positive width in mm");
  if (!std::isfinite(outside) || outside < 0 || outside > width)
    throw InputError(where +
                     ": the outside part of the zone must lie between 0 and the tolerance " +
                     std::to_string(width));
  return ToleranceZone{width, outside};
}

}  // namespace furrow
