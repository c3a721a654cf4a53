// Reading G-code: 1,000,000 lines as a Fanuc-style post writes them (N
// numbers, modal words without repeats, a comment now and then, one line in
// a hundred an arc), parsed in memory. Prints lines, points, seconds and lines/s
// (best of 3; target < 2 s on the 2-core machine). Prints figures; it does
// not pass or fail.
//   usage: bench_gcode [LINES]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/machining/gcode_reader.hpp"

using namespace furrow;

int main(int argc, char** argv) {
  const long lines = argc > 1 ? std::atol(argv[1]) : 1'000'000;
  std::string text = "%\nO1000 (BENCH)\nN1 G90 G94 G17 G49 G40 G80\nN2 G21\nN3 T1 M6\nN4 S8000 M3\n"
                     "N5 G0 X0. Y0.\nN6 G43 Z5. H1\nN7 G1 Z0. F1000.\n";
  long written = 9;
  char buf[128];
  double x = 0;
  for (long k = 0; written < lines - 2; ++k, ++written) {
    if (k % 50 == 0) {
      std::snprintf(buf, sizeof buf, "(ROW %ld)\n", k / 50);
    } else if (k % 100 == 25) {
      // A half circle of radius 0.05 mm (about 25 points).
      std::snprintf(buf, sizeof buf, "N%ld G3 X%.4f Y%.4f I0.05 J0.\n", k + 10, x + 0.1, 0.0);
      x += 0.1;
    } else {
      x += 0.01;
      std::snprintf(buf, sizeof buf, "N%ld G1 X%.4f Y%.4f Z%.4f\n", k + 10, x, 0.001 * (k % 7), -0.01 * (k % 3));
    }
    text += buf;
  }
  text += "N999999 M30\n%\n";
  written += 2;

  double best = 1e300;
  std::size_t points = 0;
  for (int run = 0; run < 3; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    const Toolpath p = parse_gcode(text, "bench.nc");
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    points = p.point_count();
    if (s < best) best = s;
  }
  std::printf("G-code: %ld lines (%.1f MB), %zu path points (arcs flattened at 1e-4 mm)\n", written,
              static_cast<double>(text.size()) / 1e6, points);
  std::printf("parse: %.3f s (best of 3), %.0f lines/s (target < 2 s for 1,000,000 lines)\n", best,
              static_cast<double>(written) / best);
  return 0;
}
