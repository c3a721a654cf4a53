#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "machining/prediction/cross_section_scallop.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/pass_scallops.hpp"

using namespace furrow;

TEST_CASE("cross-section scallop: a bull-nose on a flat part follows 2(R - r) + 2 sqrt(2 r h - h^2)") {
  const Cutter bull("bull", 5, 1.5);
  for (double h : {0.001, 0.005, 0.05}) {
    const double w = 2 * (5 - 1.5) + 2 * std::sqrt(2 * 1.5 * h - h * h);
    const auto height = cutter_scallop_height(bull, 0.0, 0.0, w);
    REQUIRE(height);
    CHECK(*height == doctest::Approx(h).epsilon(1e-6));
    const SideStepResult s = cutter_side_step_for_scallop(bull, 0.0, 0.0, h);
    CHECK(s.converged);
    CHECK(s.side_step == doctest::Approx(w).epsilon(1e-6));
  }
  // Flat bottoms overlapping: nothing is left.
  CHECK(*cutter_scallop_height(bull, 0.0, 0.0, 6.9) == doctest::Approx(0).scale(1e-9));
  // A flat end mill leaves no scallop until the bottoms part.
  const Cutter flat("flat", 4, 0);
  CHECK(*cutter_scallop_height(flat, 0.0, 0.0, 7.9) == doctest::Approx(0).scale(1e-9));
  CHECK_FALSE(cutter_scallop_height(flat, 0.0, 0.0, 8.1));
}

TEST_CASE("cross-section scallop: the ball is the closed form at any tilt") {
  const Cutter ball("ball", 3, 3);
  for (double k : {-1 / 25.4, 0.0, 1 / 25.4})
    for (double tilt : {0.0, 0.4}) {
      CHECK(*cutter_scallop_height(ball, k, tilt, 0.8) == doctest::Approx(*ball_scallop_height(3, k, 0.8)).epsilon(1e-14));
      // Within the side-step tolerance (1e-6 mm by default).
      CHECK(std::fabs(cutter_side_step_for_scallop(ball, k, tilt, 0.004).side_step -
                      ball_side_step_for_scallop(3, k, 0.004).side_step) < 2e-6);
    }
}

TEST_CASE("cross-section scallop of a bull-nose on a tilted plane agrees with the z-map of the two passes") {
  // Plane z = x tan(a), rising across the passes (passes along y). Contacts
  // an arc w apart along the slope; the z-map with exact envelopes gives the
  // ridge height between the passes.
  const Cutter cutters[] = {Cutter("bull", 5, 1.5), Cutter("flat", 3, 0)};
  for (const Cutter& cutter : cutters) {
    for (double a_deg : {10.0, 25.0}) {
      const double a = a_deg * M_PI / 180;
      Part part;
      part.faces.emplace_back("slope", make_plane({0, 0, 0}, {40 * std::cos(a), 0, 40 * std::sin(a)}, {0, 30, 0}));
      const VerticalProjector projector(part);
      const double h = cutter.corner_radius() > 0 ? 0.004 : 0.02;
      const SideStepResult s = cutter_side_step_for_scallop(cutter, 0.0, -a, h);
      REQUIRE(s.converged);
      // The normal leans toward -x: seen across the passes (+x) it is tilted by -a.
      std::vector<ZMapMove> moves;
      std::vector<std::vector<PathContact>> passes;
      for (int k = 0; k < 2; ++k) {
        const double x = (15 + k * s.side_step) * std::cos(a);
        const SurfacePoint p0 = projector.project(x, 5), p1 = projector.project(x, 25);
        REQUIRE(p0.valid);
        CHECK(p0.normal.x() < 0);
        moves.push_back({cutter_location(cutter, p0.point, p0.normal).tip, cutter_location(cutter, p1.point, p1.normal).tip, k, 0});
        passes.push_back({exact_contact(cutter, p0), exact_contact(cutter, p1)});
      }
      ZMap zmap(part_xy_extent(part), 0.05);
      zmap.cut(cutter, moves);
      const auto scallops = pass_pair_scallops(projector, zmap, cutter, passes);
      REQUIRE(scallops.size() == 1);
      CAPTURE(cutter.name());
      CAPTURE(a_deg);
      for (const ScallopPeak& peak : {scallops[0].ridge, scallops[0].cusp}) {
        REQUIRE(peak.found);
        CHECK(peak.height == doctest::Approx(h).epsilon(1e-4).scale(0));
      }
    }
  }
}
