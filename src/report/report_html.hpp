#pragma once
// report.html: the QA report for people, one self-contained file (inline
// CSS, every figure a data: URI; no external resource, so it opens offline
// and survives being mailed or archived; no script is needed to read it).
//
// Order (what a QA engineer looks for first): the verdict (PASS/FAIL, the
// profile value against the zone, gouges confirmed, the reasons), then the
// alignment (transform, RMS before/after, outliers, uncertainty), regions,
// deviations, predicted vs measured, gouges, the full point table, and
// traceability (Furrow version, date, SHA-256 of every input, every option,
// stage times).
//
// A few lines of script at the end only mark the page for automated checks
// (data-images-loaded="n/m" on <body> once every image has decoded); the
// content does not depend on it.
#include <string>
#include <vector>

#include "inspection/comparison_document.hpp"
#include "partition/region_map.hpp"
#include "report/qa_report.hpp"
#include "report/report_figures.hpp"
#include "report/verdict.hpp"

namespace furrow {

std::string report_html(const ComparisonDocument& doc, const ReportVerdict& verdict, const RegionMap* regions,
                        const ReportContext& context, const std::vector<ReportFigure>& figures);

}  // namespace furrow
