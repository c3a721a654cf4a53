#pragma once
// A dense scan compared with the part (`furrow compare PART --scan FILE`,
// docs/scan.md): the pre-processed cloud's fit subset registered by the same
// robust fit as probe points, then the deviation of EVERY point that is not
// spray by the exact closest-point projection, its statistics overall and
// per region, and the verdict.
//
// Frames: the cloud's points are in the scanner's frame; the fit runs on
// them relative to the cloud's local origin (the centroid, subtracted in
// double), so a cloud kilometres from the origin is fitted with the same
// precision as one at it. `transform` maps the scanner frame to the part
// frame.
//
// Which points count (every point keeps a status, none is dropped):
//   spray_far, spray_near  flagged by pre-processing (scan_preprocess.hpp);
//   off_part               after the registration its foot lies on a face
//                          or trim boundary with the point more than the
//                          registration's edge_tolerance beside the surface
//                          (scanned fixture, table, a neighbouring part), or
//                          its projection did not converge;
//   evaluated              everything else: its deviation counts against
//                          the tolerance.
// A deviation is signed along the nominal normal at the foot (+ material
// left, - removed), the same rule as a probe point's (contact points,
// no probe radius).
//
// Verdict: FAIL when an evaluated point lies outside the zone or none was
// evaluated; INCONCLUSIVE with alignment != "ok" when the registration did
// not succeed (exit 3); PASS otherwise. Spray is reported, never a reason
// to fail or pass.
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/scan_display.hpp"
#include "io/scan/scan_cloud.hpp"
#include "io/scan/scan_preprocess.hpp"

namespace furrow {

// Per point status, as written in the deviation cloud's `outlier` property.
enum class ScanPointStatus : std::uint8_t { evaluated = 0, spray_far = 1, spray_near = 2, off_part = 3 };
const char* to_string(ScanPointStatus status);  // "evaluated", "spray_far", "spray_near", "off_part"

struct ScanComparison {
  std::string scan;  // the file
  ScanPreprocessOptions preprocessing;
  ScanPreprocessed pre;  // origin, spray, fit subset
  std::size_t read = 0, not_finite = 0, points = 0;  // points: finite points, the size of the vectors below
  std::size_t off_part = 0, evaluated = 0;
  std::string normals;  // "file" or "estimated"
  RegistrationResult registration;  // of the fit subset, relative to pre.origin
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // scanner frame -> part frame
  ToleranceZone tolerance;
  std::vector<ScanPointStatus> status;  // per point
  std::vector<float> deviation;         // per point [mm]; 0 where not evaluated
  std::vector<int> region;              // per point; -1 none (no partition, or not evaluated)
  ComparisonSummary summary;            // over the evaluated points; points = evaluated + off_part
  // What the report shows (scan_display.hpp), filled by the comparison
  // stage (compare_scan_stage) after compare_scan.
  ScanDisplay display;
  ScanHistogram histogram;
  RegistrationOptions fit_options;  // what the fit ran with (comparison.json "fit_options")
};

// `cloud` and `pre` as read and pre-processed; `regions` may be null (else
// it must belong to the finder's part). Registration options, the tolerance
// and its scaling come from `options` as for probe points; the fit's points
// are contact points (no probe radius). Failure of the fit is reported in
// the result (summary.alignment), never thrown.
ScanComparison compare_scan(const ClosestPointFinder& finder, const ScanCloud& cloud, const ScanPreprocessed& pre,
                            const RegionMap* regions, const CompareOptions& options);

}  // namespace furrow
