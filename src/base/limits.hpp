#pragma once
// The physical ranges and work caps every reader and command enforces
// (docs/formats.md "Limits"). A value outside them is bad input: it is
// refused where it is read, with the file and field named, before any work
// or allocation depends on it.
#include <string>

namespace furrow::limits {

// Part, measurement, contact-point and tool-path coordinates, in mm after unit
// conversion: |x|, |y|, |z| at most this (a 2 km part is not machined).
constexpr double kMaxCoordinateMm = 1e6;
// A scan's coordinates as its file holds them, in mm: a scanner's or a
// site's frame may lie far from the part (docs/scan.md "Precision"); the
// registration brings the points into the part frame, where the limit above
// holds again.
constexpr double kMaxScanCoordinateMm = 1e8;
// NURBS weights: each in [kMinWeight, kMaxWeight], the largest of a face at
// most kMaxWeightRatio times its smallest.
constexpr double kMinWeight = 1e-6;
constexpr double kMaxWeight = 1e6;
constexpr double kMaxWeightRatio = 1e6;
// NURBS knots: |knot| at most this (parameters are unit-free).
constexpr double kMaxKnot = 1e9;
// Cutter sizes: diameter in [kMinToolDiameterMm, kMaxToolDiameterMm]; a
// non-zero corner radius at least half the smallest diameter.
constexpr double kMinToolDiameterMm = 1e-3;
constexpr double kMaxToolDiameterMm = 1e4;
constexpr double kMinCornerRadiusMm = 0.5e-3;
// Probe ball diameter, mm.
constexpr double kMinProbeDiameterMm = 1e-3;
constexpr double kMaxProbeDiameterMm = 1e3;
// Points read from one file (tool path, contact points, measurements, plan).
constexpr long kMaxFilePoints = 10'000'000;
// Planned probe points (--points, or --density times the area).
constexpr long kMaxPlanPoints = 1'000'000;
// Tool-path planning: passes and contact points of one generated path.
constexpr long kMaxToolpathPasses = 100'000;
constexpr long kMaxToolpathPoints = 20'000'000;

// Throws InputError "`where`: VALUE is outside ±1e6 mm ..." unless `value`
// is finite and within kMaxCoordinateMm.
void check_coordinate(double value, const std::string& where);

}  // namespace furrow::limits
