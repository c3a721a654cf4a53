#pragma once
// Surface profile tolerance zone (ISO 1101 / ASME Y14.5 profile of a
// surface) on the signed deviation d (+ material left, - material removed).
//
// A zone of total width t; `outside` of it lies on the material-added side:
//   bilateral (equal)      outside = t/2   ->  -t/2 <= d <= t/2
//   unilateral outside     outside = t     ->   0   <= d <= t
//   unilateral inside      outside = 0     ->  -t   <= d <= 0
//   unequally disposed     0 < outside < t (ASME's "U" modifier value)
// A deviation on a limit is in tolerance (touching is not violating).
#include <string>

namespace furrow {

struct ToleranceZone {
  double width = 0.05;     // t [mm]
  double outside = 0.025;  // part of the zone on the + side [mm], 0..t

  double upper() const { return outside; }
  double lower() const { return outside - width; }
  bool contains(double deviation) const { return deviation >= lower() && deviation <= upper(); }
  // "bilateral", "unilateral outside", "unilateral inside" or "unequal".
  std::string disposition() const;

  // Throws InputError naming `where` unless 0 < width and 0 <= outside <= width.
  static ToleranceZone make(double width, double outside, const std::string& where);
};

}  // namespace furrow
