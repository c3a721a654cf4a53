#include "io/cmm/measurement_file.hpp"

#include <cmath>
#include <string_view>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/dmis_results.hpp"
#include "io/cmm/ippdme_session.hpp"
#include "io/cmm/ippdme_response_log.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/cmm/measurement_fields.hpp"
#include "io/cmm/measurement_qif.hpp"
#include "io/cmm/measurement_xyz.hpp"
#include "io/part_file.hpp"

namespace furrow {

const char* to_string(ProbePointKind kind) {
  return kind == ProbePointKind::probe_centre ? "centre" : "contact";
}

ProbePointKind parse_probe_point_kind(const std::string& text, const std::string& where) {
  if (text == "centre" || text == "center" || text == "centres" || text == "centers")
    return ProbePointKind::probe_centre;
  if (text == "contact") return ProbePointKind::contact;
  throw InputError(where + ": " + quote_field(text) + " is neither \"centre\" nor \"contact\"");
}

const char* to_string(MeasuredFeatureType type) {
  switch (type) {
    case MeasuredFeatureType::plane: return "plane";
    case MeasuredFeatureType::circle: return "circle";
    case MeasuredFeatureType::cylinder: return "cylinder";
  }
  return "?";
}

namespace {

// The ball the I++ DME answers are centres of: the ER() they report, else
// the given diameter. Registration compensates one radius per set, so the
// answers must agree with each other and with the diameter given for those
// without ER().
double ippdme_ball_diameter(const MeasurementSet& set, const std::string& name, const MeasurementReadOptions& o) {
  const MeasuredPoint* first_er = nullptr;
  const MeasuredPoint* first_without = nullptr;
  for (const MeasuredPoint& p : set.points) {
    if (!p.effective_radius) {
      if (!first_without) first_without = &p;
      continue;
    }
    if (!first_er) first_er = &p;
    if (*p.effective_radius != *first_er->effective_radius)
      measurement_fields::fail(name, p.line, "ER(" + measurement_fields::shortest(*p.effective_radius) +
                                                 ") differs from ER(" + measurement_fields::shortest(*first_er->effective_radius) +
                                                 ") on line " + std::to_string(first_er->line) +
                                                 ": one ball radius per measurement set");
  }
  if (!first_er) return o.probe_diameter;
  const double er = *first_er->effective_radius;
  if (o.kind == ProbePointKind::contact)
    measurement_fields::fail(name, first_er->line, "the answers report ER(), so they are ball centres, not contact points");
  if (first_without && o.probe_diameter > 0 && o.probe_diameter != 2 * er)
    measurement_fields::fail(name, first_without->line, "no ER() here, and the probe diameter " +
                                                            measurement_fields::shortest(o.probe_diameter) +
                                                            " mm is not twice the ER(" + measurement_fields::shortest(er) +
                                                            ") of line " + std::to_string(first_er->line));
  return 2 * er;
}

bool is_dmis_extension(const std::string& ext) {
  return ext == ".dmo" || ext == ".dms" || ext == ".out" || ext == ".dmi" || ext == ".dmis" || ext == ".res";
}

}  // namespace

MeasurementFormat measurement_format_from_path(const std::string& path, const std::string& text) {
  const std::string ext = lower_extension(path);
  // An I++ DME session is told by its content, whatever the file is called
  // (.res, .log, .txt ...: docs/formats.md "Measurements"); without the
  // content the extension decides.
  if (!text.empty() && ext != ".csv" && ext != ".qif" &&
      is_ippdme_response_log(std::string_view(text).substr(has_bom(text) ? 3 : 0)))
    return MeasurementFormat::ippdme_log;
  if (ext == ".csv") return MeasurementFormat::csv;
  if (ext == ".xyz" || ext == ".txt") return MeasurementFormat::xyz;
  if (ext == ".log" || ext == ".ipp") return MeasurementFormat::ippdme_log;
  if (is_dmis_extension(ext)) return MeasurementFormat::dmis;
  if (ext == ".qif") return MeasurementFormat::qif;  // QIF 3.0 Results (measurement_qif.hpp)
  throw InputError(path + ": unknown measurement file type " + quote_field(ext) +
                   " (expected .csv, .xyz/.txt, DMIS .dmo/.dms/.out/.dmi/.dmis/.res, I++ DME .log/.ipp/.res or "
                   "QIF .qif)");
}

MeasurementFormat measurement_output_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".csv") return MeasurementFormat::csv;
  if (ext == ".dmo" || ext == ".dms" || ext == ".out") return MeasurementFormat::dmis;
  if (ext == ".res" || ext == ".log") return MeasurementFormat::ippdme_log;
  if (ext == ".qif") return MeasurementFormat::qif;
  throw InputError(path + ": measurements are written as CSV (.csv), DMIS output (.dmo, .dms, .out), an "
                          "I++ DME response log (.res, .log) or QIF 3.0 Results (.qif); " +
                   quote_field(ext) + " is none of them");
}

std::string measurements_text(const MeasurementSet& set, MeasurementFormat format) {
  // One case per output format; a new writer (e.g. QIF results) adds its case here.
  switch (format) {
    case MeasurementFormat::csv: return measurements_to_csv(set);
    case MeasurementFormat::dmis: return dmis_results_text(set);
    case MeasurementFormat::ippdme_log: return ippdme_response_log_text(set);
    case MeasurementFormat::qif:  // needs the plan: measurements_to_qif (measurement_qif.hpp)
    case MeasurementFormat::xyz:
    case MeasurementFormat::automatic: break;
  }
  throw std::logic_error("measurements_text: no writer for this format (measurement_output_format decides)");
}

MeasurementSet parse_measurements(const std::string& file_text, const std::string& name,
                                  MeasurementFormat format, const MeasurementReadOptions& options) {
  // A byte-order mark (Excel's "CSV UTF-8", some CMM software) is not content.
  // QIF states its own units and probe (docs/qif.md).
  if (format == MeasurementFormat::qif) return parse_qif_measurements(file_text, name, options);
  std::string_view text = file_text;
  if (has_bom(file_text)) text.remove_prefix(3);
  MeasurementSet set;
  set.source = name;
  const CsvDialect& dialect = options.dialect;
  const double scale = dialect.units ? units_to_mm(*dialect.units, name + ": dialect units")
                                     : units_to_mm(options.units, name + ": units");
  switch (format) {
    case MeasurementFormat::csv:
      parse_measurements_csv(text, name, scale, dialect, set);
      break;
    case MeasurementFormat::xyz:
      parse_measurements_xyz(text, name, scale, set);
      break;
    case MeasurementFormat::dmis:
      parse_dmis_results(text, name, set);
      break;
    case MeasurementFormat::ippdme_log: {
      std::optional<IppdmeSession> program;
      if (!options.ippdme_program.empty()) program = read_ippdme_session(options.ippdme_program);
      parse_ippdme_response_log(text, name, program ? &*program : nullptr, options.ippdme_program, set);
      break;
    }
    case MeasurementFormat::qif:
    case MeasurementFormat::automatic:
      throw std::logic_error("parse_measurements: resolve the format first");
  }
  if (set.points.empty())
    throw InputError(name + ": no measured points in the file" +
                     (set.not_measured.empty() ? std::string()
                                               : " (" + std::to_string(set.not_measured.size()) +
                                                     " PtMeas not measured, the first: " + set.not_measured[0].id +
                                                     ": " + set.not_measured[0].reason + ")"));
  // Generated ids (a log's tag and its use, a line number) are unique by
  // construction; only the file's own can repeat. Sorting a million of them
  // costs a log read 4 % for nothing.
  if (set.ids_from_file) measurement_fields::check_unique_ids(set, name);
  if (!std::isfinite(options.probe_diameter) || options.probe_diameter < 0)
    throw InputError(name + ": the probe diameter must be a non-negative number");
  // I++ DME servers answer PtMeas with the ball's centre (docs/formats.md
  // "Probe compensation of I++ DME answers"); DMIS results are compensated.
  const bool compensated = format == MeasurementFormat::dmis;
  set.kind = options.kind.value_or(compensated ? ProbePointKind::contact : ProbePointKind::probe_centre);
  double diameter = options.probe_diameter;
  if (format == MeasurementFormat::ippdme_log) diameter = ippdme_ball_diameter(set, name, options);
  if (set.kind == ProbePointKind::probe_centre && !(diameter > 0))
    throw InputError(name +
                     ": the points are probe centres, so the probe diameter is needed "
                     "(--probe-diameter, or a plan with a probe)");
  set.probe_radius = set.kind == ProbePointKind::probe_centre ? diameter / 2 : 0.0;
  return set;
}

MeasurementSet read_measurements(const std::string& path, const MeasurementReadOptions& options) {
  // The extension is checked before the file is read; only .res needs its content.
  MeasurementFormat format = options.format;
  if (format == MeasurementFormat::automatic) format = measurement_format_from_path(path);
  if (format == MeasurementFormat::qif) return read_qif_measurements(path, options);  // parsed in place
  const std::string text = json_fields::read_text(path);
  if (options.format == MeasurementFormat::automatic) format = measurement_format_from_path(path, text);
  return parse_measurements(text, path, format, options);
}

}  // namespace furrow
