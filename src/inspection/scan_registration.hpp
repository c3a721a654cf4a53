#pragma once
// A scan's registration from one or two coarse starts (docs/scan.md
// "Registration"): the fit subset (relative to the scan's local origin) is
// fitted by Furrow's robust fit (registration.hpp) from the global search's
// start and/or from the feature start of the scan module
// (io/scan/scan_feature_start.hpp: PCL's FPFH + SampleConsensusPrerejective
// against a sampling of the part with its exact normals), and with both the
// fit that measures better is kept.
//
// The measure: the Cauchy cost sum c^2 ln(1 + d_i^2 / c^2) over EVERY point
// of the fit subset at the fit's final transform, c the fit's loss scale,
// d_i the point's deviation (the part's size for a point without a foot):
// the same points for both, whatever each fit left out, and a point far off
// costs only the log of its distance, so a wrong placement cannot hide
// behind the points it flagged. A fit whose alignment did not succeed
// (not converged, too few points) loses to one that did. Costs within a
// relative 1e-6 are a tie (both fits found the same minimum) and a tie goes
// to the global search, so a scan both place alike gives today's answer bit
// for bit.
//
// With ScanStart::features, a scan the feature start cannot place (a
// plane-like patch: no features) is fitted from the global search and the
// record says so. Failure of a fit is reported in its result, never
// thrown.
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "inspection/registration.hpp"
#include "io/scan/scan_feature_start.hpp"
#include "io/scan/scan_preprocess.hpp"

namespace furrow {

// One start's fit, as comparison.json records it.
struct ScanStartFit {
  bool ran = false;
  std::string status;  // the fit's status; or why it did not run
  bool ok = false;     // the alignment succeeded (converged, not weakly constrained)
  double cost = 0;     // the measure above [mm^2]
  double rms = 0;      // rms_after [mm]
  int outer_iterations = 0, solver_iterations = 0;
  double seconds = 0;  // wall time of the start and its fit; not written (output is deterministic)
  // Where it started and ended (local frame -> part frame): for benches
  // and tests, not written.
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity(), transform = Eigen::Isometry3d::Identity();
};

// Which start was kept and why, with both starts' figures
// (comparison.json "registration.start").
struct ScanStartRecord {
  ScanStart mode = ScanStart::best;
  std::string chosen;  // "global" or "features"
  std::string why;     // one sentence
  ScanStartFit global, features;
  FeatureStart feature;  // the feature start itself (found or why not)
  double feature_seconds = 0;  // of the feature start alone; not written
  // The feature start against the kept registration: rotation [rad] and
  // translation [mm, at the local origin] between them; set when it was found.
  double feature_rotation_error = 0, feature_translation_error = 0;
};

struct ScanRegistration {
  RegistrationResult registration;  // the one kept
  ScanStartRecord record;
};

// `fit`: the fit subset, relative to pre.origin, as contact points;
// `fit_normals` one per fit point (pre.fit_normals); `voxel` the fit
// subset's voxel [mm].
ScanRegistration register_scan(const ClosestPointFinder& finder, const MeasurementSet& fit,
                               const std::vector<Eigen::Vector3f>& fit_normals, bool normals_estimated,
                               double voxel, ScanStart mode, const RegistrationOptions& options);

}  // namespace furrow
