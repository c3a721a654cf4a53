#pragma once
// comparison.json of a scan read back (docs/formats.md "comparison.json of
// a scan"): what `furrow report` shows of a scan comparison, as plain data.
// Every number is the one written (shortest round-trip text).
//
// Only the members the report shows are read, and members it does not know
// are let through: the scan document grows (gouge confirmation from a scan,
// spray per region) and a report of a newer comparison should still show
// what it can. What it does read is checked like every Furrow file, errors
// naming the file and the member. A scan comparison written before the
// display sample was recorded is refused: compare the scan again.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/scan_display.hpp"
#include "inspection/scan_verification.hpp"
#include "inspection/tolerance_zone.hpp"

namespace furrow {

struct ScanComparisonDocument {
  std::string furrow_version;
  struct Sources {
    std::string part, scan, regions, deviations, prediction, scan_units;  // file names as given; empty when not given
  } sources;
  struct Preprocessing {
    double voxel = 0;  // [mm]
    int spray_neighbours = 0, normal_neighbours = 0;
    double spray_far_sigmas = 0, spray_near_sigmas = 0;
    bool spray_removal = true;
    Eigen::Vector3d local_origin = Eigen::Vector3d::Zero();  // scanner frame [mm]
    double local_plane_sigma = 0;                             // [mm]
    std::size_t statistical_rule = 0;                         // points where the far rule fired
    std::string normals;                                      // "file" or "estimated"
  } preprocessing;
  struct Points {
    std::size_t read = 0, not_finite = 0, kept = 0, spray_far = 0, spray_near = 0, off_part = 0, fit = 0, in_fit = 0;
    std::size_t grazing = 0;  // seen beyond the largest incidence (0 in a comparison written before it)
  } points;
  struct Registration {
    std::string status, coarse;
    bool converged = false;
    double coarse_median = 0, rms_before = 0, rms_after = 0, sigma = 0;  // [mm]
    int outer_iterations = 0;
    Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();  // scanner frame -> part frame
  } registration;
  ToleranceZone tolerance;
  // The registration options (dof, loss, outlier rules, caps) as the
  // probe-point document holds them; points "contact", probe diameter 0.
  ComparisonDocument::Options fit_options;
  ComparisonSummary summary;  // evaluated, in/out of tolerance, deviations, profile, regions, alignment, verdict
  ScanHistogram histogram;
  ScanDisplay display;
  // With a machining prediction (sources.prediction set): predicted versus
  // measured, the gouge sites and the unexplained overcuts as written (no
  // per-point records: a site's and a cluster's points are counts,
  // scan_verification_json.hpp).
  std::optional<ScanVerification> verification;
};

// True when the text is a JSON object whose "kind" is "scan" (cheap: used
// to choose the reader; a malformed file is left to the reader's errors).
bool is_scan_comparison_text(const std::string& text);

// InputError naming `name` and the member for anything missing or mistyped.
ScanComparisonDocument parse_scan_comparison(const std::string& text, const std::string& name);
ScanComparisonDocument read_scan_comparison(const std::string& path);

}  // namespace furrow
