// The ball-contact rule of narrow regions (ball_contact.hpp, docs/cmm.md
// "Narrow regions") on a slot made of three plane patches: a floor of width
// w between two walls. The oracle is the slot's geometry: a ball of radius r
// standing on the floor at y0 (the slot's middle at y = 0) measures the floor
// alone, its contact staying on the floor with the centre off by the shift s,
// exactly when the nearest wall is farther than r from the moved centre:
// w/2 - |y0| - s > r.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/closest_point.hpp"
#include "geometry/primitives.hpp"
#include "planning/ball_contact.hpp"

using namespace furrow;

namespace {

constexpr double kWidth = 3, kLength = 20, kDepth = 5;

Part slot() {
  Part part;
  part.faces.emplace_back("floor", make_plane({0, -kWidth / 2, 0}, {kLength, 0, 0}, {0, kWidth, 0}));
  part.faces.emplace_back("wall_minus_y", make_plane({0, -kWidth / 2, 0}, {0, 0, kDepth}, {kLength, 0, 0}));
  part.faces.emplace_back("wall_plus_y", make_plane({0, kWidth / 2, 0}, {kLength, 0, 0}, {0, 0, kDepth}));
  return part;
}

const InRegion kOnFloor = [](std::size_t face, const Eigen::Vector2d&) { return face == 0; };

}  // namespace

TEST_CASE("ball contact on a slot floor: accepted exactly where the moved ball still clears both walls") {
  const Part part = slot();
  const ClosestPointFinder finder(part);
  BallContactOptions options;
  options.shift = 0.25;
  int accepted = 0, refused = 0;
  for (int i = -14; i <= 14; ++i)
    for (int k = 1; k <= 16; ++k) {
      const double y0 = 0.1 * i, r = 0.1 * k;
      const double margin = kWidth / 2 - std::abs(y0) - options.shift - r;
      if (std::abs(margin) < 0.01) continue;  // a tie: the moved ball just touches the wall
      CAPTURE(y0);
      CAPTURE(r);
      const ContactProblem got = check_ball_contact(finder, 0, Eigen::Vector3d(kLength / 2, y0, 0),
                                                    Eigen::Vector3d::UnitZ(), r, kOnFloor, options);
      CHECK((got == ContactProblem::none) == (margin > 0));
      (got == ContactProblem::none ? accepted : refused)++;
      // A ball reaching into a wall at its nominal place is refused before
      // any shift: its contact is not the planned point.
      if (kWidth / 2 - std::abs(y0) < r - 0.01) CHECK(got == ContactProblem::elsewhere);
    }
  CHECK(accepted > 50);
  CHECK(refused > 50);
}

TEST_CASE("the largest ball that measures a slot floor is w - 2 s across, to the bisection's resolution") {
  const Part part = slot();
  const ClosestPointFinder finder(part);
  for (double shift : {0.0, 0.25, 0.5}) {
    CAPTURE(shift);
    BallContactOptions options;
    options.shift = shift;
    std::vector<ContactCandidate> candidates;
    for (int i = -5; i <= 5; ++i) candidates.push_back({0, Eigen::Vector3d(kLength / 2, 0.2 * i, 0), Eigen::Vector3d::UnitZ()});
    // The moved ball must keep the floor nearest (r < w/2 - s); unmoved, the
    // walls must stay r + tolerance from the centre (r <= w/2 - tolerance).
    const double expected = shift > 0 ? kWidth / 2 - shift : kWidth / 2 - options.tolerance;
    const double got = largest_fitting_ball(finder, candidates, 5.0, kOnFloor, options, 0.005);
    CHECK(got <= expected + 1e-6);
    CHECK(got >= expected - 0.005 - 1e-6);
    // A ball no larger than asked is the answer itself.
    CHECK(largest_fitting_ball(finder, candidates, 0.5, kOnFloor, options, 0.005) == 0.5);
  }
  // Nothing fits when the shift alone leaves the floor.
  BallContactOptions wide;
  wide.shift = kWidth;
  CHECK(largest_fitting_ball(finder, {{0, Eigen::Vector3d(kLength / 2, 0, 0), Eigen::Vector3d::UnitZ()}}, 1.0, kOnFloor,
                             wide) == 0);
}
