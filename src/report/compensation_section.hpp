#pragma once
// The "Compensation" section of the QA report (docs/report.md
// "Compensation"), from the record `furrow compensate` wrote beside its
// program (inspection/compensation_record.hpp): what the program is expected
// to leave at the measured points, per region and overall, RMS and worst
// point before (the measured deviation) and expected after (the residual),
// and what limited the corrections (gain, maximum offset, points clipped,
// cut back against a gouge, unreachable, reduced by the clip-back).
//
// The numbers are the record's, shown, not recomputed: the record describes
// the program that was written. Its maps are report_figures.hpp's
// (figures/compensation_before.png and _after.png).
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "inspection/compensation_record.hpp"

namespace furrow {

// The section's HTML, with `figures_html` (its figures, already rendered) at
// its end. Empty without a record: a report without compensation has no
// such section.
std::string compensation_section_html(const std::optional<CompensationRecord>& record, const std::string& source,
                                      const std::string& figures_html);

// report.json's "compensation" member (docs/report.schema.json): null
// without a record. `source` is the record's file as named.
nlohmann::json compensation_section_json(const std::optional<CompensationRecord>& record, const std::string& source);

}  // namespace furrow
