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
//   grazing                seen beyond the largest incidence from its
//                          normal (pre-processing with a line of sight,
//                          scan_preprocess.hpp step 5): out of the fit and
//                          of the evaluation, whatever else it is;
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
// evaluated, or (with a prediction) a predicted gouge is confirmed;
// INCONCLUSIVE with alignment != "ok" when the registration did not
// succeed (exit 3), or when a predicted gouge site was not seen; PASS
// otherwise. Spray is reported, never a reason
// to fail or pass.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "inspection/comparison.hpp"
#include "inspection/scan_verification.hpp"
#include "inspection/scan_display.hpp"
#include "inspection/scan_registration.hpp"
#include "io/scan/scan_cloud.hpp"
#include "io/scan/scan_preprocess.hpp"

namespace furrow {

// Per point status, as written in the deviation cloud's `outlier` property.
enum class ScanPointStatus : std::uint8_t { evaluated = 0, spray_far = 1, spray_near = 2, off_part = 3, grazing = 4 };
// "evaluated", "spray_far", "spray_near", "off_part", "grazing"
const char* to_string(ScanPointStatus status);

// Points removed from the comparison in one region of the partition: the
// region holding the foot of their projection (region -1: in none, or the
// projection did not converge).
struct ScanRemovedInRegion {
  int region = -1;
  std::size_t spray_far = 0, spray_near = 0, off_part = 0, grazing = 0;
};

struct ScanComparison {
  std::string scan;  // the file
  ScanPreprocessOptions preprocessing;
  ScanPreprocessed pre;  // origin, spray, fit subset
  std::size_t read = 0, not_finite = 0, points = 0;  // points: finite points, the size of the vectors below
  std::size_t off_part = 0, evaluated = 0, grazing = 0;
  std::string normals;  // "file" or "estimated"
  RegistrationResult registration;  // of the fit subset, relative to pre.origin
  ScanStartRecord start;            // which coarse start it came from (scan_registration.hpp)
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // scanner frame -> part frame
  ToleranceZone tolerance;
  std::vector<ScanPointStatus> status;  // per point
  std::vector<float> deviation;         // per point [mm]; 0 where not evaluated
  // Per point: the region of the partition holding its foot; -1 none (no
  // partition, outside every region, or the projection did not converge).
  // With a partition spray is projected too, for this alone.
  std::vector<int> region;
  std::vector<ScanRemovedInRegion> removed_by_region;  // with a partition; by increasing region
  // The foot of every evaluated point (what a prediction is looked up at):
  // face index (-1 where not evaluated), (u, v) and the unit normal there.
  std::vector<std::int32_t> foot_face;
  std::vector<Eigen::Vector2d> foot_uv;
  std::vector<Eigen::Vector3f> foot_normal;
  ComparisonSummary summary;            // over the evaluated points; points = evaluated + off_part
  // With a machining prediction (scan_verification.hpp).
  std::optional<ScanVerification> verification;
  // What the report shows (scan_display.hpp), filled by the comparison
  // stage (compare_scan_stage) after compare_scan.
  ScanDisplay display;
  ScanHistogram histogram;
  RegistrationOptions fit_options;  // what the fit ran with (comparison.json "fit_options")
};

// `cloud` and `pre` as read and pre-processed with `preprocessing` (its
// voxel and `start` choose the registration's start); `regions` may be null (else
// it must belong to the finder's part). Registration options, the tolerance
// and its scaling come from `options` as for probe points; the fit's points
// are contact points (no probe radius), weighted by pre.fit_weights when it
// has them. Failure of the fit is reported in
// the result (summary.alignment), never thrown.
ScanComparison compare_scan(const ClosestPointFinder& finder, const ScanCloud& cloud, const ScanPreprocessed& pre,
                            const ScanPreprocessOptions& preprocessing, const RegionMap* regions,
                            const CompareOptions& options);

// The verdict from the statistics, the alignment and, with a prediction,
// the gouge sites (the rules above; with a prediction as for probe points,
// docs/verification.md "Verdict": a confirmed gouge fails the part, a site
// the scan did not see leaves it INCONCLUSIVE). compare_scan() and
// verify_scan_prediction() call it.
void decide_scan_verdict(ScanComparison& comparison);

}  // namespace furrow
