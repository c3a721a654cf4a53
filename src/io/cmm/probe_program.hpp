#pragma once
// A CMM measuring program as plain data: what the DMIS and I++ DME writers
// print and their strict readers give back (dmis_writer.hpp,
// ippdme_writer.hpp). The planner (src/planning) fills it from a plan and
// its moves; io knows nothing of how the points were chosen.
//
// Positions: `moves_before` and `final_moves` are probe-ball-centre targets
// (DMIS GOTO, I++ GoTo), part frame, mm. A step's point gives the nominal
// contact point xyz and the outward unit normal ijk; the CMM touches moving
// along -ijk from `approach` mm (ball surface to surface) and backs off
// `retract` mm, searching up to `search` mm past the nominal point.
// The last move before a point is its approach point (plan.json `approach`).
//
// Numbers in both programs are fixed-point: coordinates with
// kProgramDecimals decimals (1 nm, far below any CMM's resolution; at most
// 16 digits as the I++ DME spec requires for |x| < 1e9), directions with
// kDirectionDecimals.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/plan_file.hpp"

namespace furrow {

constexpr int kProgramDecimals = 6;
constexpr int kDirectionDecimals = 9;

struct ProgramStep {
  PlannedPoint point;
  std::vector<Eigen::Vector3d> moves_before;  // GOTO targets, the last = approach point
};

struct ProbeProgram {
  std::string name;       // program name: letters, digits, '_' and '-' (checked by the writers)
  std::string part;       // informative, in a comment (DMIS only)
  ProbeDefinition probe;  // probe.name is the sensor / tool label
  double stylus_length = 0;  // ball centre to probe body [mm] (DMIS SNSDEF)
  double approach = 0, retract = 0, search = 0;  // [mm], > 0
  std::vector<ProgramStep> steps;
  std::vector<Eigen::Vector3d> final_moves;
};

// Fixed-point text with `decimals` digits; "-0.000" is written "0.000".
std::string fixed_number(double value, int decimals);

// Throws InputError when a name, label or number cannot be written into a
// program: empty or non-ASCII names, ids that are not DMIS labels
// ([A-Za-z0-9_]), non-finite numbers, non-positive distances, |coordinate|
// >= 1e9. `format` ("DMIS", "I++ DME") prefixes the message.
void check_program(const ProbeProgram& program, const std::string& format);

}  // namespace furrow
