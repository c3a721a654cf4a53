#pragma once
// The options of a simulated scan (`furrow simulate-measurement --scan`),
// described once (base/option_table.hpp). The part's placement in the
// scanner's frame (--misalign), the seed and planted bumps (--bump) are the
// measurement simulation's own options (simulation_options.hpp), taken for a
// scan too.
#include "base/option_table.hpp"
#include "inspection/scan_simulation.hpp"

namespace furrow {

struct ScanSimulationOptions {
  ScannerModel scanner;
  bool inch = false;  // write the cloud in inches, as some scanner software does
};

const OptionTable<ScanSimulationOptions>& scan_simulation_option_table();

}  // namespace furrow
