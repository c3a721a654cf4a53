#pragma once
// Measured points from a CMM (docs/architecture.md "Files", docs/formats.md
// "Measurements"): the types every measurement reader fills, and the choice
// of reader by format, extension or content. One reader per format:
//
//   CSV   measurement_csv.hpp: a header naming the columns, any delimiter,
//         decimal mark and header names (csv_dialect.hpp), nominal/actual
//         point tables.
//   XYZ   measurement_xyz.hpp: (.xyz, .txt) "x y z [i j k]" per line.
//   DMIS  dmis_results.hpp: (.dmo, .dms, .out, .dmi, .dmis, .res) FA()
//         actuals of points, planes, circles and cylinders.
//   I++   ippdme_response_log.hpp: (.log, .ipp, and any file whose content
//         is an I++ DME session) a server's answers to any client's
//         program: .res, plain and time-stamped session logs.
//
// Coordinates are converted to millimetres at this boundary (CSV and XYZ by
// MeasurementReadOptions::units or the dialect's units, DMIS by its own UNITS
// statement; I++ DME servers report millimetres). Points are in the CMM's
// frame; nothing here knows the part.
//
// Probe: a CMM reports either the probe ball's centre (raw, the usual case
// for scanning, for our simulated data and for I++ DME PtMeas answers, whose
// ER() gives the radius) or the contact point it compensated itself (the
// usual case for DMIS results).
// The kind and the ball diameter travel with the set; registration
// compensates centres along the nominal normal inside its loop
// (docs/architecture.md "Inspection").
//
// Errors: InputError "FILE:LINE: what", one per file: a missing or unknown
// column, a wrong field count, a non-numeric or non-finite field (naming its
// column), a zero direction vector, a duplicate id (naming the first line
// too), no points.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/cmm/csv_dialect.hpp"

namespace furrow {

enum class ProbePointKind { probe_centre, contact };
const char* to_string(ProbePointKind kind);
// "centre"/"center" or "contact"; throws InputError naming `where`.
ProbePointKind parse_probe_point_kind(const std::string& text, const std::string& where);

struct MeasuredPoint {
  std::string id;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  // [mm], CMM frame
  // Unit vector the CMM reported with the point (i, j, k), if any.
  std::optional<Eigen::Vector3d> ijk;
  // The nominal the file gives with the point (DMIS F(label), the nominal
  // columns of a CSV point table, the PtMeas target of an I++ DME program),
  // part frame [mm].
  std::optional<Eigen::Vector3d> nominal;
  std::optional<Eigen::Vector3d> nominal_ijk;
  // DMIS: label of the datum set in force (the last D(x)=DATSET/... before
  // the actual), as written; empty when none. Recorded, not applied.
  std::string datum;
  int line = 0;  // source line, for messages
  // I++ DME: the effective ball radius ER() the server reported with the
  // point (it answers with the ball's centre); see MeasurementSet::kind.
  std::optional<double> effective_radius;
  // Relative weight in the registration: the point's residual enters the
  // fit multiplied by it (1/sigma relative to the set's other points;
  // positive and finite). Every reader leaves 1; a scan's fit points carry
  // cos(incidence) (docs/scan.md "Weights"). Deviations are never weighted.
  double weight = 1;
};

// A point the file says was to be measured but was not (an I++ DME PtMeas
// the server answered with an error, or did not answer): reported, counted,
// never a pass (docs/formats.md "Reading any I++ DME session").
struct UnmeasuredPoint {
  std::string id;
  std::optional<Eigen::Vector3d> nominal;  // the target, when the file has it
  std::string reason;                      // e.g. the server's error text
  int line = 0;
};

// A measured datum feature (DMIS FA() of a plane, circle or cylinder), as
// the CMM reported it: position and direction in the CMM's frame [mm],
// diameter (and cylinder length when given) [mm]; 0 where the type has none.
enum class MeasuredFeatureType { plane, circle, cylinder };
const char* to_string(MeasuredFeatureType type);
struct MeasuredFeature {
  std::string label;
  MeasuredFeatureType type = MeasuredFeatureType::plane;
  bool inner = false;  // circle, cylinder: INNER (a hole) or OUTER (a boss)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
  double diameter = 0;
  double length = 0;
  std::string datum;  // as MeasuredPoint::datum
  int line = 0;
};

struct MeasurementSet {
  std::string source;  // file name, for messages and reports
  std::vector<MeasuredPoint> points;
  std::vector<MeasuredFeature> features;  // DMIS datum features; points stay in `points`
  std::vector<UnmeasuredPoint> not_measured;  // I++ DME PtMeas without a point
  ProbePointKind kind = ProbePointKind::probe_centre;
  double probe_radius = 0;     // [mm]; 0 for contact points
  bool ids_from_file = false;  // false when ids were generated (XYZ, CSV without id)
};

enum class MeasurementFormat { automatic, csv, xyz, dmis, ippdme_log, qif };  // qif: docs/qif.md

struct MeasurementReadOptions {
  MeasurementFormat format = MeasurementFormat::automatic;  // by extension
  std::string units = "mm";  // of CSV and XYZ coordinates ("mm" or "inch")
  CsvDialect dialect;        // CSV only; its units, when set, replace `units`
  // I++ DME sessions: the program (.prg, any client's) the server ran, to
  // match the responses to its PtMeas commands (ippdme_response_log.hpp);
  // empty: none.
  std::string ippdme_program;
  // Centres or contact points; unset = centres for CSV/XYZ/I++ DME, contact
  // points for DMIS (what CMMs write there).
  std::optional<ProbePointKind> kind;
  // Probe ball diameter [mm, regardless of `units`]; required (> 0) for
  // centres, except I++ DME answers that carry ER() (docs/formats.md "Probe
  // compensation of I++ DME answers").
  double probe_diameter = 0;
};

MeasurementSet read_measurements(const std::string& path, const MeasurementReadOptions& options);
// `name` stands for the source in messages; `format` must not be automatic.
MeasurementSet parse_measurements(const std::string& text, const std::string& name,
                                  MeasurementFormat format, const MeasurementReadOptions& options);
// By content first: any file but .csv and .qif whose `text` (the content,
// when known) is an I++ DME session (is_ippdme_response_log); then by
// extension, in any case: .csv, .xyz/.txt, DMIS .dmo/.dms/.out/.dmi/.dmis/
// .res, I++ DME .log/.ipp. InputError for another extension.
MeasurementFormat measurement_format_from_path(const std::string& path, const std::string& text = "");

// The format a measurement file is written in by `furrow simulate-measurement
// --out` (.csv, DMIS .dmo/.dms/.out, I++ DME .res/.log); InputError naming
// the path for any other extension, before anything is written.
MeasurementFormat measurement_output_format(const std::string& path);
// The text of `set` in `format` (measurement_output_format), numbers in
// their shortest exact form so that reading the file back gives the same
// coordinates bit for bit.
std::string measurements_text(const MeasurementSet& set, MeasurementFormat format);

}  // namespace furrow
