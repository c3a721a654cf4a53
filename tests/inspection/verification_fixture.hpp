#pragma once
// The inspection tests' fixture: synthetic predictions of the mould
// (support/synthetic_prediction.hpp), a dent to machine into a simulated
// part, and the comparison options the CLI derives from a tolerance.
#include <cmath>

#include "inspection/comparison.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/synthetic_prediction.hpp"

namespace furrow::test {

inline Part mould_part() { return read_part(source_path("examples/parts/mould.json")); }

// A smooth dent of `depth` (> 0) within `radius` (uv units) of `centre`:
// -depth (1 + cos(pi rho / radius)) / 2.
inline double dent(const Eigen::Vector2d& uv, const Eigen::Vector2d& centre, double radius, double depth) {
  const double rho = (uv - centre).norm();
  return rho < radius ? -depth * (1 + std::cos(M_PI * rho / radius)) / 2 : 0.0;
}

// The registration options the CLI derives from a tolerance.
inline CompareOptions compare_options(double tolerance) {
  CompareOptions o;
  o.tolerance = ToleranceZone::make(tolerance, tolerance / 2, "test");
  o.registration.loss_scale = tolerance / 2;
  o.registration.outlier_floor = tolerance / 2;
  return o;
}

}  // namespace furrow::test
