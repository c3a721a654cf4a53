#include "io/cmm/measurement_qif.hpp"

#include <cmath>
#include <unordered_map>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "io/qif/qif_document.hpp"
#include "io/qif/qif_points_reader.hpp"

namespace furrow {

namespace {

MeasurementSet to_measurement_set(QifMeasuredPoints qif, const std::string& name,
                                  const MeasurementReadOptions& options) {
  MeasurementSet set;
  set.source = name;
  set.ids_from_file = true;
  set.kind = qif.probe_radius ? ProbePointKind::probe_centre : ProbePointKind::contact;
  set.probe_radius = qif.probe_radius.value_or(0.0);
  if (options.kind && *options.kind != set.kind)
    throw InputError(name + ": the file holds " +
                     (qif.probe_radius ? std::string("uncompensated probe centres") : "compensated contact points") +
                     ", not " + (*options.kind == ProbePointKind::contact ? "contact points" : "probe centres") +
                     " (--points)");
  if (qif.probe_radius && options.probe_diameter > 0 &&
      std::abs(options.probe_diameter - 2 * *qif.probe_radius) > 1e-9 * options.probe_diameter)
    throw InputError(name + ": the file's probe radius " + std::to_string(*qif.probe_radius) +
                     " mm does not match the probe diameter " + std::to_string(options.probe_diameter) + " mm");
  if (static_cast<long>(qif.points.size()) > limits::kMaxFilePoints)
    throw InputError(name + ": more than " + std::to_string(limits::kMaxFilePoints) +
                     " measured points (docs/formats.md \"Limits\")");
  std::unordered_map<std::string, int> seen;
  seen.reserve(qif.points.size());
  set.points.reserve(qif.points.size());
  for (QifMeasuredPoint& q : qif.points) {
    const std::string where = name + ":" + std::to_string(q.line);
    for (int a = 0; a < 3; ++a) limits::check_coordinate(q.xyz[a], where + ": " + char('x' + a));
    const auto [it, inserted] = seen.emplace(q.id, q.line);
    if (!inserted)
      throw InputError(where + ": point " + quote_field(q.id) + " measured twice (first on line " +
                       std::to_string(it->second) + "); a document must hold one measurement of one part");
    MeasuredPoint p;
    p.id = std::move(q.id);
    p.xyz = q.xyz;
    p.ijk = q.ijk;
    p.nominal = q.nominal;
    p.nominal_ijk = q.nominal_ijk;
    p.line = q.line;
    set.points.push_back(std::move(p));
  }
  return set;
}

}  // namespace

MeasurementSet parse_qif_measurements(std::string text, const std::string& name,
                                      const MeasurementReadOptions& options) {
  return to_measurement_set(parse_qif_points(std::move(text), name), name, options);
}

MeasurementSet read_qif_measurements(const std::string& path, const MeasurementReadOptions& options) {
  return to_measurement_set(read_qif_points(path), path, options);
}

std::string measurements_to_qif(const MeasurementSet& set, const InspectionPlan* plan,
                                const std::string& part_name) {
  QifDocumentData d;
  d.part_name = part_name;
  d.description = std::string("Furrow ") + FURROW_VERSION + ": measured points of " + set.source;
  d.probe_radius = set.kind == ProbePointKind::probe_centre ? set.probe_radius : 0.0;
  const auto by_id = plan ? plan->index_by_id() : std::unordered_map<std::string, std::size_t>{};
  d.points.reserve(set.points.size());
  for (const MeasuredPoint& m : set.points) {
    QifPoint q;
    q.id = m.id;
    if (const auto it = by_id.find(m.id); it != by_id.end()) {
      q.nominal = plan->points[it->second].xyz;
      q.normal = plan->points[it->second].ijk;
    } else if (m.nominal) {
      q.nominal = *m.nominal;
      q.normal = m.nominal_ijk.value_or(m.ijk.value_or(Eigen::Vector3d::UnitZ()));
      if (!m.nominal_ijk && !m.ijk)
        throw InputError(set.source + ": point " + quote_field(m.id) + " has a nominal but no direction");
    } else {
      throw InputError(set.source + ": point " + quote_field(m.id) +
                       " has no nominal (not in the plan): a QIF point feature needs one");
    }
    if (set.kind == ProbePointKind::probe_centre) {
      // The contact point along the direction the CMM reported, else the nominal's.
      const Eigen::Vector3d n = m.ijk.value_or(q.normal);
      q.probe_centre = m.xyz;
      q.actual = m.xyz - set.probe_radius * n;
    } else {
      q.actual = m.xyz;
    }
    d.points.push_back(std::move(q));
  }
  return qif_results_text(d);
}

}  // namespace furrow
