#pragma once
// What `furrow select-tool` writes: the JSON of docs/formats.md "Tool
// selection JSON" and a short text summary. Deterministic.
#include <string>

#include "machining/gouge/gouge_report.hpp"
#include "machining/gouge/tool_selection.hpp"

namespace furrow {

std::string tool_selection_json(const Part& part, const std::string& part_path,
                                const std::string& library_path, const ToolSelection& selection,
                                const SiteSource& source, const ToolSelectionOptions& options);

std::string tool_selection_text(const Part& part, const std::string& part_path,
                                const ToolSelection& selection);

}  // namespace furrow
