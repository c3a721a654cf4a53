// Rapid moves against the part and the stock (machining/prediction/rapid_check.hpp),
// with closed-form oracles: a ball swept along a line through a flat plate or
// a sphere.
#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/prediction/rapid_check.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;
using furrow::test::one_face;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The plate z = 0 over [-50, 50] x [-30, 30], normal +z.
Part plate() { return one_face("plate", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0})); }

RapidMove rapid(const Eigen::Vector3d& from, const Eigen::Vector3d& to, int line) {
  RapidMove r;
  r.line = line;
  r.known = true;
  r.from = from;
  r.to = to;
  return r;
}

RapidCheckOptions coarse() {
  RapidCheckOptions o;
  o.sample_spacing = 0.5;  // the refinement finds the deepest point between samples
  o.threshold = 0.02;
  return o;
}

// Distance from o to the line through a and b.
double line_distance(const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = (b - a).normalized();
  const Eigen::Vector3d w = o - a;
  return (w - w.dot(d) * d).norm();
}

}  // namespace

TEST_CASE("rapid check: a rapid diving through a flat plate is a part gouge as deep as its lowest tip") {
  const Part part = plate();
  const Cutter ball("ball6", 3, 3);
  // From above the plate down to 2 mm below its top: the deepest point is
  // under the end, where the ball's bottom is the tip itself.
  const RapidCheck r = check_rapids(part, ball, {rapid({-30, 0, 0.5}, {40, 10, -2}, 8)}, coarse());
  CHECK(r.rapids == 1);
  CHECK(r.checked == 1);
  CHECK(r.unchecked == 0);
  REQUIRE(r.gouges.size() == 1);
  const RapidGouge& g = r.gouges[0];
  CHECK(g.line == 8);
  CHECK(g.kind == RapidGougeKind::part);
  CHECK(g.face == 0);
  CHECK(g.depth == doctest::Approx(2.0).epsilon(1e-9));
  CHECK(g.at.x() == doctest::Approx(40).epsilon(1e-5));
  CHECK(g.at.y() == doctest::Approx(10).epsilon(1e-5));
  CHECK(std::fabs(g.at.z()) < 1e-9);
}

TEST_CASE("rapid check: a ball swept along a line past a sphere goes in by rho + R - distance") {
  // Sphere of radius rho at the origin (upper half); ball centres on the
  // line C(s). The swept capsule reaches the sphere along the line from the
  // origin to the closest centre, so the deepest overcut along the normal is
  // rho + R - D, at rho times that direction (D the line's distance from the
  // origin, the closest point inside the segment).
  const double rho = 20, R = 5;
  const Part part = one_face("dome", make_sphere(rho, -kPi, kPi, 0, kPi / 2));
  const Cutter ball("ball10", R, R);
  struct Case {
    Eigen::Vector3d from, to;  // tips
  } cases[] = {{{-30, 4, 17}, {30, 4, 17}}, {{-30, -2, 25}, {30, 3, 12}}, {{-25, -25, 16}, {25, 20, 18}}};
  int line = 10;
  for (const Case& c : cases) {
    CAPTURE(line);
    const Eigen::Vector3d up(0, 0, R);
    const Eigen::Vector3d a = c.from + up, b = c.to + up;  // ball centres
    const Eigen::Vector3d o(0, 0, 0);
    const double D = line_distance(o, a, b);
    const double s = (o - a).dot(b - a) / (b - a).squaredNorm();
    REQUIRE(s > 0.05);
    REQUIRE(s < 0.95);
    const Eigen::Vector3d closest = a + s * (b - a);
    REQUIRE(closest.z() > 0);
    REQUIRE(D < rho + R - 0.1);
    const double depth = rho + R - D;
    const Eigen::Vector3d where = rho * closest.normalized();
    const RapidCheck r = check_rapids(part, ball, {rapid(c.from, c.to, line)}, coarse());
    REQUIRE(r.gouges.size() == 1);
    CHECK(r.gouges[0].line == line);
    CHECK(r.gouges[0].depth == doctest::Approx(depth).epsilon(1e-7));
    CHECK((r.gouges[0].at - where).norm() < 2e-3);
    ++line;
  }
}

TEST_CASE("rapid check: rapids above the part, or dipping less than the threshold, are clear") {
  const Part part = plate();
  const Cutter ball("ball6", 3, 3);
  const Cutter flat("flat6", 3, 0);
  const Cutter bull("bull8", 4, 1);
  RapidCheckOptions o = coarse();
  for (const Cutter* c : {&ball, &flat, &bull}) {
    CAPTURE(c->name());
    // Across the whole plate 0.5 mm above it, and down to 0.015 mm below
    // it (less than the 0.02 mm threshold).
    const RapidCheck r = check_rapids(
        part, *c, {rapid({-60, -20, 0.5}, {60, 20, 0.5}, 3), rapid({0, 0, 5}, {0, 0, -0.015}, 4)}, o);
    CHECK(r.checked == 2);
    CHECK(r.gouges.empty());
    // 0.03 mm below it is a gouge for every cutter (each bottoms at its tip).
    const RapidCheck deeper = check_rapids(part, *c, {rapid({0, 0, 5}, {0, 0, -0.03}, 5)}, o);
    REQUIRE(deeper.gouges.size() == 1);
    CHECK(deeper.gouges[0].depth == doctest::Approx(0.03).epsilon(1e-6));
  }
}

TEST_CASE("rapid check: below the stock top but above the part is a gouge only with a stock box") {
  const Part part = plate();
  const Cutter ball("ball6", 3, 3);
  const std::vector<RapidMove> rapids = {
      rapid({-70, 0, 2}, {70, 0, 2}, 5),    // level, 3 mm below the stock top
      rapid({-70, 0, 8}, {-45, 0, 3}, 6),   // descending into the stock
      rapid({-70, 0, 2}, {-70, 40, 2}, 7),  // beside the stock: the disc never reaches it
      rapid({0, 0, 6}, {10, 0, 5.5}, 8)};   // above the stock top
  RapidCheckOptions o = coarse();
  const RapidCheck without = check_rapids(part, ball, rapids, o);
  CHECK(without.checked == 4);
  CHECK(without.gouges.empty());
  o.stock = Eigen::AlignedBox3d(Eigen::Vector3d(-50, -30, -10), Eigen::Vector3d(50, 30, 5));
  const RapidCheck with = check_rapids(part, ball, rapids, o);
  CHECK(with.stock);
  REQUIRE(with.gouges.size() == 2);
  // Level: the tip is at z = 2 from where the ball's disc first overlaps
  // the box (x = -50 - R); the first such point is reported.
  CHECK(with.gouges[0].line == 5);
  CHECK(with.gouges[0].kind == RapidGougeKind::stock);
  CHECK(with.gouges[0].depth == doctest::Approx(3).epsilon(1e-12));
  CHECK((with.gouges[0].at - Eigen::Vector3d(-53, 0, 2)).norm() < 1e-9);
  // Descending: lowest at its end.
  CHECK(with.gouges[1].line == 6);
  CHECK(with.gouges[1].depth == doctest::Approx(2).epsilon(1e-12));
  CHECK((with.gouges[1].at - Eigen::Vector3d(-45, 0, 3)).norm() < 1e-9);
  // The disc reaches the box's corner region only by its radius: a rapid
  // passing 3.5 mm from the box's side is clear, 2.5 mm is not.
  const RapidCheck side = check_rapids(
      part, ball, {rapid({-53.5, -40, 0}, {-53.5, 40, 0}, 9), rapid({-52.5, -40, 0}, {-52.5, 40, 0}, 10)}, o);
  REQUIRE(side.gouges.size() == 1);
  CHECK(side.gouges[0].line == 10);
  CHECK(side.gouges[0].depth == doctest::Approx(5).epsilon(1e-12));
}

TEST_CASE("rapid check: rapids not in the part frame are counted as unchecked, not placed") {
  const Part part = plate();
  const Cutter ball("ball6", 3, 3);
  // G0 from an unknown start (line 2), a cut, a rapid through the plate
  // (line 5), G28 home (line 6), G0 with Z still unknown (line 7), G0 back
  // down from a known position (line 8, clear).
  const Toolpath path = parse_gcode(
      "G21 G90 G54\n"
      "G0 X-40 Y0 Z10\n"
      "G0 Z0.5\n"
      "G1 X-30 F500\n"
      "G0 X0 Y0 Z-1\n"
      "G28 G91 Z0\n"
      "G90 G0 X10 Y5\n"
      "G0 Z20\n"
      "G0 Z1\n",
      "r.nc");
  REQUIRE(path.rapids.size() == 7);
  const RapidCheck r = check_rapids(part, ball, path.rapids, coarse());
  CHECK(r.rapids == 7);
  CHECK(r.unchecked == 4);  // lines 2, 6, 7, 8 (Z unknown until line 8 sets it)
  CHECK(r.checked == 3);    // lines 3, 5, 9
  REQUIRE(r.gouges.size() == 1);
  CHECK(r.gouges[0].line == 5);
  CHECK(r.gouges[0].depth == doctest::Approx(1).epsilon(1e-9));
}

TEST_CASE("rapid check: a bad stock box or spacing is refused") {
  const Part part = plate();
  const Cutter ball("ball6", 3, 3);
  RapidCheckOptions o = coarse();
  o.stock = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-1, 1, 1));
  CHECK_THROWS_AS(check_rapids(part, ball, {rapid({0, 0, 1}, {1, 0, 1}, 1)}, o), InputError);
  o = coarse();
  o.sample_spacing = 0;
  CHECK_THROWS_AS(check_rapids(part, ball, {rapid({0, 0, 1}, {1, 0, 1}, 1)}, o), InputError);
}
