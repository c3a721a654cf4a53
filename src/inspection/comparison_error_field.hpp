#pragma once
// The systematic error field of a measured part, from its comparison
// (docs/compensation.md "What the field is fitted to").
//
// Which number each measured point gives. A comparison with a prediction
// holds, per point, the residual measured - predicted (prediction_comparison.hpp):
// the furrows, scallops and gouges of the path itself are geometry the
// prediction already explains, and compensating them would chase the cusps
// (a path offset cannot remove a scallop, only move it). So with a
// prediction the sample is the residual, and a point the prediction did not
// reach (not compared) gives no sample. Without a prediction the sample is
// the deviation itself and `prediction_removed` is false: the field then
// also holds the path's own marks, which the caller should say.
// Points that are not evaluated (blunders, beyond an edge, no foot point)
// give none either.
//
// Why here and not in machining/compensation: the comparison is an
// inspection document and machining sits below inspection
// (docs/architecture.md "Module order"); the fit itself is machining's
// (machining/compensation/error_field.hpp) and works on plain samples.
//
// Failure: a point whose face is not that face of `part` (by index and
// name) is an InputError naming `where` and the point: the comparison is of
// another part. The fit's own InputErrors (too many samples on a face) name
// `where` too.
#include <cstddef>
#include <string>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "machining/compensation/error_field.hpp"

namespace furrow {

struct ComparisonErrorField {
  ErrorField field;              // one per face of the part
  bool prediction_removed = false;  // samples are residuals against the prediction
  std::size_t samples = 0;          // points used
  std::size_t not_evaluated = 0;    // points skipped: not evaluated
  std::size_t not_predicted = 0;    // evaluated, but the prediction did not reach them
};

ComparisonErrorField fit_error_field(const ComparisonDocument& comparison, const Part& part,
                                     const ErrorFieldOptions& options, const std::string& where);

}  // namespace furrow
