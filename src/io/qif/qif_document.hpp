#pragma once
// QIF 3.0 (ISO 23952) documents that Furrow writes (docs/qif.md): a Results
// document (measured points, the surface profile characteristic, per-point
// status, the verdict, traceability) and a Plan document (the planned points
// and the profile characteristic to evaluate). The data is plain: the
// comparison, the plan and the measurement set are converted into it by
// their own layers (report/report_qif, io/qif/plan_qif,
// io/cmm/measurement_qif), so this module needs nothing above io/.
//
// The text is valid by the official QIF 3.0 XSD set (QIFDocument.xsd and
// the files it includes; tests/io/qif/ run xmllint on every written
// document): elements in the order of each xs:sequence, every list with its
// `n` count, ids numbered from 1 in document order with idMax the largest,
// every *Id reference to an element of the document. Lengths are
// millimetres (FileUnits says so); numbers are the shortest text that reads
// back to the same double, without an exponent in xs:decimal elements
// (xs_decimal.hpp).
//
// Deterministic: the same data gives the same bytes. The document's QPId and
// the results' ThisResultsInstanceQPId are UUIDs derived from the SHA-256 of
// the document's own content (qif_uuid.hpp), not random; a time appears only
// when the caller gives one (the report's generation time).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace furrow {

// An input file named in the results' ExternalFileReferences.
struct QifFile {
  std::string role;    // "part", "measurements", "plan", ...
  std::string path;    // as the command line or job gave it
  std::string sha256;  // lower-case hex
};

struct QifPoint {
  std::string id;                                      // FeatureName
  Eigen::Vector3d nominal = Eigen::Vector3d::Zero();   // nominal point [mm], part frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit, out of the material
  // Results only: the measured point [mm] (PointFeatureMeasurement/Location).
  std::optional<Eigen::Vector3d> actual;
  // Results only: the uncompensated probe centre [mm] the actual came from;
  // written as a MeasuredPointSet with Compensated false and the ProbeRadius.
  std::optional<Eigen::Vector3d> probe_centre;
  // Results with a profile: the signed deviation [mm] and the point's
  // CharacteristicStatusEnum ("PASS", "FAIL", "NOT_ANALYZED").
  std::optional<double> deviation;
  std::string status;
  // Under the surface profile characteristic; false for a plan's alignment
  // point, which is measured (first) but not evaluated.
  bool profiled = true;
};

// The surface profile characteristic over all points.
struct QifProfile {
  double tolerance = 0;                    // zone width [mm], ToleranceValue
  // Upper limit of an unequally disposed zone [mm] (OuterDisposition);
  // unset for a bilateral zone.
  std::optional<double> outer_disposition;
  // Results only: the measured profile [mm] and its CharacteristicStatusEnum.
  std::optional<double> value;
  std::string status;
};

// Results only: who and what the inspection was about (Traceability.xsd,
// InspectionTraceabilityType), from the report's inspection record. Fields
// whose QIF element the record can fill go there - InspectionOperator/Name,
// ReportPreparer/Name - and the rest into its Attributes as AttributeStr
// name/value pairs: "customer" and "program" first (QIF's
// CustomerOrganization needs a CustomerNumber, its InspectionProgram a
// FormalStandardId and an Author, which a record does not have), then
// `attributes` in the given order (part number, revision, serial, lot, CMM,
// probe, qualification date, temperature, notes). Empty texts are left out.
struct QifTraceability {
  std::string customer, program, operator_name, report_preparer;
  std::vector<std::pair<std::string, std::string>> attributes;
};

// Results only: how the measured points reached the part frame
// (MeasurementResults/ActualTransforms, IntermediatesPMI.xsd
// TransformInstanceType): the transform CMM -> part, written as QIF's
// Rotation (XDirection, YDirection, ZDirection: the matrix's columns, the
// part-frame directions of the CMM's axes) and Origin (the translation),
// named after the method ("bestfit", "cmm", "datums", "rps"), which an
// AttributeStr "alignment" also carries for a reader that looks it up.
struct QifAlignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // [mm]
  std::string method;
  std::string name;  // the Transform's Name, in words
};

struct QifDocumentData {
  std::string part_name;       // Part/ModelNumber
  std::string description;     // Header/Description (what made the document)
  std::vector<QifFile> inputs;
  // An xs:dateTime (ISO 8601, e.g. 2026-11-25T12:00:00Z); none: no time in
  // the document.
  std::optional<std::string> time;
  double probe_radius = 0;          // [mm] of every probe_centre
  std::vector<QifPoint> points;
  std::optional<QifProfile> profile;
  // Results only: InspectionStatusEnum ("PASS", "FAIL", "NOT_CALCULATED"...)
  // or, when `inspection_status_other`, the text of OtherInspectionStatus.
  std::string inspection_status = "NOT_CALCULATED";
  bool inspection_status_other = false;
  std::optional<QifTraceability> traceability;  // Results only
  std::optional<QifAlignment> alignment;        // Results only
};

// The QIF Results document: Features (nominals and items), the profile
// characteristic (surface profile over all points and a point profile per
// point) when `profile` is set, Results with one MeasurementResults. Every
// point must have `actual`. Throws std::invalid_argument for data that is
// not a document (a point without actual, a non-finite number, a time that
// is not an xs:dateTime, a decimal of 24 integer digits or more).
std::string qif_results_text(const QifDocumentData& data);

// The QIF Plan document: Features and the surface profile characteristic
// (Definition, Nominal, Item over every point), no Results.
std::string qif_plan_text(const QifDocumentData& data);

// The namespace every QIF 3 document declares.
inline constexpr const char* kQifNamespace = "http://qifstandards.org/xsd/qif3";

}  // namespace furrow
