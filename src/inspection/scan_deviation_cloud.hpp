#pragma once
// The deviation cloud of a scan comparison (`--deviations OUT.ply`,
// docs/formats.md "Deviation cloud"): every finite point of the scan in the
// part frame with its deviation and status, as CloudCompare and GOM write a
// cloud with a scalar field. Binary little-endian PLY 1.0, one vertex
// element:
//   double x, y, z      the point in the part frame [mm]
//   float deviation     signed deviation [mm] (+ material left); 0 where the
//                       point was not evaluated
//   uchar outlier       ScanPointStatus: 0 evaluated, 1 spray (far),
//                       2 spray (near the surface), 3 off the part,
//                       4 grazing (seen beyond the largest incidence)
// in the scan file's order (non-finite points left out).
#include <string>

#include "inspection/scan_comparison.hpp"

namespace furrow {

std::string scan_deviation_ply(const ScanComparison& c, const ScanCloud& cloud);

}  // namespace furrow
