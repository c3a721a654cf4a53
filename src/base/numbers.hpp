#pragma once
// The one pi, and degree/radian conversion: angles are radians inside and
// degrees in files and on the command line (docs/architecture.md
// "Conventions").
namespace furrow {

constexpr double kPi = 3.14159265358979323846;

constexpr double radians(double degrees) { return degrees * (kPi / 180); }
constexpr double degrees(double radians) { return radians * (180 / kPi); }

}  // namespace furrow
