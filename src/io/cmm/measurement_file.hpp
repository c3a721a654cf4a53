#pragma once
// Measured points from a CMM (docs/architecture.md "Files", docs/formats.md
// "Measurements"): CSV with a header, whitespace-separated XYZ text, or the
// DMIS results a CMM writes for one of our programs.
//
//   CSV   header naming the columns id, x, y, z, i, j, k (any order, any case;
//         id optional; i, j, k together or not at all); one point per line;
//         '#' starts a comment line.
//   XYZ   (.xyz, .txt) "x y z" or "x y z i j k" per line, the same count on
//         every line; ids are the point's 1-based position.
//   DMIS  (.dmi, .dmis, .dmo, .res) F(label)=FEAT/POINT,CART,x,y,z,i,j,k
//         nominals and FA(label)=FEAT/POINT,CART,... actuals; UNITS/MM|INCH
//         is honoured; "$" continues a statement, "$$" starts a comment;
//         other statements and other feature types are skipped.
//
// Coordinates are converted to millimetres at this boundary (CSV and XYZ by
// MeasurementReadOptions::units, DMIS by its own UNITS statement). Points are
// in the CMM's frame; nothing here knows the part.
//
// Probe: a CMM reports either the probe ball's centre (raw, the usual case
// for scanning and for our simulated data) or the contact point it
// compensated itself (the usual case for DMIS results). The kind and the ball
// diameter travel with the set; registration compensates centres along the
// nominal normal inside its loop (docs/architecture.md "Inspection").
//
// Errors: InputError "FILE:LINE: what", one per file: a missing or unknown
// column, a wrong field count, a non-numeric or non-finite field, a zero
// direction vector, a duplicate id (naming the first line too), no points.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

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
  // DMIS only: the nominal F(label) of the same label, part frame [mm].
  std::optional<Eigen::Vector3d> nominal;
  std::optional<Eigen::Vector3d> nominal_ijk;
  int line = 0;  // source line, for messages
};

struct MeasurementSet {
  std::string source;  // file name, for messages and reports
  std::vector<MeasuredPoint> points;
  ProbePointKind kind = ProbePointKind::probe_centre;
  double probe_radius = 0;     // [mm]; 0 for contact points
  bool ids_from_file = false;  // false when ids were generated (XYZ, CSV without id)
};

enum class MeasurementFormat { automatic, csv, xyz, dmis, qif };  // qif: docs/qif.md

struct MeasurementReadOptions {
  MeasurementFormat format = MeasurementFormat::automatic;  // by extension
  std::string units = "mm";  // of CSV and XYZ coordinates ("mm" or "inch")
  // Centres or contact points; unset = centres for CSV/XYZ, contact points
  // for DMIS (what CMMs write there).
  std::optional<ProbePointKind> kind;
  // Probe ball diameter [mm, regardless of `units`]; required (> 0) for centres.
  double probe_diameter = 0;
};

MeasurementSet read_measurements(const std::string& path, const MeasurementReadOptions& options);
// `name` stands for the source in messages; `format` must not be automatic.
MeasurementSet parse_measurements(const std::string& text, const std::string& name,
                                  MeasurementFormat format, const MeasurementReadOptions& options);
MeasurementFormat measurement_format_from_path(const std::string& path);

// CSV writer (id,x,y,z[,i,j,k], shortest exact numbers, a comment line with
// the probe kind and diameter); reading it back reproduces every coordinate.
std::string measurements_to_csv(const MeasurementSet& set);
void write_measurements_csv(const MeasurementSet& set, const std::string& path);

// DMIS text as statements, shared with the reader of Furrow's own DMIS
// programs (dmis_program_reader.hpp): "$$" comments removed, a line ending
// in "$" joined with the next, blank lines dropped; `line` is where the
// statement starts (1-based).
struct DmisStatement {
  int line = 0;
  std::string text;
};
std::vector<DmisStatement> dmis_statements(const std::string& text);

// UNITS/MM or UNITS/INCH: the factor to millimetres; nullopt for another
// statement; InputError "name:line: ..." for another unit.
std::optional<double> dmis_units_scale(const DmisStatement& statement, const std::string& name);

// F(label)=FEAT/POINT,CART,x,y,z,i,j,k (a nominal) or FA(label)=... (an
// actual), coordinates times `scale`, ijk normalised; nullopt for any other
// statement (other feature types included); InputError "name:line: ..." for
// a malformed point (not CART, wrong count, bad number, zero direction).
struct DmisPointFeature {
  std::string label;  // as written
  bool actual = false;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d ijk = Eigen::Vector3d::UnitZ();
};
std::optional<DmisPointFeature> parse_dmis_point_feature(const DmisStatement& statement, const std::string& name,
                                                         double scale);

}  // namespace furrow
