#pragma once
// The inspection record in report.html (docs/report.md "Inspection
// record"): a compact grid of the filled fields under the heading, or one
// line saying that no record was given - never a form of empty
// placeholders; and the sign-off block (prepared / checked / approved, with
// name, date and a line to sign) that the print layout carries at the end of
// the report. Every text is HTML-escaped here; long values wrap instead of
// widening the page.
#include <optional>
#include <string>

#include "report/inspection_record.hpp"

namespace furrow {

std::string record_header_html(const std::optional<InspectionRecord>& record);
std::string sign_off_html(const std::optional<InspectionRecord>& record);

// CSS of the record grid, the sign-off block, and the wrapping of long
// values in key/value tables and option blocks (for the page's <style>).
const char* inspection_record_css();

}  // namespace furrow
