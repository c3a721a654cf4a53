#pragma once
// The simulated scan stage (`furrow simulate-measurement --scan`, and a
// job's `"measurements": {"scan": {"simulate": {...}}}`): the scanner model
// run on the part (inspection/scan_simulation.hpp) and the cloud written as
// scanner software writes it, a binary little-endian PLY with double x y z,
// float normals, grey colour and intensity (docs/scan_simulation.md). One
// function, so the command and the job write the same bytes.
#include <string>

#include "geometry/part.hpp"
#include "stage/scan_simulation_options.hpp"

namespace furrow {

struct SimulatedScanFile {
  SimulatedScan scan;  // part frame data and ray counts
  std::string ply;     // the file's bytes
};

// `options.scanner` complete (placement, seed and bumps set by the caller);
// `part_name` is named in the file's comment (its file name, no folder).
// Coordinates in inches when options.inch. Throws InputError for a model
// the simulation refuses.
SimulatedScanFile simulate_scan_stage(const Part& part, const ScanSimulationOptions& options,
                                      const std::string& part_name);

}  // namespace furrow
