#pragma once
// The options of the measurement simulation (`furrow simulate-measurement`,
// a job's "measurements": {"simulate": {...}}), described once
// (base/option_table.hpp). Planted bumps are not among them: the command
// line repeats --bump X,Y,Z,R,H where a job file lists [[x, y, z, r, h], ...].
#include "base/option_table.hpp"
#include "inspection/measurement_simulation.hpp"

namespace furrow {

const OptionTable<SimulationOptions>& simulation_option_table();

}  // namespace furrow
