#pragma once
// results.qif: a comparison as a QIF 3.0 Results document (docs/qif.md),
// written by `furrow compare --qif` and into the report folder of
// `furrow report` and `furrow run` (qa_report.hpp). It carries what
// comparison.json says, in QIF's terms:
//
//   the part            Product/PartSet/Part, ModelNumber = the part file
//   each point          PointFeatureNominal (the foot point and the normal),
//                       PointFeatureItem (FeatureName = the point id),
//                       PointFeatureMeasurement (Location = the registered
//                       contact point, part frame)
//   the tolerance       SurfaceProfileCharacteristic over every point
//                       (ToleranceValue = zone width, OuterDisposition for a
//                       zone that is not bilateral; measured Value = the
//                       profile, 2 max |d|) and a PointProfileCharacteristic
//                       per point (Value = the signed deviation)
//   per-point status    PASS in the zone, FAIL outside, NOT_ANALYZED for a
//                       point not evaluated (outlier reasons, docs/registration.md)
//   the verdict         InspectionStatus: PASS, FAIL, or OtherInspectionStatus
//                       "INCONCLUSIVE" (QIF's InspectionStatusEnum has no
//                       such value); the surface profile's status PASS,
//                       FAIL or INDETERMINATE likewise
//   traceability        Header (Furrow and its version), the inputs as
//                       ExternalFileReferences with their SHA-256, and the
//                       time - only when one is given: comparison.json has
//                       none, so `furrow compare` writes none and stays
//                       byte-for-byte reproducible; the QA report gives
//                       its generation time.
//   the record          (the report's inspection record, when given)
//                       InspectionTraceability: customer, CMM program,
//                       operator, report preparer in their QIF elements,
//                       the other fields as AttributeStr (docs/qif.md)
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"
#include "report/inspection_record.hpp"
#include "report/qa_report.hpp"

namespace furrow {

std::string comparison_to_qif(const ComparisonDocument& doc, const std::vector<InputDigest>& inputs,
                              const std::optional<std::string>& time,
                              const std::optional<InspectionRecord>& record = std::nullopt);

// The QIF names of the verdict and of a point's state (docs/qif.md).
const char* qif_characteristic_status(Verdict verdict);           // PASS, FAIL, INDETERMINATE
const char* qif_point_status(const std::optional<bool>& in_tolerance);  // PASS, FAIL, NOT_ANALYZED

}  // namespace furrow
