#pragma once
// Measured versus nominal: registration, per-point deviations against a
// profile tolerance zone, statistics overall and per region, and the
// verdict. What `furrow compare` computes and comparison_file.hpp writes.
//
// The verdict has three states (docs/verification.md "Verdict"):
// - FAIL: something was shown to be bad — an evaluated point outside the
//   zone, a predicted gouge confirmed — or the registration did not
//   converge, or no point could be evaluated;
// - INCONCLUSIVE: nothing was shown to be bad, but something was not shown
//   to be good: a point outside the zone that the outlier rule suspects of
//   being a blunder (re-measure it), a predicted gouge site with no point on
//   it, a plan region with fewer evaluated points than its minimum, or an
//   alignment that the points do not determine (rank-deficient), a point
//   the measurement file says was to be measured but was not (an I++ DME
//   PtMeas answered by an error, MeasurementSet::not_measured), or a
//   point in the best fit that the fit follows instead of checking it (its
//   redundancy, registration.hpp, below kCheckedRedundancy);
// - PASS: neither. PASS is never given for what was not seen.
// An alignment that did not succeed (not converged, too few points on the
// part, weakly constrained: a motion that the measured faces would fix but
// the points do not, registration.hpp; or an orientation the points cannot
// tell from another that puts some evaluated point on the other side of
// the zone, orientation_check.hpp) certifies nothing either way:
// the verdict is INCONCLUSIVE with the reason, and `alignment` says which,
// so that the commands exit with 3 (the computation did not succeed).
//
// Which points count: a point is evaluated unless it is a blunder, beyond a
// face edge or has no foot point (registration.hpp). Large real deviations
// (outlier reason large_deviation) are evaluated - they are left out of the
// fit only - so a gouge fails the part instead of vanishing.
//
// Regions: each point may carry a region id of the curvature partition.
// With a partition (regions.json) it is the region holding the point's foot
// (face, u, v) (assign_regions); without one, the region of the plan point
// with the same id. Statistics per region are computed from whatever ids are
// set.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "inspection/datum_frame.hpp"
#include "inspection/gouge_confirmation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "inspection/reference_points.hpp"
#include "inspection/registration.hpp"
#include "inspection/tolerance_zone.hpp"
#include "partition/region_map.hpp"

namespace furrow {

struct DeviationStatistics {
  std::size_t count = 0;
  double mean = 0, sigma = 0, min = 0, max = 0;  // [mm]; sigma: sample standard deviation
};
// Deterministic (sums in index order). All zero for no values.
DeviationStatistics deviation_statistics(const std::vector<double>& values);

enum class Verdict { pass, fail, inconclusive };
const char* to_string(Verdict verdict);  // "PASS", "FAIL", "INCONCLUSIVE"
// Throws InputError naming `where` for any other text.
Verdict parse_verdict(const std::string& text, const std::string& where);

// Why a comparison that found nothing bad still cannot pass.
struct InconclusiveReason {
  // "suspected_blunder", "gouge_not_measured", "region_below_minimum",
  // "point_not_checked", "point_not_measured", "alignment_undetermined" or "alignment_failed"
  std::string kind;
  std::string subject;  // the point id, the gouge site id, "region N", or "" for the alignment
  std::string text;     // for people, saying what to do ("re-measure point P0006: ...")
};

struct RegionStatistics {
  int region = 0;
  DeviationStatistics deviations;
  std::size_t out_of_tolerance = 0;
};

struct ComparisonSummary {
  std::size_t points = 0, in_fit = 0, evaluated = 0, outliers = 0;
  std::size_t not_measured = 0;  // Comparison::not_measured
  std::size_t in_tolerance = 0, out_of_tolerance = 0;
  DeviationStatistics deviations;         // over evaluated points
  double profile = 0;                     // 2 max |d| over evaluated points [mm]
  std::size_t confirmed_gouges = 0;       // predicted gouge sites CONFIRMED (with a prediction)
  std::size_t unexplained_overcuts = 0;   // clusters of UNEXPLAINED overcut (with a prediction)
  Verdict verdict = Verdict::fail;
  // "ok", or why the alignment did not succeed: "not_converged",
  // "too_few_points", "ambiguous_outliers", "weakly_constrained",
  // "ambiguous_orientation".
  std::string alignment = "ok";
  std::vector<InconclusiveReason> inconclusive;  // set when verdict is inconclusive
  bool pass = false;                             // verdict == pass
  std::vector<RegionStatistics> regions;  // by increasing region id; empty without region ids
};

// How the measured points are put into the part frame (docs/registration.md
// "Alignments"): a best fit (form only), the CMM's own frame as measured
// (cmm: the program aligned the part), or the datum reference frame from
// the plan's datum features (form + location), or the frame a reference
// point system fixes (rps, also form + location).
enum class AlignMethod { bestfit, cmm, datums, rps };
const char* to_string(AlignMethod method);  // "bestfit", "cmm", "datums", "rps"
// Throws InputError naming `where` for any other text.
AlignMethod parse_align_method(const std::string& text, const std::string& where);

struct Comparison {
  AlignMethod align = AlignMethod::bestfit;
  std::optional<DatumFrame> datum_frame;  // with datums
  // With cmm and datums: the best-fit registration of the same points,
  // kept for its profile (2 max |d| over its evaluated points) - form
  // alone, next to the frame's form + location.
  std::optional<RegistrationResult> bestfit;
  std::optional<double> bestfit_profile;
  std::vector<std::string> point_ids;  // per point, as in the measurement set
  // What the measurement file says was not measured (MeasurementSet::
  // not_measured): counted, and never a pass.
  std::vector<UnmeasuredPoint> not_measured;
  RegistrationResult registration;
  ToleranceZone tolerance;
  std::vector<std::optional<int>> region;  // per point
  std::vector<bool> in_tolerance;          // per point (false for points not evaluated)
  // Fewest evaluated points each plan region needs (region_minimums); empty
  // without a plan, when the plan has no regions, or when the points'
  // regions are unknown (generated ids and no partition).
  std::map<int, std::size_t> region_minimum;
  ComparisonSummary summary;
  // With a machining prediction (verify_prediction):
  std::optional<PredictionComparison> prediction;
  std::optional<GougeConfirmation> gouges;
};

struct CompareOptions {
  AlignMethod align = AlignMethod::bestfit;
  // datums and rps: the frame fitted to the datum or reference points
  // (prepare_alignment, compare_stage.hpp); required then.
  std::optional<DatumFrame> datum_frame;
  // rps: the reference point system (reference_points.hpp); required then.
  std::optional<ReferencePointSystem> rps;
  RegistrationOptions registration;
  ToleranceZone tolerance;
  PredictionComparisonOptions prediction;  // used with a prediction only
  GougeConfirmationOptions gouges;         // likewise
};

// A point of the best fit with a smaller share of its deviation in its
// reading (RegisteredPoint::redundancy) is not checked by the fit: a
// deviation there moves the part instead of showing, ten times the
// tolerance reads as less than the tolerance, and a blunder hides below
// ten times the outlier limit. 0.1 is the bound of geodesy's reliability
// analysis below which an observation is called uncontrolled
// (docs/registration.md "Points the fit cannot check").
constexpr double kCheckedRedundancy = 0.1;

// The planner's default fewest points per region (PlannerOptions::
// min_per_region) and the prediction comparison's "too few points" count.
constexpr std::size_t kRegionMinimumPoints = 5;

// Per plan region: the fewest evaluated points that make it inspected,
// min(points the plan puts there, kRegionMinimumPoints). plan.json does not
// record the planner's --min-per-region; what the plan put into a region is
// what it promised to measure there, and five points are what per-region
// statistics need (docs/verification.md "Verdict"). A region the plan
// records as uncovered (plan.json `uncovered_regions`) needs the minimum the
// planner asked for, with or without points in the plan.
std::map<int, std::size_t> region_minimums(const InspectionPlan& plan);

// Registers and evaluates. `plan` may be null (no id coarse start, no regions,
// no region minimum).
Comparison compare_measurements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                const InspectionPlan* plan, const CompareOptions& options);

// Replaces every point's region by the region of the partition holding its
// foot point (RegionMap::region_at(face, u, v)); points without a foot point
// or outside every region get none. The map must belong to the part the
// comparison was made on (RegionMap::check_belongs_to, the caller's job).
// Call summarize() afterwards.
void assign_regions(Comparison& comparison, const RegionMap& regions);

// Predicted versus measured (prediction_comparison.hpp) and gouge
// confirmation (gouge_confirmation.hpp) against `prediction`, which must
// belong to `part` (check_prediction_against_part); then summarize(): a
// confirmed gouge fails the part. `probe_radius` is the measurement set's.
void verify_prediction(Comparison& comparison, const Part& part, double probe_radius,
                       const Prediction& prediction, const CompareOptions& options);

// Recomputes in_tolerance and the summary from the registration, the zone
// and the region ids (call after changing either).
void summarize(Comparison& comparison);

}  // namespace furrow
