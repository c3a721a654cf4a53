#pragma once
// Coarse start of a registration: a rigid transform (CMM -> part) good enough
// for the fine, surface-based fit (registration.hpp) to converge to the
// global optimum.
//
// 1. By ids: measured points whose ids match plan.json points (or DMIS
//    nominals F(label) of the same label) are paired with their nominal
//    probe-centre (or contact) positions and fitted with Umeyama's closed
//    form (Eigen::umeyama, no scaling); pairs off by more than 3x the median
//    are dropped and the fit repeated once (mislabelled points).
// 2. Without ids (or when the id fit is poor): a global search. A part lies
//    on the CMM table in any orientation - turned 90 or 180 degrees is
//    common - so local ICP from one guess is not enough. Candidates: the 24
//    rotations that map the principal axes of the measured points onto those
//    of a dense surface sampling (every axis order and sign with det +1), and
//    the 24 axis-aligned quarter-turn rotations of the CMM frame itself, each
//    with the centroids matched. Every candidate gets a short trimmed ICP
//    against the sampling (offset by the probe radius for probe centres;
//    exact k-d tree, Umeyama in double, pairs beyond 3x the median distance
//    dropped so blunders do not pull); the best few get a long ICP; the
//    winner has the smallest median point-to-surface distance (exact
//    projection).
//
// The result says which method won, its median distance, and whether a
// clearly different orientation fitted almost as well (a symmetric part:
// the measurement cannot tell, a metrologist must).
#include <Eigen/Geometry>
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/plan_file.hpp"

namespace furrow {

// frame: a start the caller already knows (RegistrationOptions::start: the
// frame of a datum or RPS alignment), no search; features: a scan's start
// from PCL's FPFH features (scan_registration.hpp), given as such a frame.
enum class CoarseMethod { identity, plan_ids, dmis_nominals, global_search, frame, features };
const char* to_string(CoarseMethod method);

struct CoarseOptions {
  int min_matches = 3;                  // id pairs needed for Umeyama
  std::size_t max_id_pairs = 20000;     // an even subset of the points is matched by id
  double fallback_median = 0.5;         // [mm] an id start worse than this is checked globally
  std::size_t surface_samples = 20000;  // ICP target cloud size
  std::size_t screen_points = 200;      // measured points in the short ICP of every candidate
  std::size_t refine_points = 1000;     // measured points in the long ICP
  int screen_iterations = 10;           // ICP iterations per candidate
  int refine_iterations = 30;           // ICP iterations for the best candidates
  int refine_candidates = 4;            // how many candidates get the long ICP ...
  // ... and how many when fewer than `few_points` points are usable: their
  // screening medians rank the candidates poorly (a plane's other side
  // fell out of the best four at 16 and 30 points), and the long ICP of a
  // few points is cheap. With many points more candidates only add
  // equally good in-plane placements of a weak shape to choose from.
  int refine_candidates_few = 12;
  std::size_t few_points = 100;
  double icp_tolerance = 1e-12;         // ICP stops when the 4x4 matrix changes less than this
  double ambiguity_ratio = 1.5;         // a runner-up within this factor of the best median ...
  double ambiguity_angle_deg = 5;       // ... and rotated at least this much from it is reported
};

struct CoarseResult {
  CoarseMethod method = CoarseMethod::identity;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // CMM -> part
  std::size_t matched = 0;      // id pairs used (ids methods; at most max_id_pairs)
  int candidates = 0;           // orientations tried (global search)
  double median_distance = 0;   // median |point-to-surface distance - probe radius| [mm]
  bool ambiguous = false;       // another orientation fits about as well
  double runner_up_median = 0;  // its median distance [mm] (global search)
  // Global search: the other refined placements, best first (CMM -> part).
  // With few points the fine fit starts from each of them as well
  // (registration.hpp).
  std::vector<Eigen::Isometry3d> alternatives;
};

// Chooses and runs the methods above. `plan` may be null.
CoarseResult coarse_alignment(const ClosestPointFinder& finder, const MeasurementSet& set,
                              const InspectionPlan* plan, const CoarseOptions& options);

// The global search alone (exposed for tests and benchmarks).
CoarseResult coarse_global_search(const ClosestPointFinder& finder, const MeasurementSet& set,
                                  const CoarseOptions& options);

// Median over (a deterministic, spread subset of at most `max_points` of)
// the points that can lie on the part after `transform` (within 1.5 part
// diagonals of its control box) of |signed distance - probe radius| [mm];
// +infinity when no point can.
double median_surface_distance(const ClosestPointFinder& finder, const MeasurementSet& set,
                               const Eigen::Isometry3d& transform, std::size_t max_points);

}  // namespace furrow
