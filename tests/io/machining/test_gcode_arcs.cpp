// G2/G3 arcs read from G-code against the analytic circle they describe.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.hpp"
#include "io/machining/gcode_reader.hpp"
#include "support/input_error.hpp"

using namespace furrow;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string error_of(const std::string& text) {
  return test::input_error_of([&] { parse_gcode(text, "arc.nc"); });
}

// All points of the only pass, which must start at `start`.
std::vector<Eigen::Vector3d> arc_points(const std::string& text, const Eigen::Vector3d& start,
                                        const ToolpathReadOptions& options = {}) {
  const Toolpath p = parse_gcode(text, "arc.nc", options);
  REQUIRE(p.passes.size() == 1);
  std::vector<Eigen::Vector3d> out;
  for (const auto& t : p.passes[0].points) out.push_back(t.position);
  CHECK((out.front() - start).norm() == 0);
  return out;
}

// Every point at `radius` from `centre` in the (u, v) plane, every chord's
// midpoint no deeper than `sag` inside the circle, and the signed angle swept
// (sum of the per-chord angles, each less than half a turn).
double check_on_circle(const std::vector<Eigen::Vector3d>& pts, int u, int v, const Eigen::Vector2d& centre,
                       double radius, double sag) {
  double swept = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector2d q(pts[k][u], pts[k][v]);
    CHECK(std::abs((q - centre).norm() - radius) < 1e-9);
    if (k == 0) continue;
    const Eigen::Vector2d p(pts[k - 1][u], pts[k - 1][v]);
    const double depth = radius - ((p + q) / 2 - centre).norm();
    CHECK(depth <= sag + 1e-12);
    const Eigen::Vector2d a = p - centre, b = q - centre;
    const double step = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    CHECK(std::abs(step) < kPi / 2 + 1e-12);
    swept += step;
  }
  return swept;
}

}  // namespace

TEST_CASE("G-code arcs: G2 and G3 quarter circles in G17 lie on the circle within the chord sag") {
  const auto cw = arc_points("G21 G90 G17\nG0 X10 Y0 Z1\nG2 X0 Y-10 I-10 J0 F500\n", {10, 0, 1});
  CHECK(cw.back() == Eigen::Vector3d(0, -10, 1));  // exact endpoint
  CHECK(check_on_circle(cw, 0, 1, {0, 0}, 10, 1e-4) == doctest::Approx(-kPi / 2).epsilon(1e-12));
  // At the default sag 1e-4 mm a chord spans at most 2 acos(1 - 1e-4 / r).
  CHECK(cw.size() == 1 + static_cast<std::size_t>(std::ceil((kPi / 2) / (2 * std::acos(1 - 1e-4 / 10)))));
  for (const auto& p : cw) CHECK(p.z() == 1);

  const auto ccw = arc_points("G90 G0 X10 Y0 Z1\nG3 X0 Y-10 I-10 J0 F500\n", {10, 0, 1});
  CHECK(check_on_circle(ccw, 0, 1, {0, 0}, 10, 1e-4) == doctest::Approx(3 * kPi / 2).epsilon(1e-12));

  // A coarser sag from the options: fewer chords, still within it.
  ToolpathReadOptions coarse;
  coarse.arc_tolerance = 0.01;
  const auto few = arc_points("G90 G0 X10 Y0 Z1\nG2 X0 Y-10 I-10 J0\n", {10, 0, 1}, coarse);
  CHECK(few.size() < cw.size());
  check_on_circle(few, 0, 1, {0, 0}, 10, 0.01);
}

TEST_CASE("G-code arcs: the same path as fine G1 segments gives the same polyline to the sag") {
  // The fine version, written the way a post without arc output would.
  std::string fine = "G90 G0 X10 Y0 Z0\n";
  const int n = 4000;
  char buf[96];
  for (int k = 1; k <= n; ++k) {
    const double a = -kPi / 2 * k / n;
    std::snprintf(buf, sizeof buf, "G1 X%.12f Y%.12f\n", 10 * std::cos(a), 10 * std::sin(a));
    fine += buf;
  }
  const auto lines = arc_points(fine, {10, 0, 0});
  const auto arc = arc_points("G90 G0 X10 Y0 Z0\nG2 X0 Y-10 I-10\n", {10, 0, 0});
  // Every fine point is within the sag of the flattened polyline (distance to
  // the nearest chord, brute force).
  double worst = 0;
  for (const auto& p : lines) {
    double best = 1e9;
    for (std::size_t k = 1; k < arc.size(); ++k) {
      const Eigen::Vector3d d = arc[k] - arc[k - 1];
      const double t = std::clamp((p - arc[k - 1]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (arc[k - 1] + t * d - p).norm());
    }
    worst = std::max(worst, best);
  }
  CHECK(worst <= 1e-4 + 1e-9);
  CHECK(worst > 1e-6);  // the chords are not the circle: the check can fail
}

TEST_CASE("G-code arcs: a helix rises linearly with the angle, in each plane") {
  // G17: a full circle (end = start in XY) that descends 2 mm.
  const auto h = arc_points("G90 G0 X5 Y0 Z0\nG3 X5 Y0 Z-2 I-5 J0\n", {5, 0, 0});
  CHECK(h.back() == Eigen::Vector3d(5, 0, -2));
  double angle = 0;
  for (std::size_t k = 1; k < h.size(); ++k) {
    const double a = std::atan2(h[k - 1].x() * h[k].y() - h[k - 1].y() * h[k].x(),
                                h[k - 1].x() * h[k].x() + h[k - 1].y() * h[k].y());
    angle += a;
    CHECK(h[k].z() == doctest::Approx(-2 * angle / (2 * kPi)).epsilon(1e-12));
  }
  CHECK(angle == doctest::Approx(2 * kPi).epsilon(1e-12));

  // G18 (ZX, seen from +Y): G2 from the +X side to the +Z side is the short
  // quarter; Y moves along the normal.
  const auto zx = arc_points("G90 G18 G0 X10 Y0 Z0\nG2 X0 Y3 Z10 I-10 K0\n", {10, 0, 0});
  const double zx_swept = check_on_circle(zx, 2, 0, {0, 0}, 10, 1e-4);
  CHECK(zx_swept == doctest::Approx(-kPi / 2).epsilon(1e-12));
  for (const auto& p : zx) {
    CHECK(p.x() >= -1e-12);
    CHECK(p.z() >= -1e-12);
    CHECK(p.y() == doctest::Approx(3 * std::atan2(p.z(), p.x()) / (kPi / 2)).epsilon(1e-9));
  }
  // G19 (YZ, seen from +X): G3 from +Y to +Z is the short quarter.
  const auto yz = arc_points("G90 G19 G0 X0 Y10 Z0\nG3 Y0 Z10 J-10 K0\n", {0, 10, 0});
  CHECK(check_on_circle(yz, 1, 2, {0, 0}, 10, 1e-4) == doctest::Approx(kPi / 2).epsilon(1e-12));
}

TEST_CASE("G-code arcs: R format puts the centre on the side its sign says") {
  // Chord (0,0)-(10,0), R 10: centre at (5, -+sqrt(75)). G2 with R > 0 is the
  // short clockwise arc, its centre right of the chord (below); R < 0 the long one.
  const double h = std::sqrt(75.0);
  const auto g2_short = arc_points("G90 G0 X0 Y0 Z0\nG2 X10 Y0 R10\n", {0, 0, 0});
  CHECK(check_on_circle(g2_short, 0, 1, {5, -h}, 10, 1e-4) == doctest::Approx(-kPi / 3).epsilon(1e-12));
  const auto g2_long = arc_points("G90 G0 X0 Y0 Z0\nG2 X10 Y0 R-10\n", {0, 0, 0});
  CHECK(check_on_circle(g2_long, 0, 1, {5, h}, 10, 1e-4) == doctest::Approx(-5 * kPi / 3).epsilon(1e-12));
  const auto g3_short = arc_points("G90 G0 X0 Y0 Z0\nG3 X10 Y0 R10\n", {0, 0, 0});
  CHECK(check_on_circle(g3_short, 0, 1, {5, h}, 10, 1e-4) == doctest::Approx(kPi / 3).epsilon(1e-12));
  const auto g3_long = arc_points("G90 G0 X0 Y0 Z0\nG3 X10 Y0 R-10\n", {0, 0, 0});
  CHECK(check_on_circle(g3_long, 0, 1, {5, -h}, 10, 1e-4) == doctest::Approx(5 * kPi / 3).epsilon(1e-12));
  // A half circle: R exactly half the chord.
  const auto half = arc_points("G90 G0 X0 Y0 Z0\nG2 X10 Y0 R5\n", {0, 0, 0});
  CHECK(check_on_circle(half, 0, 1, {5, 0}, 5, 1e-4) == doctest::Approx(-kPi).epsilon(1e-12));
}

TEST_CASE("G-code arcs: full circles, incremental coordinates and inch") {
  const auto full = arc_points("G90 G0 X0 Y0 Z-1\nG2 X0 Y0 I5 J0\n", {0, 0, -1});
  CHECK(full.back() == Eigen::Vector3d(0, 0, -1));
  CHECK(check_on_circle(full, 0, 1, {5, 0}, 5, 1e-4) == doctest::Approx(-2 * kPi).epsilon(1e-12));
  // Omitting both end words is the same full circle.
  const auto same = arc_points("G90 G0 X0 Y0 Z-1\nG2 I5\n", {0, 0, -1});
  CHECK(same == full);

  // G91: the end is relative; I J stay offsets from the start.
  const auto rel = arc_points("G90 G0 X10 Y10 Z0\nG91 G3 X-10 Y10 I-10 J0\n", {10, 10, 0});
  CHECK(rel.back() == Eigen::Vector3d(0, 20, 0));
  CHECK(check_on_circle(rel, 0, 1, {0, 10}, 10, 1e-4) == doctest::Approx(kPi / 2).epsilon(1e-12));

  // Inch: end, centre and R scale by 25.4.
  const auto inch = arc_points("G20 G90 G0 X0 Y0 Z1.\nG3 X1. Y0 I.5 J0\n", {0, 0, 25.4});
  CHECK(inch.back() == Eigen::Vector3d(25.4, 0, 25.4));
  CHECK(check_on_circle(inch, 0, 1, {12.7, 0}, 12.7, 1e-4) == doctest::Approx(kPi).epsilon(1e-12));
  const auto inch_r = arc_points("G20 G90 G0 X0 Y0 Z0\nG3 X1. Y0 R.5\n", {0, 0, 0});
  CHECK(check_on_circle(inch_r, 0, 1, {12.7, 0}, 12.7, 1e-4) == doctest::Approx(kPi).epsilon(1e-12));
}

TEST_CASE("G-code arcs: errors name the line") {
  const std::string start = "G90 G0 X0 Y0 Z0\n";
  CHECK(error_of(start + "G2 X0 Y0 R5\n").find("arc.nc:2: G2: an R-format arc cannot be a full circle") == 0);
  CHECK(error_of(start + "G2 X10 Y1 I5 J0\n").find("arc.nc:2: G2: arc start radius 5 mm and end radius") == 0);
  // Within the radius tolerance (rounded posts): accepted.
  CHECK(error_of(start + "G2 X10 Y0.2 I5 J0\n").empty());  // radii differ by 0.004 mm
  CHECK(error_of(start + "G2 X10 Y0.25 I5 J0\n").find("arc.nc:2: G2: arc start radius") == 0);  // 0.00625
  CHECK(error_of(start + "G3 X10 Y0 R0\n").find("arc.nc:2: G3: arc radius R is zero") == 0);
  CHECK(error_of(start + "G3 X10 Y0 I0 J0\n").find("arc.nc:2: G3: arc radius is zero") == 0);
  CHECK(error_of(start + "G3 X10 Y0 R4\n").find("arc.nc:2: G3: arc radius R 4 mm is smaller than half") == 0);
  CHECK(error_of(start + "G17 G2 X10 Y0 I5 K0\n").find("arc.nc:2: K is not a centre word in plane G17") == 0);
  CHECK(error_of(start + "G18 G2 X10 Z0 J5\n").find("arc.nc:2: J is not a centre word in plane G18") == 0);
  CHECK(error_of(start + "G19 G2 Y10 Z0 I5\n").find("arc.nc:2: I is not a centre word in plane G19") == 0);
  CHECK(error_of(start + "G2 X10 Y0\n").find("arc.nc:2: arc without a centre") == 0);
  CHECK(error_of(start + "G2 X10 Y0 R5 I5\n").find("arc.nc:2: an arc takes either R or I J K") == 0);
  CHECK(error_of(start + "G1 X10 Y0 I5\n").find("arc.nc:2: I J K R belong to an arc") == 0);
  CHECK(error_of(start + "G90.1\nG2 X10 Y0 I5 J0\n").find("arc.nc:2: G90.1 (absolute arc centres)") == 0);
  CHECK(error_of(start + "G91.1 G2 X10 Y0 I5 J0\n").empty());
  CHECK(error_of("G0 X0 Y0\nG2 X10 Y0 I5 J0\n").find("arc.nc:2: arc before X, Y and Z are all known") == 0);
  ToolpathReadOptions zero;
  zero.arc_tolerance = 0;
  try {
    parse_gcode(start + "G1 X1\n", "arc.nc", zero);
    FAIL("a zero chord tolerance was accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("arc.nc: the arc chord tolerance") == 0);
  }
}
