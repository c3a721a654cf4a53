#pragma once
// Measured points from a QIF 3.0 Results document (docs/qif.md "Reading"),
// from Furrow or from other software: every PointFeatureMeasurement (QIF
// 3.0) or PointFeatureActual (older documents) in Results/
// MeasurementResultsSet/MeasurementResults/MeasuredFeatures becomes a point.
//
//   id       the FeatureName of the feature item it measures (FeatureItemId);
//            "item N" when the item has no name
//   xyz      the measurement's Location (a compensated contact point), or -
//            when every point's PointList names a MeasuredPointSet of one
//            uncompensated point (Compensated false, the same ProbeRadius
//            > 0 for all) - that probe centre. A point list naming anything
//            else is not used: the Location is the result, the list detail.
//   ijk      the measurement's Normal if it has one, else the nominal's
//   nominal  the FeatureNominal's Location and Normal
//
// Units: FileUnits/PrimaryUnits/LinearUnit, by UnitConversion/Factor (to
// metres) when present, else by UnitName (mm, millimeter, cm, m, meter,
// in, inch); no FileUnits means millimetres. Every length is converted to
// millimetres here.
//
// Element names are matched without their namespace prefix, so a document
// that binds the QIF namespace to a prefix ("q:QIFDocument") reads the same.
//
// Errors: InputError "NAME:LINE: what" for malformed XML (the line of the
// parser's offset), a root that is not QIFDocument, a reference to a
// missing feature item or nominal, a Location that is not three finite
// numbers, units that are not lengths, a point without Location when the
// points are not all probe centres; "NAME: no measured points ..." when the
// document has none.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace furrow {

struct QifMeasuredPoint {
  std::string id;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  // [mm]
  std::optional<Eigen::Vector3d> ijk;             // unit
  std::optional<Eigen::Vector3d> nominal;         // [mm]
  std::optional<Eigen::Vector3d> nominal_ijk;     // unit
  int line = 0;                                   // of the feature measurement
};

struct QifMeasuredPoints {
  std::vector<QifMeasuredPoint> points;  // in document order
  // Set when the points are uncompensated probe centres: the ball radius
  // [mm] every point set states. Unset: contact points (Location).
  std::optional<double> probe_radius;
};

// `text` is parsed in place (taken by value: pass it moved to avoid a copy
// of a large file). `name` stands for the source in messages.
QifMeasuredPoints parse_qif_points(std::string text, const std::string& name);

// The file at `path`, read into one buffer of its size (a large document is
// held once, not grown and copied) and parsed in place; InputError naming the
// path when it cannot be read.
QifMeasuredPoints read_qif_points(const std::string& path);

}  // namespace furrow
