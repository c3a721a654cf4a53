#pragma once
// Default curvature tolerance eps [1/mm] for classifying one face when the
// user gives none (docs/partition.md explains the choice at length).
//
//   eps = max(kEpsFloor, kEpsRelative * curvature_scale)
//
// curvature_scale is the kEpsScalePercentile quantile of max(|k1|, |k2|)
// over the face's valid samples: how curved the face typically is, robust to
// a few sharp spots (a fillet edge, a pole).
//
// Why both terms:
// - The floor, 1e-4 /mm (a radius of 10 m), is docs/architecture.md's default: over a
//   10 mm probe spacing such a surface leaves its tangent plane by
//   k l^2 / 8 = 1.25 um, below what a CMM resolves, and it is 0.16 % of the
//   curvature of a 32 mm ball end mill, so no cutter tells it from a plane.
// - The relative term protects strongly curved faces from round-off and
//   fitting noise. An imported B-spline that approximates a cylinder carries
//   a "zero" curvature of random sign whose size scales with the real one;
//   with eps at the floor such a face would flicker between convex and
//   saddle. One percent of the face's own curvature is far below any
//   curvature a user cares about on that face and above typical fitting noise.
// Neither term depends on the grid beyond the quantile's sampling.
//
// One rule for every command: `furrow info`, `furrow partition` and the
// report's regions take a face's eps from face_curvature_tolerance(), which
// samples the face on its own fixed grid, so the same face gets the same eps
// whatever grid or spacing the command samples its classes on
// (docs/partition.md "eps").
#include "partition/classification.hpp"
#include "partition/curvature_field.hpp"

namespace furrow {

constexpr double kEpsFloor = kDefaultCurvatureEps;  // 1e-4 /mm
constexpr double kEpsRelative = 0.01;
constexpr double kEpsScalePercentile = 0.9;

struct CurvatureTolerance {
  double eps = kEpsFloor;     // [1/mm]
  double curvature_scale = 0;  // [1/mm]; 0 when the face has no valid sample
};

// Deterministic (a selection on a copy of the values, no threads).
CurvatureTolerance default_curvature_tolerance(const CurvatureField& field);

// The face's own eps: default_curvature_tolerance() of a kEpsScaleGrid^2
// field, refined to kEpsScaleFineGrid^2 when trims leave fewer than
// kEpsScaleMinSamples valid cells (a small face cut from a large surface).
constexpr int kEpsScaleGrid = 64;
constexpr int kEpsScaleFineGrid = 256;
constexpr int kEpsScaleMinSamples = 512;
CurvatureTolerance face_curvature_tolerance(const Face& face);

}  // namespace furrow
