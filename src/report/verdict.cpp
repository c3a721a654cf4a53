#include "report/verdict.hpp"

#include <cstdio>

#include "base/number_text.hpp"

namespace furrow {

namespace {

std::string um(double mm) { return fixed(mm * 1000, 1) + " um"; }

}  // namespace

ReportVerdict report_verdict(const ComparisonDocument& doc) {
  ReportVerdict v;
  const ComparisonSummary& s = doc.summary;
  v.verdict = s.verdict;
  v.pass = s.pass;
  v.inconclusive = s.inconclusive;
  v.profile = s.profile;
  v.zone = doc.options.tolerance;
  v.evaluated = s.evaluated;
  v.out_of_tolerance = s.out_of_tolerance;
  v.registration_converged = doc.registration.converged;
  v.alignment = doc.summary.alignment;
  if (doc.gouges) {
    v.has_prediction = true;
    for (const GougeSiteCheck& site : doc.gouges->sites) {
      ++v.sites;
      switch (site.status) {
        case GougeSiteStatus::confirmed: ++v.confirmed; break;
        case GougeSiteStatus::not_confirmed: ++v.not_confirmed; break;
        case GougeSiteStatus::not_measured: ++v.not_measured; break;
      }
    }
    v.unexplained = doc.gouges->unexplained.size();
  }
  if (doc.prediction) v.prediction_verdict = to_string(doc.prediction->overall.verdict);

  // Files written before the alignment state: the old rule, said in words.
  if (!v.registration_converged && v.alignment == "ok")
    v.reasons.push_back("the registration did not converge (" + doc.registration.status + ")");
  if (v.out_of_tolerance > 0)
    v.reasons.push_back(std::to_string(v.out_of_tolerance) + " of " + std::to_string(v.evaluated) +
                        " evaluated points outside the profile zone [" + um(v.zone.lower()) + ", " +
                        um(v.zone.upper()) + "]");
  if (doc.gouges)
    for (const GougeSiteCheck& site : doc.gouges->sites)
      if (site.status == GougeSiteStatus::confirmed)
        v.reasons.push_back("predicted gouge " + site.id + " confirmed: measured depth " +
                            um(site.measured_depth.value_or(0)) +
                            (site.predicted_depth ? ", predicted " + um(*site.predicted_depth) : std::string()));
  for (const InconclusiveReason& r : v.inconclusive) v.reasons.push_back(r.text);
  if (!v.pass && v.reasons.empty()) v.reasons.push_back("the comparison failed the part");
  return v;
}

}  // namespace furrow
