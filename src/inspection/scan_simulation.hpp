#pragma once
// A simulated laser or structured-light scan of a part (`furrow
// simulate-measurement --scan`), for the scan tests and the scan demo
// (docs/scan_simulation.md): what a scanner looking along one direction
// reports, on the raster of its stripes, with the part where it lies in the
// scanner's frame.
//
// The model, and why:
// - Rays on a raster: the scanner looks along `view` (a parallel
//   projection: a laser line swept over the part, or a fringe projector far
//   away compared with the part); its points lie on stripes `stripe_pitch`
//   apart, `point_pitch` apart along each stripe. Every ray gives at most one
//   point: the first surface it meets, so what the part hides from the view
//   (occlusion) is not measured.
// - Exact points: each ray's point is solved on the NURBS face itself
//   (Newton on S(u, v) = ray, at most `max_newton` steps to `newton_tolerance`
//   mm), from the face and (u, v) of the nearest triangle of a tessellation,
//   which only decides what the ray sees first (a cell the trim cuts is
//   kept whole, so no ray slips between the faces along a trimmed edge). Rays whose solution does not
//   converge, falls outside the face's trim, lands where the face's
//   parametrisation has no normal (a pole: a ray exactly through it), or
//   meets the surface from behind are counted and give no point.
// - Grazing rays give nothing: a scanner loses a surface seen beyond
//   `max_incidence_deg` from its normal.
// - The part as machined: planted bumps and dents move each point along
//   the surface normal (SurfaceBump, as for probe points).
// - Noise along the line of sight (Gaussian, `noise_sigma` mm): a
//   triangulating scanner's error is in depth, not along the normal. With
//   `noise_grows_with_incidence` its sigma is noise_sigma / cos^2(incidence),
//   so that the part of it along the normal grows as noise_sigma /
//   cos(incidence): the model the comparison weights its fit by
//   (docs/scan.md "Weights").
// - Spray: a share of the points thrown off along the line of sight by
//   `spray_min`..`spray_max` mm (either sign), as specular glints and dust
//   give them.
//
// Everything random comes from one std::mt19937 seeded with `seed`, drawn in
// raster order, so the same inputs give the same points whatever the number
// of threads.
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/measurement_simulation.hpp"

namespace furrow {

struct ScannerModel {
  Eigen::Vector3d view = -Eigen::Vector3d::UnitZ();  // direction the scanner looks, part frame
  double stripe_pitch = 0.2;                         // [mm] between stripes, > 0
  double point_pitch = 0.2;                          // [mm] along a stripe, > 0
  double max_incidence_deg = 75;                     // (0, 90): steeper views give no point
  double noise_sigma = 0.005;                        // [mm] along the line of sight, >= 0
  bool noise_grows_with_incidence = false;           // sigma / cos^2(incidence) along the line of sight
  double spray_share = 0;                            // [0, 1): share of the points thrown off
  double spray_min = 0.3, spray_max = 3;             // [mm], 0 < min <= max
  Misalignment part_to_scanner;                      // the part in the scanner's frame
  std::vector<SurfaceBump> bumps;                    // the part as machined
  std::uint32_t seed = 1;
  int max_newton = 30;             // Newton steps per ray
  double newton_tolerance = 1e-9;  // [mm] on the ray's residual
};

// Rays per outcome. Every raster ray is counted once.
struct ScanRayCounts {
  std::size_t rays = 0;           // raster rays over the part's shadow
  std::size_t points = 0;         // rays that gave a point (spray included)
  std::size_t missed = 0;         // met no face of the part
  std::size_t grazing = 0;        // met it beyond max_incidence_deg
  std::size_t from_behind = 0;    // met a face's back first (an open sheet)
  std::size_t not_solved = 0;     // Newton did not converge or left the face's trim
  std::size_t spray = 0;          // of `points`
};

struct SimulatedScan {
  // Per point, raster order (stripe by stripe):
  std::vector<Eigen::Vector3d> points;   // scanner frame [mm]
  std::vector<Eigen::Vector3d> normals;  // the nominal surface normal there, scanner frame
  std::vector<float> intensity;          // cos(incidence), what a scanner's return falls with
  std::vector<std::size_t> face;         // the face the ray met
  std::vector<Eigen::Vector2d> uv;       // its (u, v) on that face (the nominal hit)
  std::vector<Eigen::Vector3d> nominal;  // the nominal hit, part frame [mm]
  // Offset of the point from the nominal surface along its normal [mm]:
  // bumps plus the normal part of the noise (and of the spray for a spray
  // point): the deviation a comparison should read, to first order.
  std::vector<double> true_deviation;
  std::vector<bool> spray;
  ScanRayCounts counts;
};

// Validates the model first: a zero view, a pitch or bump radius <= 0, an
// incidence outside (0, 90), negative noise, a spray share outside [0, 1)
// or a bad spray range throw InputError naming the value; so does a raster
// of more than 50 million rays (a pitch too fine for the part).
SimulatedScan simulate_scan(const Part& part, const ScannerModel& model);

}  // namespace furrow
