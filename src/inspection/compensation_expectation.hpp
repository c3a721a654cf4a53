#pragma once
// What a compensated program is expected to leave, at the measured points,
// before it is cut (docs/compensation.md "Predicted before it is cut").
//
// At each evaluated point of the comparison: the measured deviation m
// (docs/architecture.md "Conventions": + material left) [mm], the fitted
// field there f (the faded value compensation applies, and its standard
// error where the face has a fit), the correction the written program
// actually makes there, and the expected residual r = m + d.
//
// Why d is read from the program and not computed as -gain f: the program
// is what gets cut. The offset written at a point of the path is
// -gain f, except where it was clipped (--max-offset: the clipped value),
// cut back against a gouge or by the z-map clip-back (the reduced value),
// or not moved at all (unreachable, no contact, in the air, or where the
// field has faded: 0). So d at a measured point is the applied offset of the
// path point whose contact lies nearest to the point's foot, within `reach`
// (the cutter's radius: a contact farther away does not cut the surface
// at the point); with none within reach the program does not cut there and
// d = 0. The nearest contact stands for the surface cut around it: the
// error of that choice is the field's slope times the contact spacing
// (a 50 um bump over 15 mm with contacts 0.5 mm apart: ~2 um at most).
//
// Statistics per region (the comparison's region ids) and over all points:
// RMS of m and of r, the worst point (largest |value|, first in point
// order on a tie) of each, the RMS of f, and the largest standard error.
// Deterministic: sums in point order.
#include <cstddef>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"
#include "machining/compensation/error_field.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/prediction/path_contacts.hpp"

namespace furrow {

struct ExpectedPoint {
  std::size_t index = 0;    // into comparison.points
  std::string id;
  int region = -1;          // -1: none
  double measured = 0;      // m [mm]
  double field = 0;         // f, faded [mm]
  double standard_error = 0;  // of the unfaded fit at the point [mm]; 0 without a fit
  bool cut = false;         // a path contact lies within reach
  double correction = 0;    // d written there [mm]
  double residual = 0;      // m + d [mm]
};

struct ExpectedStatistics {
  std::size_t count = 0;
  double rms_before = 0, rms_after = 0, rms_field = 0;  // [mm]
  std::string worst_before_id, worst_after_id;
  double worst_before = 0, worst_after = 0;  // signed values at the worst points [mm]
  double largest_standard_error = 0;         // [mm]
};

struct RegionExpectation {
  int region = 0;
  ExpectedStatistics statistics;
};

struct CompensationExpectation {
  double reach = 0;  // [mm]
  ExpectedStatistics overall;
  std::vector<RegionExpectation> regions;  // by increasing id; points without a region only in overall
  std::vector<ExpectedPoint> points;       // evaluated points, in comparison order
};

// `geometry` is the located path `offset` was made from (same passes and
// points). reach > 0 [mm].
CompensationExpectation expect_compensation(const ComparisonDocument& comparison, const ErrorField& field,
                                            const PathGeometry& geometry, const PathOffset& offset, double reach);

}  // namespace furrow
