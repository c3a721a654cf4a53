#pragma once
// What `furrow report comparison.json` reads: the comparison document, the
// part it names (for the figures), its partition when it names one, and
// the SHA-256 of every file involved (the comparison and each source it
// names: part, measurements, plan, regions, prediction).
//
// Source paths in a comparison are stored as they were given to `furrow
// compare` (relative to the directory it ran in) or, for a comparison
// written by `furrow run`, relative to the job's output folder. A relative
// path is therefore looked up relative to the current directory first, then
// to the comparison file's folder; the digests name the file actually used.
// A source that is found in neither place is an InputError: a report must
// not vouch for a file it cannot identify.
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/scan_comparison_document.hpp"
#include "machining/prediction/prediction.hpp"
#include "partition/region_map.hpp"
#include "report/qa_report.hpp"

namespace furrow {

struct ReportSources {
  ComparisonDocument doc;
  Part part;
  std::optional<RegionMap> regions;
  std::optional<Prediction> prediction;  // when the comparison names one (the report's 3D view shows its error field)
  std::vector<InputDigest> inputs;  // comparison first, then its sources
};

ReportSources read_report_sources(const std::string& comparison_path);

// The same for a comparison of a scan (kind "scan"): the part and the
// partition are needed and found by the same rules; the scan and its
// deviation cloud are digested when found (the report does not need them:
// what it shows is in the comparison) and left out of the inputs when not.
struct ScanReportSources {
  ScanComparisonDocument doc;
  Part part;
  std::optional<RegionMap> regions;
  std::vector<InputDigest> inputs;  // comparison first, then its sources
};
ScanReportSources read_scan_report_sources(const std::string& comparison_path);

}  // namespace furrow
