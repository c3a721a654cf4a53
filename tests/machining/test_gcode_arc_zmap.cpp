// A G2 arc and the same arc as fine G1 segments cut the same z-map: the
// flattening's chord sag (1e-4 mm) is below the 0.1 µm a prediction prints.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "io/machining/gcode_reader.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

TEST_CASE("z-map: a G2 arc cuts what the same arc as fine G1 segments cuts, to 0.1 um") {
  constexpr double kPi = 3.14159265358979323846;
  const std::string start = "G21 G90 G0 X10 Y0 Z5\nG1 Z0 F500\n";
  std::string fine = start;
  const int n = 4000;  // chord sag 10 (1 - cos(pi / 16000)) = 2e-7 mm
  char buf[96];
  for (int k = 1; k <= n; ++k) {
    const double a = -kPi / 2 * k / n;
    std::snprintf(buf, sizeof buf, "G1 X%.12f Y%.12f\n", 10 * std::cos(a), 10 * std::sin(a));
    fine += buf;
  }
  const Toolpath lines = parse_gcode(fine, "fine.nc");
  const Toolpath arc = parse_gcode(start + "G2 X0 Y-10 I-10 J0\n", "arc.nc");
  REQUIRE(arc.point_count() < lines.point_count() / 10);  // really flattened coarser

  const Cutter ball("ball6", 3, 3);
  const Eigen::AlignedBox2d extent(Eigen::Vector2d(-4, -14), Eigen::Vector2d(14, 4));
  ZMap a(extent, 0.05), b(extent, 0.05);
  a.cut(ball, moves_from_toolpath(arc));
  b.cut(ball, moves_from_toolpath(lines));
  // Compared where the groove's flank is no steeper than 45 degrees (depth
  // below the tip's top <= r (1 - cos 45)): there a sideways chord sag s
  // moves the surface by at most s; on steeper flanks it moves it by s times
  // the slope, which is the geometry, not the reader.
  const double shallow = 3 * (1 - std::cos(kPi / 4));
  int compared = 0;
  double worst = 0;
  for (int i = 0; i < a.nx(); ++i)
    for (int j = 0; j < a.ny(); ++j) {
      const double ha = a.node_height(i, j), hb = b.node_height(i, j);
      if (!std::isfinite(ha) || !std::isfinite(hb) || hb > shallow) continue;
      worst = std::max(worst, std::abs(ha - hb));
      ++compared;
    }
  CHECK(compared > 1000);
  CHECK(worst < 1e-4);
}
