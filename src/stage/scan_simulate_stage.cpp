// The simulated scan stage (contract in scan_simulate_stage.hpp).
#include "stage/scan_simulate_stage.hpp"

#include <algorithm>
#include <cmath>

#include "io/ply_writer.hpp"

namespace furrow {

SimulatedScanFile simulate_scan_stage(const Part& part, const ScanSimulationOptions& o, const std::string& part_name) {
  SimulatedScanFile out;
  out.scan = simulate_scan(part, o.scanner);
  const SimulatedScan& scan = out.scan;
  const double unit = o.inch ? 25.4 : 1.0;
  std::vector<PlyColumn> columns = {{"x", PlyScalar::float64, {}}, {"y", PlyScalar::float64, {}},
                                    {"z", PlyScalar::float64, {}}, {"nx", PlyScalar::float32, {}},
                                    {"ny", PlyScalar::float32, {}}, {"nz", PlyScalar::float32, {}},
                                    {"red", PlyScalar::uchar, {}},  {"green", PlyScalar::uchar, {}},
                                    {"blue", PlyScalar::uchar, {}}, {"intensity", PlyScalar::float32, {}}};
  for (std::size_t k = 0; k < scan.points.size(); ++k) {
    for (int a = 0; a < 3; ++a) {
      columns[a].values.push_back(scan.points[k][a] / unit);
      columns[3 + a].values.push_back(scan.normals[k][a]);
    }
    // Grey by the return's strength, as a monochrome scanner colours it.
    const double grey = std::round(40 + 200 * std::clamp(double(scan.intensity[k]), 0.0, 1.0));
    for (int c = 6; c < 9; ++c) columns[c].values.push_back(grey);
    columns[9].values.push_back(scan.intensity[k]);
  }
  out.ply = ply_vertex_text(columns, {"furrow simulate-measurement --scan of " + part_name,
                                      std::string("units ") + (o.inch ? "inch" : "mm"),
                                      "seed " + std::to_string(o.scanner.seed)});
  return out;
}

}  // namespace furrow
