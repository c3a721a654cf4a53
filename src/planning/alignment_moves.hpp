#pragma once
// The probe moves of a plan's alignment (docs/cmm.md "Part alignment"):
// every alignment point is reached over the clearance plane — up from the
// previous retract point, across, straight down to the approach point — as
// the accessibility check (vertical access) has cleared, and the last one
// leaves up and over to `start`, above the first free-form point. Datum
// points sit on walls and in corners where a straight move between two of
// them could cross the part; the clearance plane never does.
//
// Units: mm, probe-centre positions in the part frame.
#include <Eigen/Core>

#include "io/cmm/probe_program.hpp"
#include "io/plan_alignment.hpp"

namespace furrow {

// Fills program.alignment, alignment_steps and alignment_final_moves.
void add_alignment_moves(ProbeProgram& program, const PartAlignment& alignment, double clearance_z,
                         const Eigen::Vector3d& start);

}  // namespace furrow
