#include "planning/alignment_moves.hpp"

#include <algorithm>

namespace furrow {

void add_alignment_moves(ProbeProgram& program, const PartAlignment& alignment, double clearance_z,
                         const Eigen::Vector3d& start) {
  program.alignment = alignment;
  program.alignment_steps.clear();
  program.alignment_final_moves.clear();
  const Eigen::Vector3d* previous = nullptr;
  auto above = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p.x(), p.y(), std::max(clearance_z, p.z()));
  };
  const std::vector<PlannedPoint> points = alignment.points();
  for (const PlannedPoint& p : points) {
    ProgramStep step;
    step.point = p;
    if (previous && previous->z() < clearance_z) step.moves_before.push_back(above(*previous));
    step.moves_before.push_back(above(p.approach));
    if (p.approach.z() < clearance_z) step.moves_before.push_back(p.approach);
    program.alignment_steps.push_back(std::move(step));
    previous = &p.retract;
  }
  if (previous) {
    if (previous->z() < clearance_z) program.alignment_final_moves.push_back(above(*previous));
    program.alignment_final_moves.push_back(start);
  }
}

}  // namespace furrow
