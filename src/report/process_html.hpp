#pragma once
// The "Process" section of report.html (docs/report.md "Process"): per
// region a sparkline of its mean deviation over the latest parts, this
// part's value, the process mean, Cpk and the rules violated at this part.
// Inline SVG, no script; every text escaped. Empty without a process.
#include <optional>
#include <string>

#include "report/process_context.hpp"

namespace furrow {

std::string process_section_html(const std::optional<ProcessContext>& process);

}  // namespace furrow
