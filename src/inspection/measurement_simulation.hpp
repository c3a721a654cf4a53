#pragma once
// Realistic CMM data from a plan, for tests and demos (`furrow
// simulate-measurement`): probe-ball centres (or contact points) of the
// planned points on the part as machined, with Gaussian probing noise along
// the normal, a misalignment (the part lies somewhere on the CMM table) and a
// few blunders (dust, a mis-trigger: large offsets along the normal).
//
// The machined surface is the nominal one unless `surface_offset` says by
// how much it lies above (+, material left) or below (-) the nominal along
// the normal at a planned point; the machining-prediction module plugs its
// z-map in here (simulate-measurement --prediction).
//
// Everything random comes from one std::mt19937 seeded with `seed`, so the
// same inputs give the same file.
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "io/measurement_file.hpp"
#include "io/plan_file.hpp"

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

struct SimulationOptions {
  Misalignment misalignment;
  double noise_sigma = 0.002;                   // [mm] along the normal
  int blunders = 0;                             // how many points get a blunder
  double blunder_min = 0.1, blunder_max = 1.0;  // [mm] blunder size range (random sign)
  std::uint32_t seed = 1;
  ProbePointKind kind = ProbePointKind::probe_centre;
  bool anonymous = false;        // no ids, points shuffled (as an unplanned scan)
  SurfaceOffset surface_offset;  // empty: the nominal surface
};

struct SimulatedMeasurement {
  MeasurementSet set;                  // CMM frame, probe from the plan
  std::vector<std::string> plan_ids;   // plan id of each measured point (also when anonymous)
  std::vector<bool> blunder;           // per measured point
  std::vector<double> true_deviation;  // offset + noise + blunder along the normal [mm]
};

// Throws InputError for a negative noise, more blunders than points or a
// bad blunder range.
SimulatedMeasurement simulate_measurement(const InspectionPlan& plan,
                                          const SimulationOptions& options,
                                          const std::string& name = "simulated");

// A plan of nu x nv points on an even (u,v) grid of every face (cell
// centres; trimmed-away ones skipped), approach/retract `clearance` mm out
// along the normal. A baseline and a test aid, not a risk-based plan.
InspectionPlan grid_plan(const Part& part, int nu, int nv, const ProbeDefinition& probe,
                         double clearance = 5);

}  // namespace furrow
