#pragma once
// A real comparison document for the report tests: the mould example
// measured on a 16 x 12 grid plan (simulated: a 60 um dent 20 mm wide,
// 1 um noise, a small misalignment), registered and read back through
// comparison.json exactly as `furrow report` sees it.
#include <string>

#include "geometry/closest_point.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"

namespace furrow::test {

struct ReportFixture {
  Part part;
  ComparisonDocument doc;
  std::string comparison_json;  // the text doc was read from (an oracle for the report's tables)
};

inline ReportFixture make_report_fixture() {
  ReportFixture f;
  f.part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const InspectionPlan plan = grid_plan(f.part, 16, 12, {"ruby", 2.0});
  SimulationOptions sim;
  sim.noise_sigma = 0.001;
  sim.seed = 5;
  sim.misalignment = {{0.5, -0.3, 10}, {5, -3, 2}};
  sim.bumps.push_back({plan.points[100].xyz, 20.0, -0.06});  // a dent around grid point 100
  const SimulatedMeasurement measured = simulate_measurement(plan, sim, "grid");
  CompareOptions options;
  options.tolerance = ToleranceZone::make(0.05, 0.025, "test");
  options.registration.loss_scale = options.registration.outlier_floor = 0.025;
  const ClosestPointFinder finder(f.part);
  const Comparison c = compare_measurements(finder, measured.set, &plan, options);
  ComparisonSources sources;
  sources.part = "examples/parts/mould.json";
  sources.measurements = "grid.csv";
  f.comparison_json = comparison_to_json_text(c, measured.set, f.part, options, sources);
  f.doc = parse_comparison(f.comparison_json, "comparison.json");
  return f;
}

}  // namespace furrow::test
