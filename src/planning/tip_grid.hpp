#pragma once
// The orientations an indexable head can take: its index grid, A range by
// B range at the head's steps (io/cmm/probe_head.hpp), each direction once
// (docs/cmm.md "Tips chosen by the planner").
//
// Grid points that give the same stylus direction are one orientation: at
// A = 0 (and A = 180) every B is the same vertical stylus, and B values 360
// degrees apart (-180 and 180) are the same turn. Of equal directions the
// one the head file lists as qualified gives the name (the operator
// qualified it under that name), else the first in grid order (A, then B,
// ascending); the vertical one is A = 0 with B = 0 when 0 is on the B grid,
// else the B grid's minimum.
//
// Order: grid order, A ascending, then B ascending. Deterministic.
#include <optional>
#include <vector>

#include "io/cmm/probe_head.hpp"

namespace furrow {

// Work cap on the grid (docs/formats.md "Limits"): a PH10's 7.5 degree grid
// has 673 orientations.
constexpr long kMaxTipOrientations = 20000;

// Grid points before merging equal directions (A values times B values),
// for the limit check before any work.
long tip_grid_size(const ProbeHead& head);

std::vector<TipAngles> tip_grid(const ProbeHead& head);

// Index of the vertical orientation (A = 0) in `grid`, or nullopt.
std::optional<std::size_t> vertical_orientation(const std::vector<TipAngles>& grid);

}  // namespace furrow
