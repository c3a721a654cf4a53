#pragma once
// The QA report of a scan (`furrow report C.json` with C.json of kind
// "scan", and the report stage of a scan job; docs/report.md "A scan").
//
// The report is the probe-point report's (verdict, alignment, regions,
// deviations, traceability, report.json, PDF) made from a comparison
// document without per-point records (scan_as_comparison), with what a
// scan adds:
//   - a "Scan" section: points read, not finite, kept, removed per reason
//     (spray far and near, off the part), the pre-processing's figures and
//     the registration of the fit subset;
//   - the histogram of the deviations of every evaluated point (the bins
//     counted when the scan was compared, inspection/scan_display.hpp);
//   - the deviation surface: the display sample (at most 50 000 real points
//     of the cloud, recorded at compare time) coloured by deviation, from
//     above (figures/scan_deviation_top.png) and in the interactive 3D view
//     on the part;
//   - report.json's "scan" member (docs/report.schema.json).
// The per-point deviations are in the comparison's deviation cloud, not in
// points.csv (which keeps its header and no row) nor in results.qif.
//
// Everything comes from the comparison document: the raw scan is not
// needed. Deterministic: the same document, part, partition and context
// give the same bytes.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "inspection/comparison_document.hpp"
#include "inspection/scan_comparison_document.hpp"
#include "report/qa_report.hpp"

namespace furrow {

// The comparison document the report's common sections read: sources
// (measurements = the scan), tolerance, registration, summary; no points.
ComparisonDocument scan_as_comparison(const ScanComparisonDocument& scan);

// region map (with a partition), deviation surface from above, histogram,
// the 3D view (needs three.js, as the probe-point report's).
std::vector<ReportFigure> make_scan_report_figures(const ScanComparisonDocument& scan, const Part& part,
                                                   const RegionMap* regions);

// The whole folder (qa_report.hpp's files). `context.scan` is set here.
std::vector<FolderFile> make_scan_report(const ScanComparisonDocument& scan, const Part& part,
                                         const RegionMap* regions, const ReportContext& context);

// The "Scan" section's HTML with `figures_html` at its end; empty for no scan.
std::string scan_section_html(const ScanComparisonDocument* scan, const std::string& figures_html);

// report.json's "scan" member; null for no scan.
nlohmann::json scan_section_json(const ScanComparisonDocument* scan);

}  // namespace furrow
