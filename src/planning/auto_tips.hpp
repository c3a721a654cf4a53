#pragma once
// The planner's own choice of tips (`--tips auto`, docs/cmm.md "Tips chosen
// by the planner"): one step of check_reach (plan_steps.hpp).
//
// For every candidate point: the checks that do not depend on the tip
// (ball, approach path, vertical access: check_point_access) once; then,
// for each orientation of the head's grid (tip_grid.hpp) whose axis lies
// within --max-tilt of the point's normal, the checks that do
// (check_axis_access: stylus, probe body, head), as the tip cover asks for
// them (tip_cover.hpp: exact on small instances, lazy greedy otherwise).
// Orientations beyond the tilt limit are never checked. The collision model
// is accessibility.hpp's, unchanged.
//
// Reads the candidates (sampled), the options (head, tip cover limits) and
// the access options; sets s.tips and s.tip_angles (the chosen tips: the
// vertical one first, then in grid order), result.tip_choice, and per
// candidate original, normal, reach (over the chosen tips), kept,
// nearest_tip and access (the reason for a point no chosen tip reaches).
// Relocation of those is left to the caller. Deterministic; the collision
// checks run in parallel into fixed slots.
#include "planning/plan_steps.hpp"

namespace furrow {

void choose_auto_tips(PlanState& s);

}  // namespace furrow
