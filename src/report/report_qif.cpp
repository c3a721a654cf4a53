#include "report/report_qif.hpp"

#include "io/qif/qif_document.hpp"

namespace furrow {

const char* qif_characteristic_status(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass: return "PASS";
    case Verdict::fail: return "FAIL";
    case Verdict::inconclusive: return "INDETERMINATE";
  }
  return "UNDEFINED";
}

const char* qif_point_status(const std::optional<bool>& in_tolerance) {
  if (!in_tolerance) return "NOT_ANALYZED";
  return *in_tolerance ? "PASS" : "FAIL";
}

std::string comparison_to_qif(const ComparisonDocument& doc, const std::vector<InputDigest>& inputs,
                              const std::optional<std::string>& time,
                              const std::optional<InspectionRecord>& record) {
  QifDocumentData d;
  d.part_name = doc.sources.part;
  d.description = std::string("Furrow ") + FURROW_VERSION + ": surface profile inspection of " + doc.sources.part +
                  " from " + doc.sources.measurements;
  d.time = time;
  for (const InputDigest& in : inputs) d.inputs.push_back({in.role, in.path, in.sha256});
  d.points.reserve(doc.points.size());
  for (const ComparisonDocument::Point& p : doc.points) {
    QifPoint q;
    q.id = p.id;
    q.nominal = p.foot;
    q.normal = p.normal;
    q.actual = p.contact;
    q.deviation = p.deviation;
    q.status = qif_point_status(p.in_tolerance);
    d.points.push_back(std::move(q));
  }
  const ToleranceZone& zone = doc.options.tolerance;
  QifProfile profile;
  profile.tolerance = zone.width;
  if (zone.outside != zone.width / 2) profile.outer_disposition = zone.outside;
  profile.value = doc.summary.profile;
  profile.status = qif_characteristic_status(doc.summary.verdict);
  d.profile = profile;
  // The alignment the actuals went through (CMM -> part).
  const ComparisonDocument::Alignment& a = doc.alignment;
  QifAlignment qa;
  qa.rotation = doc.registration.transform.topLeftCorner<3, 3>();
  qa.origin = doc.registration.transform.topRightCorner<3, 1>();
  qa.method = a.method;
  qa.name = a.method == "bestfit" ? "CMM to part: best fit of the measured points"
            : a.method == "cmm"   ? "CMM to part: identity, the CMM program aligned the part"
            : a.method == "rps"   ? "CMM to part: reference point system"
                                  : "CMM to part: datum reference frame";
  d.alignment = qa;
  d.inspection_status = to_string(doc.summary.verdict);
  d.inspection_status_other = doc.summary.verdict == Verdict::inconclusive;
  if (record) {
    QifTraceability t;
    t.customer = record->customer;
    t.program = record->program;
    t.operator_name = record->operator_name;
    t.report_preparer = record->prepared.name;
    // Fields QIF has no element for in InspectionTraceability, by their
    // record file names (docs/formats.md "Inspection record").
    for (const InspectionRecord::Field& f : record->fields()) {
      const std::string key = f.key;
      if (key != "customer" && key != "program" && key != "operator") t.attributes.emplace_back(key, f.value);
    }
    // The prepared-by name is ReportPreparer; the rest of the sign-off too
    // has no element of its own.
    for (const auto& [role, s] : {std::pair<std::string, const SignOff*>{"prepared", &record->prepared},
                                  {"checked", &record->checked},
                                  {"approved", &record->approved}}) {
      if (role != "prepared") t.attributes.emplace_back(role + "_by", s->name);
      t.attributes.emplace_back(role + "_date", s->date);
    }
    d.traceability = std::move(t);
  }
  return qif_results_text(d);
}

}  // namespace furrow
