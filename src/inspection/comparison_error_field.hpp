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
// A prediction given apart (`furrow compensate --prediction`: a comparison
// made without one, or a prediction of the path as it is now) takes the
// place of the comparison's: the sample is the point's deviation minus the
// prediction's error at its foot (Prediction::predicted_error_at, the
// error map's cell means interpolated: the furrows and cusps the path
// leaves there), and a point whose face the prediction lacks or whose cell
// it did not reach gives no sample. Unlike `furrow compare --prediction`
// the placement is not re-fitted to the predicted surface first (the
// deviations are taken as the comparison registered them). The caller
// checks the prediction against the part (check_prediction_against_part).
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
#include "machining/prediction/prediction.hpp"

namespace furrow {

struct ComparisonErrorField {
  ErrorField field;              // one per face of the part
  bool prediction_removed = false;  // samples are residuals against the prediction
  bool prediction_given = false;    // ... against the one given apart, not the comparison's
  std::size_t samples = 0;          // points used
  std::size_t not_evaluated = 0;    // points skipped: not evaluated
  std::size_t not_predicted = 0;    // evaluated, but the prediction did not reach them
};

// `prediction` (may be null): one given apart, see above.
ComparisonErrorField fit_error_field(const ComparisonDocument& comparison, const Part& part,
                                     const ErrorFieldOptions& options, const std::string& where,
                                     const Prediction* prediction = nullptr);

}  // namespace furrow
