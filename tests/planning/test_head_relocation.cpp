// With an indexable head, a planned point that no qualified tip reaches is
// moved to a nearby place one does, as with the vertical stylus. The
// oracle is brute force (support/capsule_oracle.hpp): at the original place
// every tip is tilted too far or brought into the part by its assembly; at
// the new place the assembly of the tip the point got clears the part along
// the touch and both vertical legs.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>

#include "geometry/primitives.hpp"
#include "io/cmm/probe_head.hpp"
#include "plan_fixtures.hpp"
#include "planning/probe_planner.hpp"
#include "support/capsule_oracle.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A floor over x in [-40, 5], y in [-15, 15], and a wall 30 mm high at
// x = 5: next to the wall the vertical tip's probe body (radius 6.6, from 21
// to 46 mm above the ball) runs into it.
constexpr double kFloorX = -40, kHalfWidth = 15, kWallHeight = 30;

// A vertical tip, which cannot lean away from the wall, and a horizontal
// one for the wall itself, which cannot take the floor (90 degrees off).
const char* kHead = R"({
  "head": {"type": "PH10M", "a": {"min": 0, "max": 105, "step": 7.5}, "b": {"min": -180, "max": 180, "step": 7.5},
           "length": 30, "diameter": 24},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": [{"a": 0, "b": 0}, {"a": 90, "b": 0}]
})";
const OracleHead kOracleHead{1, 0.5, 20, 25, 6.6, 30, 12};

}  // namespace

TEST_CASE("indexable head: a point no tip reaches is moved to where one does") {
  const Part part = floor_and_wall(kFloorX, kHalfWidth, kWallHeight);
  const RegionMap map = partition_of(part, 60, 60);
  PlannerOptions o;
  o.points = 60;
  o.min_per_region = 1;
  use_head(o, parse_probe_head(kHead, "head.json"));
  const PlanResult r = plan_probe_points(part, map, o);
  std::map<std::string, const PlannedPoint*> by_id;
  for (const PlannedPoint& p : r.plan.points) by_id[p.id] = &p;

  const double h = 0.25;
  const std::vector<Eigen::Vector3d> part_samples = floor_and_wall_samples(h, kFloorX, kHalfWidth, kWallHeight);
  // A sampled plane overestimates a distance d >= 0.5 by at most h^2 / (4 d).
  const double sampling = h * h / 2 + 1e-6;
  int moved = 0;
  for (const PlanIssue& issue : r.issues) {
    if (issue.kind != PlanIssue::Kind::moved) continue;
    ++moved;
    REQUIRE(by_id.count(issue.point));
    const PlannedPoint& p = *by_id.at(issue.point);
    CAPTURE(issue.point);
    CAPTURE(issue.where.transpose());
    CAPTURE(p.xyz.transpose());
    REQUIRE(p.tip);
    CHECK(std::abs(issue.distance - (p.xyz - issue.where).norm()) < 1e-9);
    // Where it was (a floor point, normal +z): no tip could take it.
    for (const TipAngles& t : o.head->qualified) {
      const std::vector<OracleCapsule> caps = oracle_capsules(kOracleHead, t.a, t.b);
      const double tilt = std::acos(std::clamp(-oracle_tip_direction(t.a, t.b).z(), -1.0, 1.0));
      if (tilt > o.max_tilt_degrees * kPi / 180) continue;
      const Eigen::Vector3d c = issue.where + Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d top(c.x(), c.y(), r.clearance_z);
      // Not clearly clear: within each capsule's documented conservatism
      // (a quarter of its radius, accessibility.hpp) of the part.
      double margin = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < caps.size(); ++i)
        margin = std::min(margin, swept_clearance(part_samples, {caps[i]}, c, top) - (i > 0 ? caps[i].radius / 4 : 0));
      CAPTURE(t.a);
      CHECK(margin <= sampling + 0.02);
    }
    // Where it is: the tip it got clears the part.
    const std::vector<OracleCapsule> all = oracle_capsules(kOracleHead, p.tip->a, p.tip->b);
    const std::vector<OracleCapsule> rest(all.begin() + 1, all.end());
    const Eigen::Vector3d c = p.xyz + p.ijk;
    CHECK(swept_clearance(part_samples, rest, c, p.xyz + (1 + std::max(r.approach, r.retract)) * p.ijk) >= -sampling);
    for (const Eigen::Vector3d& q : {p.approach, p.retract})
      CHECK(swept_clearance(part_samples, all, q, Eigen::Vector3d(q.x(), q.y(), std::max(q.z(), r.clearance_z))) >=
            -sampling);
  }
  MESSAGE(moved << " of " << r.plan.points.size() << " points moved with the head");
  CHECK(moved >= 2);
}
