#pragma once
// Measured points as QIF 3.0 Results and back (docs/qif.md): the bridge
// between the measurement set of measurement_file.hpp and the QIF module
// (io/qif/), which sits below io/cmm in the module order and so does not
// know MeasurementSet.
//
// Reading: parse_qif_points (io/qif/qif_points_reader.hpp). The file states
// what its points are: uncompensated probe centres with their ProbeRadius,
// or compensated contact points. `options.kind` and `options.probe_diameter`,
// when given, must agree with it (a contradiction is an InputError), as a
// command line cannot change what a CMM measured.
//
// Writing: a QIF Results document of the raw measurement - features and
// feature measurements, no characteristic evaluated (InspectionStatus
// NOT_CALCULATED). Probe centres are written as one-point MeasuredPointSets
// (Compensated false, ProbeRadius) next to a Location compensated along the
// point's ijk, so that reading it back gives the same centres bit for bit.
// Each point's nominal comes from `plan` (same id) or from the point's own
// nominal; a point with neither is an InputError, since a QIF point feature
// is measured against a nominal.
#include <string>

#include "io/cmm/measurement_file.hpp"
#include "io/plan_file.hpp"

namespace furrow {

MeasurementSet parse_qif_measurements(std::string text, const std::string& name,
                                      const MeasurementReadOptions& options);
// The file at `path` (read_qif_points: one buffer, parsed in place).
MeasurementSet read_qif_measurements(const std::string& path, const MeasurementReadOptions& options);

// `plan` may be null; `part_name` names the part in the document.
std::string measurements_to_qif(const MeasurementSet& set, const InspectionPlan* plan,
                                const std::string& part_name);

}  // namespace furrow
