#pragma once
// Axis ticks shared by the raster canvas (plot_canvas.hpp) and the vector
// figures (chart.hpp): "nice" 1-2-5 steps and their labels, so an axis reads
// the same in every figure.
#include <string>
#include <vector>

namespace furrow::plot {

// Tick values at 1-2-5 steps covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);
// A number for a tick label: no trailing zeros, no "-0".
std::string tick_label(double value, double step);

}  // namespace furrow::plot
