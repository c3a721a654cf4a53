#include "report/report_sources.hpp"

#include <filesystem>

#include "base/error.hpp"
#include "inspection/comparison_file.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "partition/regions_file.hpp"

namespace furrow {

namespace {

namespace fs = std::filesystem;

std::string locate(const std::string& comparison_path, const std::string& role, const std::string& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return path;
  const fs::path beside = fs::path(comparison_path).parent_path() / path;
  if (!fs::path(path).is_absolute() && fs::is_regular_file(beside, ec)) return beside.lexically_normal().string();
  throw InputError(comparison_path + ": its " + role + " file \"" + path +
                   "\" is found neither relative to the current directory nor next to the comparison");
}

}  // namespace

ScanReportSources read_scan_report_sources(const std::string& comparison_path) {
  ScanReportSources s;
  s.doc = read_scan_comparison(comparison_path);
  s.inputs.push_back(digest_file("comparison", comparison_path));
  const auto& src = s.doc.sources;
  if (src.part.empty()) throw InputError(comparison_path + ": names no part file");
  const std::string part_path = locate(comparison_path, "part", src.part);
  s.inputs.push_back(digest_file("part", part_path));
  for (const auto& [role, path] : {std::pair<const char*, const std::string*>{"scan", &src.scan},
                                   {"deviation cloud", &src.deviations}}) {
    std::error_code ec;
    if (path->empty()) continue;
    if (fs::is_regular_file(*path, ec)) s.inputs.push_back(digest_file(role, *path));
    else if (const fs::path beside = fs::path(comparison_path).parent_path() / *path;
             !fs::path(*path).is_absolute() && fs::is_regular_file(beside, ec))
      s.inputs.push_back(digest_file(role, beside.lexically_normal().string()));
  }
  s.part = read_part(part_path);
  if (!src.regions.empty()) {
    const std::string regions_path = locate(comparison_path, "regions", src.regions);
    s.inputs.push_back(digest_file("regions", regions_path));
    s.regions = read_regions(regions_path);
    s.regions->check_belongs_to(s.part, regions_path, part_path);
  }
  return s;
}

ReportSources read_report_sources(const std::string& comparison_path) {
  ReportSources s;
  s.doc = read_comparison(comparison_path);
  s.inputs.push_back(digest_file("comparison", comparison_path));
  const ComparisonDocument::Sources& src = s.doc.sources;
  const std::pair<const char*, const std::string*> named[] = {
      {"part", &src.part},       {"measurements", &src.measurements}, {"plan", &src.plan},
      {"regions", &src.regions}, {"prediction", &src.prediction},
  };
  std::string part_path, regions_path, prediction_path;
  for (const auto& [role, path] : named) {
    if (path->empty()) continue;
    const std::string found = locate(comparison_path, role, *path);
    s.inputs.push_back(digest_file(role, found));
    if (path == &src.part) part_path = found;
    if (path == &src.regions) regions_path = found;
    if (path == &src.prediction) prediction_path = found;
  }
  if (part_path.empty()) throw InputError(comparison_path + ": names no part file");
  s.part = read_part(part_path);
  if (!regions_path.empty()) {
    s.regions = read_regions(regions_path);
    s.regions->check_belongs_to(s.part, regions_path, part_path);
  }
  if (!prediction_path.empty()) {
    s.prediction = read_prediction(prediction_path);
    check_prediction_against_part(*s.prediction, s.part, prediction_path, part_path);
  }
  check_comparison_faces(s.doc, s.part);
  return s;
}

}  // namespace furrow
