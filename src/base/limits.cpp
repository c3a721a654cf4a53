#include "base/limits.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"

namespace furrow::limits {

void check_coordinate(double value, const std::string& where) {
  if (std::isfinite(value) && std::abs(value) <= kMaxCoordinateMm) return;
  std::ostringstream s;
  s.precision(6);
  s << where << ": ";
  if (std::isfinite(value))
    s << value << " mm is outside the coordinate range of ±" << kMaxCoordinateMm
      << " mm (docs/formats.md \"Limits\")";
  else
    s << "not a finite number";  // also a finite file value beyond a double once in mm
  throw InputError(s.str());
}

}  // namespace furrow::limits
