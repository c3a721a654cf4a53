#pragma once
// The options of a simulated scan (`furrow simulate-measurement --scan`),
// described once (base/option_table.hpp). The part's placement in the
// scanner's frame (--misalign), the seed and planted bumps (--bump) are the
// measurement simulation's own options (simulation_options.hpp), taken for a
// scan too.
#include "base/option_table.hpp"
#include "inspection/scan_simulation.hpp"
#include "stage/simulation_options.hpp"

namespace furrow {

struct ScanSimulationOptions {
  ScannerModel scanner;
  bool inch = false;  // write the cloud in inches, as some scanner software does
};

const OptionTable<ScanSimulationOptions>& scan_simulation_option_table();

// The measurement simulation's options a scan takes too: "misalign" (the
// part's placement in the scanner's frame) and "seed" (a job's simulated
// scan reads them with this table; the command reads the whole
// simulation table and refuses the probe-only ones).
const OptionTable<SimulationOptions>& scan_simulation_placement_table();

}  // namespace furrow
