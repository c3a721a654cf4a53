#pragma once
// The datum reference frame of a part from its measured datum features, the
// 3-2-1 rule (docs/registration.md "Datum frame"): what `furrow compare
// --align datums` evaluates the free-form points in, instead of a best fit.
//
// Construction, the same for the measured points (CMM frame) and for the
// nominal datum features of the plan (part frame), so that the transform
// between the two frames is the part's placement on the CMM:
//   primary A (plane, >= 3 points): least-squares plane (centroid and the
//     smallest singular vector of the centred points), normal oriented like
//     the nominal outward normal: z = n_A;
//   secondary B (line, >= 2 points): the points projected into plane A, the
//     least-squares line through them (largest singular vector), oriented
//     like the nominal direction: x = d_B; y = z x x;
//   tertiary C (point): fixes the origin along x; the origin is the point of
//     line B (in A) nearest C along x: o = b + ((c - b).x) x.
// Or, with a bore or boss perpendicular to A as secondary:
//   secondary B (cylinder, >= 3 points): the points seen along z, the
//     least-squares circle (algebraic start, Gauss-Newton, at most 50
//     iterations); its centre is the axis, which meets plane A at the
//     origin o (both in-plane translations); its form number is the
//     roundness (max - min of the radial residuals);
//   tertiary C (point): x = the in-plane direction from o to C (the turn
//     about the axis).
// Frame F maps frame coordinates to its space: F(q) = o + [x y z] q. The
// transform CMM -> part is F_nominal F_measured^-1.
//
// Probe compensation: for centre points (probe_radius > 0) each fitted
// feature is moved back by the radius against its outward normal (the
// plane's fitted normal; B's and C's nominal normals, which a placement of a
// few degrees changes only to second order).
//
// Form numbers reported: the plane's flatness (max - min of the signed
// residuals to the fitted plane) and the line's straightness (max - min of
// the in-plane residuals across the fitted line) [mm].
//
// Failure: a datum point of the plan missing from the measurements throws
// InputError naming the point and the datum (exit 2); degenerate data (plane
// points collinear, line points that coincide once projected into A - a
// line along A's normal -, a tertiary point whose face does not face along
// the line) throw DatumFrameError with the reason (exit 3: the computation
// did not succeed). Never NaN.
#include <Eigen/Geometry>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cmm/measurement_file.hpp"
#include "io/plan_alignment.hpp"

namespace furrow {

class DatumFrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A least-squares plane: centroid and unit normal (oriented along
// `orientation`), with the signed residuals' max - min.
struct PlaneFit {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double flatness = 0;  // [mm]
};
// Throws DatumFrameError (naming `what`) for fewer than 3 points or
// collinear ones.
PlaneFit fit_plane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& orientation,
                   const std::string& what);

// One datum feature as measured.
struct DatumFit {
  std::string label;
  DatumFeature::Kind kind = DatumFeature::Kind::plane;
  std::vector<std::string> point_ids;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     // centroid / point of the line / the point, CMM [mm]
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); // plane normal / line direction / point: its normal
  double form_error = 0;  // plane: flatness, line: straightness, point: 0 [mm]
};

// One point of a reference point system as fitted (rps_alignment.hpp).
struct ReferencePointFit {
  std::string id;
  std::string directions;  // the part axes it fixes, "x", "yz", ...
  double weight = 1;
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();   // measured contact point, CMM frame [mm]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // nominal outward normal, part frame
  // Transformed contact minus nominal along each fixed axis, part frame
  // [mm]; 0 along the axes the point does not fix.
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
};

struct DatumFrame {
  std::vector<DatumFit> datums;  // A, B, C as measured (3-2-1)
  std::vector<ReferencePointFit> reference_points;  // an RPS alignment instead
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();  // frame -> CMM
  Eigen::Isometry3d nominal = Eigen::Isometry3d::Identity();   // frame -> part
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity(); // CMM -> part
};

// `alignment` must be a datums alignment of three features (plane, line,
// point); anything else is an InputError naming `where`.
DatumFrame fit_datum_frame(const PartAlignment& alignment, const MeasurementSet& set,
                           const std::string& where);

// The set without the alignment's datum points (the free-form points that
// the datum frame evaluates).
MeasurementSet without_datum_points(const MeasurementSet& set, const PartAlignment& alignment);

// The set without the points of these ids, in their order.
MeasurementSet without_points(const MeasurementSet& set, const std::set<std::string>& ids);

}  // namespace furrow
