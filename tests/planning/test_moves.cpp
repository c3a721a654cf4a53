// Moves and cycle time: the trapezoidal profile against its closed form,
// straight moves over a plane, detours over the clearance plane when a
// bump is in the way.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "planning/moves.hpp"
#include "plan_fixtures.hpp"

using namespace furrow;

TEST_CASE("rest-to-rest leg time: triangle below v^2/a, trapezoid above") {
  // v = 50, a = 500: full speed needs 5 mm.
  CHECK(leg_time(5, 50, 500) == doctest::Approx(0.2));          // 2 sqrt(5/500)
  CHECK(leg_time(1.25, 50, 500) == doctest::Approx(0.1));       // 2 sqrt(1.25/500)
  CHECK(leg_time(105, 50, 500) == doctest::Approx(2.2));        // 105/50 + 50/500
  CHECK(leg_time(0, 50, 500) == 0);
}

TEST_CASE("straight over a plane, over the clearance plane past a dome") {
  const Part plane = test::one_face(make_plane({0, 0, 0}, {100, 0, 0}, {0, 100, 0}));
  const ClosestPointFinder fp(plane);
  MoveOptions o;
  o.clearance = 2;
  o.clearance_z = clearance_plane(plane, 1, 2);
  CHECK(o.clearance_z == doctest::Approx(3));
  const Move m = plan_move(fp, {10, 10, 4}, {60, 70, 4}, 1, o);
  CHECK(m.straight);
  CHECK(m.length == doctest::Approx(std::hypot(50, 60)));
  REQUIRE(m.waypoints.size() == 1);

  // A hemisphere of radius 20 at the origin between the two points.
  const double pi = 3.14159265358979323846;
  const Part dome = test::one_face(make_sphere(20, 0, 2 * pi, 0, pi / 2));
  const ClosestPointFinder fd(dome);
  o.clearance_z = clearance_plane(dome, 1, 2);
  CHECK(o.clearance_z >= 20 + 3);
  const Move d = plan_move(fd, {-30, 0, 4}, {30, 0, 4}, 1, o);
  CHECK_FALSE(d.straight);
  REQUIRE(d.waypoints.size() == 3);
  CHECK(d.waypoints[0].isApprox(Eigen::Vector3d(-30, 0, o.clearance_z)));
  CHECK(d.waypoints[1].isApprox(Eigen::Vector3d(30, 0, o.clearance_z)));
  CHECK(d.length == doctest::Approx(2 * (o.clearance_z - 4) + 60));
  // Beside the dome the same length of move goes straight.
  CHECK(plan_move(fd, {-30, 30, 4}, {30, 30, 4}, 1, o).straight);
}

TEST_CASE("cycle estimate adds legs, touches and dwell") {
  MotionModel model{50, 4, 500, 0.2};
  std::vector<Move> moves(2);
  moves[0].waypoints = {Eigen::Vector3d(0, 0, 5)};         // 5 mm down from the start
  moves[1].waypoints = {Eigen::Vector3d(105, 0, 5)};       // 105 mm across from the retract point (0,0,5)
  const CycleEstimate e = estimate_cycle({0, 0, 10}, moves, {Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(105, 0, 5)},
                                         {Eigen::Vector3d(105, 0, 10)}, 2, 2, model);
  CHECK(e.positioning_length == doctest::Approx(5 + 105 + 5));
  CHECK(e.touch_length == doctest::Approx(8));
  const double touch = leg_time(2, 4, 500) + leg_time(2, 50, 500) + 0.2;
  CHECK(e.seconds == doctest::Approx(leg_time(5, 50, 500) + leg_time(105, 50, 500) + leg_time(5, 50, 500) + 2 * touch));
  CHECK(e.straight_moves == 1);
}
