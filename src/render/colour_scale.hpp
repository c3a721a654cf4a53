#pragma once
// Colours for deviations, shared by every report figure so a colour means
// the same number everywhere.
//
// A diverging scale: blue for negative values (overcut: material removed
// below nominal), white at zero, red for positive values (undercut: material
// left), linear in the value and saturated beyond +-range. Reports choose
// range = max(tolerance, largest |deviation|) so in-tolerance points never
// look alarming and the extremes still differ. Ends are dark enough to read
// against white paper. Colours are sRGB bytes.
#include <array>

namespace furrow {

using Rgb = std::array<unsigned char, 3>;

// t in [-1, 1] (clamped; NaN maps to grey): -1 dark blue, 0 white, +1 dark red.
Rgb diverging_colour(double t);

// The scale for one figure: value / range, clamped. Preconditions: range > 0.
struct DeviationScale {
  double range = 1;  // [mm]
  Rgb colour(double value) const { return diverging_colour(value / range); }
};

// Colour of a categorical status (gouge confirmation, pass/fail), by name:
// "CONFIRMED" red, "NOT CONFIRMED" green, "NOT MEASURED" grey, "UNEXPLAINED"
// purple, "PASS" green, "FAIL" red; anything else dark grey.
Rgb status_colour(const char* status);

// Colour of a curvature class by name, the same as the partition's figures
// (regions.png, plan.png): "convex" orange, "concave" blue, "saddle" green,
// "planar" sand; anything else light grey (outside every region).
Rgb curvature_class_colour(const char* curvature_class);

}  // namespace furrow
