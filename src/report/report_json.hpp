#pragma once
// report.json of a QA report: every number of the report in one document,
// described by docs/report.schema.json (JSON Schema 2020-12) and
// docs/formats.md "report.json". Lengths in mm, rotations as in
// comparison.json. In json_fields::to_text's layout, the points streamed
// (json_text.hpp) rather than built as a tree: deterministic, every double
// in its shortest exact text. "generated" and "timing" are the only
// members that change between two runs on the same inputs.
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"
#include "partition/region_map.hpp"
#include "report/qa_report.hpp"
#include "report/report_figures.hpp"
#include "report/verdict.hpp"

namespace furrow {

constexpr int kReportFormatVersion = 1;

std::string report_json_text(const ComparisonDocument& doc, const ReportVerdict& verdict, const RegionMap* regions,
                             const ReportContext& context, const std::vector<ReportFigure>& figures);

}  // namespace furrow
