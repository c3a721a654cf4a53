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
                              const std::optional<std::string>& time) {
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
  d.inspection_status = to_string(doc.summary.verdict);
  d.inspection_status_other = doc.summary.verdict == Verdict::inconclusive;
  return qif_results_text(d);
}

}  // namespace furrow
