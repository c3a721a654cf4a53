#pragma once
// Which of the six rigid-motion parameters a registration may change.
//
// Parameters, in this order everywhere (options, covariance, reports):
// rx, ry, rz - rotation vector components [rad] (a rotation about the part
// origin), tx, ty, tz - translation [mm] in the part frame. A locked
// parameter stays exactly at its start value (zero for constrained fits,
// which start from the CMM frame as is: the CMM program's own datum
// alignment is trusted for the locked motions).
#include <array>
#include <string>

namespace furrow {

struct DegreesOfFreedom {
  std::array<bool, 6> free = {true, true, true, true, true, true};

  bool all_free() const;
  int count() const;
  // "all", "translation", "rotation", "none" is refused, or a comma list of
  // the free ones ("tx,ty,rz"). Throws InputError naming `where`.
  static DegreesOfFreedom parse(const std::string& text, const std::string& where);
  // The canonical text: "all", "translation", "rotation" or the list.
  std::string to_string() const;
};

// "rx", "ry", "rz", "tx", "ty", "tz".
const char* dof_name(int index);

}  // namespace furrow
