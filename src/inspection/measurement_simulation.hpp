#pragma once
// Realistic CMM data from a plan, for tests and demos (`furrow
// simulate-measurement`): probe-ball centres (or contact points) of the
// planned points on the part as machined, with Gaussian probing noise along
// the normal, a misalignment (the part lies somewhere on the CMM table) and a
// few blunders (dust, a mis-trigger: large offsets along the normal).
//
// The machined surface is the nominal one unless `surface_offset` says by
// how much it lies above (+, material left) or below (-) the nominal along
// the normal at a planned point - predicted_surface_offsets() gives the
// surface a machining prediction describes (simulate-measurement
// --prediction) - plus any artificial bumps and dents (`bumps`, --bump), so
// that tests and the demo can plant an overcut nothing predicted.
//
// Everything random comes from one std::mt19937 seeded with `seed`, so the
// same inputs give the same file.
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/plan_file.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow {

// Placement of the part on the CMM table: x_cmm = R x_part + t with
// R = Rz(rz) Ry(ry) Rx(rx) (rotations about the fixed part axes, x first).
struct Misalignment {
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // [mm]
  Eigen::Isometry3d part_to_cmm() const;
};

// Deviation of the machined surface from the nominal along the nominal
// normal at a planned point [mm] (+ material left, - removed).
using SurfaceOffset = std::function<double(const PlannedPoint&)>;

// A smooth artificial bump (height > 0, material left) or dent (height < 0)
// of the machined surface, along the normal: a raised cosine
//   height * (1 + cos(pi rho / radius)) / 2   for rho < radius, else 0,
// rho the 3-D distance of the planned point from `centre` [mm]. Smooth
// (C1), so neighbouring probe points see a believable shape, not a step.
struct SurfaceBump {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // [mm], part frame
  double radius = 1;                                 // [mm], > 0
  double height = 0;                                 // [mm]
  double offset_at(const Eigen::Vector3d& point) const;
};

// The machined surface of a prediction at every planned point: the
// predicted error (Prediction::predicted_error_at at the point's face and
// (u, v)) where the tool reached it. Where it did not (cell not reached,
// trimmed away, not machinable from above, or a face the prediction does
// not cover) nothing predicts a cut, so the surface stays nominal: offset 0,
// counted in not_reached - never NaN.
struct PredictedSurfaceOffsets {
  std::vector<double> offset;  // per plan point, plan order [mm]
  std::size_t reached = 0, not_reached = 0;
  // The offsets as a SurfaceOffset, looked up by plan id (a copy: it needs
  // neither `plan` nor this object afterwards).
  SurfaceOffset lookup(const InspectionPlan& plan) const;
};
PredictedSurfaceOffsets predicted_surface_offsets(const InspectionPlan& plan,
                                                  const Prediction& prediction);

struct SimulationOptions {
  Misalignment misalignment;
  double noise_sigma = 0.002;                   // [mm] along the normal
  int blunders = 0;                             // how many points get a blunder
  double blunder_min = 0.1, blunder_max = 1.0;  // [mm] blunder size range (random sign)
  std::uint32_t seed = 1;
  ProbePointKind kind = ProbePointKind::probe_centre;
  bool anonymous = false;        // no ids, points shuffled (as an unplanned scan)
  SurfaceOffset surface_offset;  // empty: the nominal surface
  std::vector<SurfaceBump> bumps;  // added to surface_offset
};

struct SimulatedMeasurement {
  MeasurementSet set;                  // CMM frame, probe from the plan
  std::vector<std::string> plan_ids;   // plan id of each measured point (also when anonymous)
  std::vector<bool> blunder;           // per measured point
  std::vector<double> true_deviation;  // offset + noise + blunder along the normal [mm]
  std::vector<std::size_t> bump_points;  // planned points each bump reaches (a bump
                                         // between all points plants nothing)
};

// Throws InputError for a negative noise, more blunders than points, a bad
// blunder range or a bump radius <= 0.
SimulatedMeasurement simulate_measurement(const InspectionPlan& plan,
                                          const SimulationOptions& options,
                                          const std::string& name = "simulated");

// A plan of nu x nv points on an even (u,v) grid of every face (cell
// centres; trimmed-away ones skipped), approach/retract `clearance` mm out
// along the normal. A baseline and a test aid, not a risk-based plan.
InspectionPlan grid_plan(const Part& part, int nu, int nv, const ProbeDefinition& probe,
                         double clearance = 5);

}  // namespace furrow
